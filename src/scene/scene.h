// The in-memory scene every backend reads: one flat, world-space triangle soup plus
// materials, textures, punctual lights and cameras. The glTF node hierarchy is baked
// into world space at load time, so the GL rasterizer, the voxelizer and Embree all
// index the same arrays and agree on every triangle.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vct {

// Every component finite (no NaN, no infinity): what each input check of a point or vector asks.
inline bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct Bounds3 {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    void expand(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void expand(const Bounds3& b) { min = glm::min(min, b.min); max = glm::max(max, b.max); }
    bool empty() const { return min.x > max.x; }
    glm::vec3 extent() const { return empty() ? glm::vec3(0.f) : max - min; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    float maxExtent() const { glm::vec3 e = extent(); return glm::max(e.x, glm::max(e.y, e.z)); }
};

// A glTF sampler's wrap mode along one texture axis (GL's REPEAT, CLAMP_TO_EDGE and
// MIRRORED_REPEAT).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// 8-bit RGBA texel data as stored in the file (base colour and emissive textures are
// sRGB-encoded per glTF; decoding to linear happens where they are sampled).
struct Texture {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4, row 0 at the top (glTF uv origin)
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;
};

// Lambertian material: glTF pbrMetallicRoughness base colour + emission; metal/roughness
// are ignored (the renderer is diffuse-only by design).
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.f};   // linear RGBA
    int baseColorTexture = -1;        // index into Scene::textures, -1 for none
    glm::vec3 emissiveFactor{0.f};    // linear RGB, already multiplied by emissive_strength
    int emissiveTexture = -1;
    bool doubleSided = false;
    bool alphaMask = false;           // alphaMode MASK (tested against alphaCutoff)
    float alphaCutoff = 0.5f;

    bool isEmissive() const { return emissiveFactor.x > 0.f || emissiveFactor.y > 0.f || emissiveFactor.z > 0.f; }
};

enum class LightType : int { Directional = 0, Point = 1, Spot = 2 };

// KHR_lights_punctual in world space. Units follow the extension: directional in lux
// (lm/m^2), point and spot in candela (lm/sr); `color` is already multiplied by intensity.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.f};           // linear RGB radiometric intensity (colour x intensity)
    glm::vec3 position{0.f};        // world space (point, spot)
    glm::vec3 direction{0, 0, -1};  // world space, direction the light travels (directional, spot)
    float range = 0.f;              // 0 = infinite (range is only a culling hint here)
    float innerConeAngle = 0.f;     // radians (spot)
    float outerConeAngle = 0.7853982f;
};

// A perspective camera in world space. Vertical field of view in radians.
struct Camera {
    std::string name;
    glm::vec3 eye{0.f, 0.f, 5.f};
    glm::vec3 target{0.f};
    glm::vec3 up{0.f, 1.f, 0.f};
    float yfov = 0.8f;
    float znear = 0.01f;
    float zfar = 1000.f;
};

// One instant of a glTF camera animation, evaluated exactly at load time, in world space.
struct CameraAnimationKey {
    double time = 0.0;             // seconds, the animation's own clock
    glm::vec3 eye{0.f};
    glm::vec3 target{0.f};         // eye + the unit view direction
    glm::vec3 up{0.f, 1.f, 0.f};   // unit, perpendicular to the view direction
    float yfov = 0.8f;             // radians, the camera's (glTF animates no field of view)
};

// A glTF animation that moves a perspective camera (its node or an ancestor), sampled
// densely: every key time of the channels that move the camera plus evenly spaced points
// between them (gltf_animation.cpp says how many), meant to be joined linearly. Plain data
// rather than a CameraPath because camera_path.h includes this header; scene/gltf_animation.h
// turns a track into a CameraPath.
struct CameraAnimationTrack {
    std::string name;        // the glTF animation's name, "animation<index>" when it has none
    int animation = -1;      // the animation's index in the file
    std::string cameraName;  // the moved camera, as named in Scene::cameras
    std::vector<CameraAnimationKey> keys;  // at least one, times strictly increasing
};

// One instant of a glTF animation of a punctual light, in world space.
struct LightAnimationKey {
    double time = 0.0;
    glm::vec3 position{0.f};
    glm::vec3 direction{0.f, 0.f, -1.f};  // unit, the direction the light travels
};

// A glTF animation that moves a light (its node or an ancestor), sampled as camera tracks are.
struct LightAnimationTrack {
    std::string name;    // the glTF animation's name, "animation<index>" when it has none
    int animation = -1;
    size_t light = 0;    // index in Scene::lights
    std::vector<LightAnimationKey> keys;  // at least one, times strictly increasing
};

// One instant of a glTF animation of a mesh node, in world space: the node's world transform.
struct MeshAnimationKey {
    double time = 0.0;
    glm::mat4 worldFromNode{1.f};
};

// A glTF animation that moves a mesh node (its node or an ancestor) rigidly: the node's world
// transform sampled as camera tracks are, and the node's vertices as loaded (its rest pose) so a
// pose at any time is computed from them, never from the last pose (no drift).
struct MeshAnimationTrack {
    std::string name;      // the glTF animation's name, "animation<index>" when it has none
    int animation = -1;
    std::string nodeName;  // the moved mesh node, "node <index>" when it has no name
    uint32_t firstVertex = 0;  // the node's vertices: [firstVertex, firstVertex + restPositions.size())
    glm::mat4 nodeFromWorldAtRest{1.f};  // inverse of the node's world transform as loaded
    std::vector<glm::vec3> restPositions;
    std::vector<glm::vec3> restNormals;
    std::vector<MeshAnimationKey> keys;  // at least one, times strictly increasing
};

struct Scene {
    std::string path;  // where it came from (for messages), may be empty

    // Vertex arrays, world space; normals are unit length (computed when the file has none).
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;          // texcoord 0; (0,0) when absent
    // Vertex colours (glTF COLOR_0): linear RGBA multiplying the base colour and its alpha.
    // Empty when no primitive has one (every vertex (1, 1, 1, 1)); else one per position.
    std::vector<glm::vec4> colors;
    std::vector<glm::uvec3> triangles;   // indices into the vertex arrays
    std::vector<uint32_t> triangleMaterial;  // per triangle, index into materials
    std::vector<uint8_t> triangleOffscreen;  // per triangle: 1 if from a node marked off-screen occluder

    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    // One track per (animation, camera) pair whose animation moves that camera; cameras
    // above hold the unanimated pose.
    std::vector<CameraAnimationTrack> cameraAnimations;
    // One track per (animation, light) pair whose animation moves that light; lights above hold
    // the unanimated pose (scene/gltf_animation.h poses them at a time).
    std::vector<LightAnimationTrack> lightAnimations;
    // One track per (animation, mesh node) pair whose animation moves that node rigidly (its
    // own translation, rotation or scale, or an ancestor's); positions and normals above hold
    // the unanimated pose (scene/gltf_animation.h poses them at a time).
    std::vector<MeshAnimationTrack> meshAnimations;
    // Animations that deform geometry (a skin, morph target weights), by name, with what they
    // deform: sequences refuse to play them, since only rigid motion is posed.
    std::vector<std::pair<std::string, std::string>> geometryAnimations;

    Bounds3 bounds;
    std::vector<std::string> warnings;  // load-time notes (e.g. degenerate triangles dropped)

    size_t triangleCount() const { return triangles.size(); }
    glm::vec3 geometricNormal(size_t tri) const {
        const glm::uvec3& t = triangles[tri];
        return glm::normalize(glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]));
    }
};

}  // namespace vct
