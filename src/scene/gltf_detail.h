// What the glTF loader's files share and callers never see: the state of one model's
// conversion, the wording of its messages, and the function each file gives the others
// (accessors, materials, primitives, lights and cameras, nodes).
#pragma once

#include "scene/gltf_loader.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace vct::gltf_detail {

// The texture coordinates a material's textures read: attribute TEXCOORD_<set> through the
// affine map `transform` (KHR_texture_transform: uv' = offset + rotate(scale * uv), the
// identity without it). Applied to the vertices at load, where it is exact: the map is affine,
// so interpolating the mapped coordinates equals mapping the interpolated ones.
struct UvMapping {
    int set = 0;
    glm::mat3 transform{1.f};  // column-major, acting on (u, v, 1)
    bool operator==(const UvMapping& o) const { return set == o.set && transform == o.transform; }
};

// One model on its way to a Scene: the elements converted so far and what later elements
// need of them.
struct LoadContext {
    const tinygltf::Model& model;
    std::string path;
    Scene scene;
    std::vector<int> sceneTextureFromGltf;                             // -1 = not converted yet
    std::map<std::tuple<int, int, int>, int> sceneTextureFromImage;  // (image, wrapS, wrapT) -> texture
    int defaultMaterial = -1;
    size_t degenerateCount = 0;
    size_t repairedNormalCount = 0;
    std::vector<size_t> camerasWithInfiniteFar;
    std::vector<int> nodeStack;  // the nodes from the root down to the one visitNode converts
    // Each scene camera with the nodes that place it, for the animations that move them.
    struct PlacedCamera {
        size_t sceneCamera;          // index in Scene::cameras
        std::vector<int> nodeChain;  // root first, the camera's own node last
    };
    std::vector<PlacedCamera> placedCameras;
    // The same for each scene light.
    struct PlacedLight {
        size_t sceneLight;           // index in Scene::lights
        std::vector<int> nodeChain;  // root first, the light's own node last
    };
    std::vector<PlacedLight> placedLights;
    // Each mesh node's vertices with the nodes that place them, for the animations that move them.
    struct PlacedMesh {
        int node = -1;
        uint32_t firstVertex = 0, vertexCount = 0;  // in Scene::positions
        glm::mat4 worldFromNode{1.f};               // as loaded
        std::vector<int> nodeChain;                 // root first, the mesh's own node last
    };
    std::vector<PlacedMesh> placedMeshes;
    // Per glTF material: the texture coordinates its textures read (convertMaterials), which
    // addPrimitive bakes into the scene's one set of UVs.
    std::vector<UvMapping> materialUv;

    LoadContext(const tinygltf::Model& m, const std::string& p) : model(m), path(p) {}

    [[noreturn]] void fail(const std::string& what) const { throw SceneError(path + ": " + what); }
};

// Messages (gltf_loader.cpp). label("node", 3, "lamp") = "node 3 'lamp'"; without a name,
// "node 3".
std::string label(const char* kind, int index, const std::string& name);
std::string str3(const glm::vec3& v);

// "texture 7 out of range [0, 3)": every reference to a missing element reads the same.
template <typename Index>
std::string outOfRange(const std::string& what, Index index, size_t count) {
    return what + " " + std::to_string(index) + " out of range [0, " + std::to_string(count) + ")";
}

// Accessors (gltf_accessors.cpp). `ctx` names the user in messages, e.g. "mesh 'floor',
// primitive 0, POSITION"; accessorLabel(3, ctx) = "accessor 3 (<ctx>)".
std::string accessorLabel(int index, const std::string& ctx);
bool isIntegerComponent(int componentType);
// Reads accessor `index` as count x `components` doubles (sparse substitution applied).
std::vector<double> readAccessor(const LoadContext& load, int index, const std::string& ctx, int components,
                                 size_t* countOut, int* componentTypeOut = nullptr);
// Reads a VEC3 attribute and rejects NaN or infinite elements.
std::vector<glm::vec3> readVec3(const LoadContext& load, int accessor, const std::string& ctx);
// Reads a COLOR_n attribute as linear RGBA (VEC3: alpha 1) of floats or of normalized
// unsigned bytes or shorts, the types glTF allows, and rejects non-finite elements.
std::vector<glm::vec4> readColors(const LoadContext& load, int accessor, const std::string& ctx);

// Extensions (gltf_extensions.cpp). Refuses a model that requires an extension the loader
// does not implement; warns of those it uses and the loader leaves out.
void checkExtensions(LoadContext& load);
// The refusal's wording for extension names (empty when every one is implemented), and the
// same read straight from a file tinygltf could not parse (empty when it cannot tell): a
// file whose geometry lives in an extension (Draco) fails tinygltf's accessor checks first.
std::string unimplementedRequiredExtension(const std::vector<std::string>& required);
std::string unimplementedRequiredExtensionInFile(const std::string& path, bool binary);

// Materials and textures (gltf_materials.cpp).
void convertMaterials(LoadContext& load);
// The scene material of a primitive's glTF material; -1 adds glTF's default material once.
uint32_t materialFor(LoadContext& load, int gltfMaterial, const std::string& ctx);

// Primitives (gltf_primitives.cpp): appends the primitive's triangles in world space.
void addPrimitive(LoadContext& load, int meshIndex, int primIndex, const glm::mat4& worldFromLocal, bool offscreen);

// Lights and cameras (gltf_lights_cameras.cpp), placed by their node's world transform.
void addLight(LoadContext& load, const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal);
void addCamera(LoadContext& load, const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal);
// Once the scene bounds are known: a far plane for the cameras whose zfar was 0 (infinite).
void boundInfiniteFarPlanes(LoadContext& load);

// Animations (gltf_animation.cpp): samples every animation that moves a placed camera into
// Scene::cameraAnimations; the others are neither read nor checked.
void addCameraAnimations(LoadContext& load);
// The same for the animations that move a punctual light (Scene::lightAnimations).
void addLightAnimations(LoadContext& load);
// The same for the animations that move a mesh node rigidly (Scene::meshAnimations).
void addMeshAnimations(LoadContext& load);
// Names the animations that deform geometry, skins and morph target weights
// (Scene::geometryAnimations), without reading their samplers.
void findGeometryAnimations(LoadContext& load);

// The node hierarchy (gltf_nodes.cpp).
std::vector<int> rootNodes(const tinygltf::Model& model);
// Converts node `nodeIndex` and its descendants under the parent's world transform.
void visitNode(LoadContext& load, int nodeIndex, const glm::mat4& worldFromParent, bool parentOffscreen, size_t depth);

}  // namespace vct::gltf_detail
