// The camera as the rasterizer sees it: matrices named destination-from-source.
// Projection is reversed-Z with an infinite far plane (depth 1 at znear, 0 at infinity)
// into a 32-bit float depth buffer, which keeps depth precision uniform in log scale and
// survives near/far ratios of 1e7 (scenes from 1e-4 to 1e5 units).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace vct {

struct View {
    Camera camera;
    int width = 0;
    int height = 0;
    glm::mat4 viewFromWorld{1.f};
    glm::mat4 worldFromView{1.f};
    glm::mat4 clipFromView{1.f};   // reversed-Z, infinite far
    glm::mat4 clipFromWorld{1.f};
    float aspect() const { return float(width) / float(height); }
    // Focal length in pixels along y: a world length L at view depth z spans L * focalPx / z pixels.
    float focalPx() const;
};

View makeView(const Camera& camera, int width, int height);
glm::mat4 reversedZInfinitePerspective(float yfov, float aspect, float znear);

}  // namespace vct
