#include "render/view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

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
