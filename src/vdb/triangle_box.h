// Conservative triangle/voxel overlap, the CPU twin of vox_overlaps in
// shaders/voxelize/voxelize_pass.glsl: Akenine-Moller's separating-axis test (13 axes) against the
// voxel grown by kVoxBoxGrowth, in float, with the same operations in the same order, so the
// sparse and the dense voxelizers mark the same voxels.
#pragma once

#include "voxelize/voxelize_shared.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace vct {

// Half-size growth of the tested box in voxel units, the GPU voxelizer's own.
constexpr float kVoxBoxGrowth = gpu::VOX_BOX_GROWTH;

// `p` are the triangle's corners in voxel units, `faceN` = cross(p1 - p0, p2 - p0).
inline bool triangleOverlapsVoxel(const glm::vec3 p[3], const glm::vec3& faceN, const glm::vec3& boxCenter) {
    const float h = 0.5f + kVoxBoxGrowth;
    const glm::vec3 v0 = p[0] - boxCenter, v1 = p[1] - boxCenter, v2 = p[2] - boxCenter;
    // Box face normals.
    const glm::vec3 lo = glm::min(v0, glm::min(v1, v2)), hi = glm::max(v0, glm::max(v1, v2));
    for (int a = 0; a < 3; ++a)
        if (lo[a] > h || hi[a] < -h) return false;
    // Triangle plane.
    const glm::vec3& n = faceN;
    if (std::abs(glm::dot(n, v0)) > h * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z))) return false;
    // Edge x box-axis cross products.
    const glm::vec3 e[3] = {v1 - v0, v2 - v1, v0 - v2};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            glm::vec3 axis = k == 0 ? glm::vec3(0.f, -e[i].z, e[i].y)
                                    : (k == 1 ? glm::vec3(e[i].z, 0.f, -e[i].x) : glm::vec3(-e[i].y, e[i].x, 0.f));
            float p0 = glm::dot(axis, v0), p1 = glm::dot(axis, v1), p2 = glm::dot(axis, v2);
            float r = h * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
            if (std::min(p0, std::min(p1, p2)) > r || std::max(p0, std::max(p1, p2)) < -r) return false;
        }
    }
    return true;
}

}  // namespace vct
