// Which camera a render uses: explicit eye/target from the command line, a camera of the
// file by name or index, the file's first camera, or a framing of the scene bounds.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>

namespace vct {

struct CameraRequest {
    std::string nameOrIndex;  // camera name, or its index in Scene::cameras; empty = first camera
    bool hasEye = false;      // true: eye/target/fovDeg below win over everything else
    glm::vec3 eye{0.f};
    glm::vec3 target{0.f};
    float fovDeg = 45.f;  // vertical field of view, degrees, (0, 180); also used by the default framing
};

// Precedence: explicit eye/target/fov, then a named or indexed camera (UsageError listing
// the available cameras when it is not found), then the scene's first camera, then
// defaultCamera(scene.bounds, aspect). `aspect` = width / height.
Camera resolveCamera(const Scene& scene, const CameraRequest& request, float aspect);

// Looks at the centre of `bounds` from above, front and right (the "3/4 view"), at the smallest
// distance where the bounding sphere fits both the vertical and the horizontal field of view
// (plus a 5% margin); znear/zfar bracket the sphere.
Camera defaultCamera(const Bounds3& bounds, float aspect, float yfovRadians = 0.7853982f);

// "x,y,z" -> vec3; throws UsageError on malformed or non-finite input.
glm::vec3 parseVec3(const std::string& text);

// "12" -> 12; false for anything but a short run of digits, so names like "2b" stay names
// (cameras and animations are chosen by name or index).
bool parseIndex(const std::string& s, size_t* index);

// "0 'front', 1 'top'" or "(none)", for error messages.
std::string describeCameras(const Scene& scene);

}  // namespace vct
