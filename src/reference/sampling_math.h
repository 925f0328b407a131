// Warps from [0,1)^2 to the directions and points the reference renderers sample.
#pragma once

#include "common/tangent_frame.h"

#include <glm/glm.hpp>

#include <cmath>

namespace vct {

// Shirley-Chiu concentric map: keeps the stratification of the input samples.
inline glm::vec2 sampleUniformDiskConcentric(glm::vec2 u) {
    glm::vec2 o = 2.f * u - 1.f;
    if (o.x == 0.f && o.y == 0.f) return {0.f, 0.f};
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = 0.78539816f * (o.y / o.x);
    } else {
        r = o.y;
        theta = 1.57079633f - 0.78539816f * (o.x / o.y);
    }
    return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// Cosine-weighted direction about +z (Malley's method); pdf = cos(theta) / pi.
inline glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
    glm::vec2 d = sampleUniformDiskConcentric(u);
    float z = std::sqrt(std::max(0.f, 1.f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

// Uniform point on a triangle as barycentrics (b0, b1, b2) (Heitz 2019's low-distortion map).
inline glm::vec3 sampleUniformTriangle(glm::vec2 u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
    return {b0, b1, 1.f - b0 - b1};
}

// Orthonormal basis around a unit vector: the cone passes' frame (common/tangent_frame.h),
// with the sign of n.z taken from its sign bit as the reference always has.
struct Frame {
    glm::vec3 x, y, z;

    static Frame fromZ(const glm::vec3& n) {
        const glm::mat3 m = gpu::frame_fromZWithSign(n, std::copysign(1.f, n.z));
        return {m[0], m[1], m[2]};
    }
    glm::vec3 toWorld(const glm::vec3& v) const { return v.x * x + v.y * y + v.z * z; }
};

inline float maxAbsComponent(const glm::vec3& v) {
    return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
}

}  // namespace vct
