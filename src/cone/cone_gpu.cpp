#include "cone/cone_gpu.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace vct::conedetail {

GLuint coneProgram(const std::string& name, const ShaderDefines& defines) {
    // Function-local static: created after the shared GL context, so destroyed before it.
    static std::map<std::string, GlProgram> cache;
    std::string key = name;
    for (const auto& [k, v] : defines) key += "|" + k + "=" + v;
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, buildComputeProgram(name, defines)).first;
    return it->second.id();
}

void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid) {
    u.voxelFromWorld = grid.voxelFromWorld;
    u.gridResolution = glm::vec4(glm::vec3(grid.resolution), float(grid.levels));
}

GlBuffer bindConeUniforms(const gpu::ConeUniforms& u) {
    GlBuffer ubo = createBuffer(sizeof(u), &u, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::CONE_UBO_BINDING, ubo.id());
    return ubo;
}

void checkGrid(const VoxelGrid& grid, const std::string& pass) {
    if (glm::any(glm::lessThan(grid.resolution, glm::ivec3(1))))
        throw std::invalid_argument(pass + ": voxel grid has no resolution");
    if (!(grid.voxelSize > 0.f) || !std::isfinite(grid.voxelSize))
        throw std::invalid_argument(pass + ": voxel grid has voxelSize " + std::to_string(grid.voxelSize));
    if (grid.levels < 1) throw std::invalid_argument(pass + ": voxel grid has no mip levels");
    if (!grid.opacity) throw std::invalid_argument(pass + ": voxel grid has no opacity texture");
}

}  // namespace vct::conedetail
