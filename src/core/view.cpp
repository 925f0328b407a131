#include "core/view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vct {

glm::mat4 reversedZInfinitePerspective(float yfov, float aspect, float znear) {
    // With glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): z_ndc = znear / z_view_distance.
    float f = 1.f / std::tan(0.5f * yfov);
    glm::mat4 m(0.f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.f;  // w_clip = -z_view
    m[3][2] = znear;  // z_clip = znear
    return m;
}

float View::focalPx() const { return 0.5f * float(height) / std::tan(0.5f * camera.yfov); }

View makeView(const Camera& camera, int width, int height) {
    // A camera built in code skips the loader's checks: a NaN eye or znear 0 would rasterize
    // garbage (or nothing) without a word. Like the loader's, these are errors in the scene.
    const std::string where = "camera '" + camera.name + "'";
    if (!finite3(camera.eye) || !finite3(camera.target) || !finite3(camera.up))
        throw std::runtime_error(where + ": eye, target or up is not finite");
    if (!(glm::length(camera.target - camera.eye) > 0.f))
        throw std::runtime_error(where + ": eye and target coincide");
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    if (!(glm::length(glm::cross(forward, camera.up)) > 1e-6f * glm::length(camera.up)))
        throw std::runtime_error(where + ": up is zero or parallel to the view direction");
    if (!(camera.yfov > 0.f && camera.yfov < 3.14159265f))
        throw std::runtime_error(where + ": yfov " + std::to_string(camera.yfov) + " outside (0, pi)");
    if (!(std::isfinite(camera.znear) && camera.znear > 0.f))
        throw std::runtime_error(where + ": znear " + std::to_string(camera.znear) + " must be finite and > 0");
    View v;
    v.camera = camera;
    v.width = width;
    v.height = height;
    v.viewFromWorld = glm::lookAt(camera.eye, camera.target, camera.up);
    v.worldFromView = glm::inverse(v.viewFromWorld);
    v.clipFromView = reversedZInfinitePerspective(camera.yfov, v.aspect(), camera.znear);
    v.clipFromWorld = v.clipFromView * v.viewFromWorld;
    return v;
}

}  // namespace vct
