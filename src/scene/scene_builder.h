// A small programmatic glTF writer: the project's own scenes are built as a tinygltf::Model,
// so that they reach the renderer through exactly the same loader path (sceneFromModel) as
// files, and can be written out as .gltf/.glb for other tools. Units metres, Y up, glTF
// conventions: front faces wind counter-clockwise, lights and cameras look down -Z.
#pragma once

#include "scene/scene.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace vct {

// A node's local transform as glTF TRS: parentFromNode = T * R * S.
struct NodeTransform {
    glm::vec3 translation{0.f};
    glm::quat rotation{1.f, 0.f, 0.f, 0.f};  // (w, x, y, z)
    glm::vec3 scale{1.f};
};

class SceneBuilder {
  public:
    explicit SceneBuilder(std::string name = "builder");
    const std::string& name() const { return sceneName; }

    // Diffuse material; emissive is linear radiance-like RGB (components above 1 are written with
    // KHR_materials_emissive_strength). Returns the material index.
    int addMaterial(const std::string& name, const glm::vec3& baseColor,
                    const glm::vec3& emissive = glm::vec3(0.f), bool doubleSided = false);

    // Raw mesh, one primitive. normals empty = none written (the loader computes flat ones);
    // indices empty = non-indexed. mode is a TINYGLTF_MODE_* value. Returns the mesh index.
    int addMesh(const std::string& name, const std::vector<glm::vec3>& positions,
                const std::vector<glm::vec3>& normals, const std::vector<uint32_t>& indices, int material,
                int mode = TINYGLTF_MODE_TRIANGLES);

    // Nodes; parent = -1 for a root. Return the node index.
    int addNode(const std::string& name, int mesh = -1, const NodeTransform& transform = {}, int parent = -1);
    int addNodeMatrix(const std::string& name, const glm::mat4& parentFromNode, int mesh = -1,
                      int parent = -1);

    // Axis-aligned box [min, max] (a mesh centred on its node, node translated to the centre).
    int addBox(const std::string& name, const glm::vec3& min, const glm::vec3& max, int material,
               int parent = -1);
    // The unit box [-0.5, 0.5]^3 under an arbitrary node transform.
    int addTransformedBox(const std::string& name, const NodeTransform& parentFromUnitBox, int material,
                          int parent = -1);
    // Parallelogram corner, corner+u, corner+u+v, corner+v; its front face is on the side of cross(u, v).
    int addQuad(const std::string& name, const glm::vec3& corner, const glm::vec3& edgeU,
                const glm::vec3& edgeV, int material, int parent = -1);
    // Horizontal rectangle of size.x (along X) by size.y (along Z) centred at `center`, facing +Y.
    int addPlane(const std::string& name, const glm::vec3& center, const glm::vec2& size, int material,
                 int parent = -1);

    // Sets extras {"offscreen_occluder": true} (the loader also honours names starting "offscreen").
    void markOffscreen(int node);
    void setExtra(int node, const std::string& key, const tinygltf::Value& value);

    // KHR_lights_punctual; intensity in candela (point, spot) or lux (directional). Return the node index.
    int addPointLight(const std::string& name, const glm::vec3& position, const glm::vec3& color,
                      float intensity, int parent = -1);
    int addSpotLight(const std::string& name, const glm::vec3& position, const glm::vec3& direction,
                     const glm::vec3& color, float intensity, float innerConeAngle, float outerConeAngle,
                     int parent = -1);
    int addDirectionalLight(const std::string& name, const glm::vec3& direction, const glm::vec3& color,
                            float intensity, int parent = -1);

    // Perspective camera at `eye` looking at `target`; yfov in radians. Returns the node index.
    int addCamera(const std::string& name, const glm::vec3& eye, const glm::vec3& target, float yfovRadians,
                  float znear = 0.05f, float zfar = 200.f, const glm::vec3& up = glm::vec3(0.f, 1.f, 0.f));

    // A LINEAR translation channel on `node` in animation `name` (created on first use): one
    // position per time (times strictly increasing, seconds).
    void addTranslationAnimation(const std::string& name, int node, const std::vector<float>& times,
                                 const std::vector<glm::vec3>& positions);

    tinygltf::Model build() const;
    Scene toScene() const;  // sceneFromModel(build(), name())
    // .glb by extension, else .gltf with the buffer embedded as base64; written to a
    // temporary name and renamed, so readers never see half a file.
    void write(const std::string& path) const;

  private:
    int addBufferView(const void* data, size_t bytes, int target);
    int addLightNode(const std::string& name, const tinygltf::Light& light, const glm::vec3& position,
                     const glm::vec3& direction, int parent);
    void attach(int node, int parent);

    std::string sceneName;
    tinygltf::Model model;
    std::vector<int> roots;
};

// The rotation that takes -Z (glTF's view/light direction) to `direction`, with +Y toward `up`.
glm::quat rotationLookingAlong(const glm::vec3& direction, const glm::vec3& up = glm::vec3(0.f, 1.f, 0.f));

}  // namespace vct
