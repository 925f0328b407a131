#include "voxelize/voxel_grid.h"

#include "core/errors.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {

VoxelGrid makeGridLayout(const Bounds3& bounds, int maxResolution) {
    if (maxResolution < 4 || maxResolution > 1024)
        throw InternalError("makeGridLayout",
                            "voxel resolution " + std::to_string(maxResolution) + " out of range [4, 1024]");
    if (bounds.empty()) throw InternalError("makeGridLayout", "cannot fit a voxel grid to empty bounds");
    VoxelGrid g;
    // One voxel of padding on each side: the longest axis spans (maxResolution - 2) voxels.
    float extent = std::max(bounds.maxExtent(), 1e-30f);
    g.voxelSize = extent / float(std::max(1, maxResolution - 2));
    glm::vec3 e = bounds.extent();
    // ceil of a ratio that is an integer up to float rounding (2 / (2 / 23) = 23.000002 at one
    // scale, 23 at another) must not flip: the grid would shift by half a voxel with the scene's
    // scale. A thousandth of a voxel past a whole count falls into the padding voxel.
    for (int a = 0; a < 3; ++a)
        g.resolution[a] = std::clamp(int(std::ceil(e[a] / g.voxelSize - 1e-3f)) + 2, 1, maxResolution);
    g.resolution = glm::max(g.resolution, glm::ivec3(1));
    glm::vec3 span = glm::vec3(g.resolution) * g.voxelSize;
    return makeGridLayout(bounds.center() - 0.5f * span, g.voxelSize, g.resolution);
}

VoxelGrid makeGridLayout(const glm::vec3& origin, float voxelSize, const glm::ivec3& resolution) {
    if (!(voxelSize > 0.f) || !std::isfinite(voxelSize))
        throw InternalError("makeGridLayout", "voxel size " + std::to_string(voxelSize) + " must be finite and > 0");
    if (glm::any(glm::lessThan(resolution, glm::ivec3(1))) || glm::any(glm::greaterThan(resolution, glm::ivec3(1024))))
        throw InternalError("makeGridLayout", "resolution outside [1, 1024]");
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(origin[a])) throw InternalError("makeGridLayout", "origin is not finite");
    VoxelGrid g;
    g.resolution = resolution;
    g.voxelSize = voxelSize;
    g.origin = origin;
    g.voxelFromWorld = glm::scale(glm::mat4(1.f), glm::vec3(1.f / g.voxelSize)) *
                       glm::translate(glm::mat4(1.f), -g.origin);
    g.worldFromVoxel = glm::inverse(g.voxelFromWorld);
    int maxRes = std::max(g.resolution.x, std::max(g.resolution.y, g.resolution.z));
    g.levels = int(std::floor(std::log2(float(maxRes)))) + 1;
    return g;
}

}  // namespace vct
