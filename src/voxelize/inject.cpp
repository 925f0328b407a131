#include "voxelize/voxelize.h"

#include "core/errors.h"
#include "gl/program_cache.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxel_programs.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {


namespace {

constexpr float HALF_SAFE_MAX = 30000.f;
constexpr float PI = 3.14159265358979f;

// Whether injected radiance can leave the half-float range: emission stored as float, or a
// light whose irradiance at one voxel's distance (directional: its lux) is that bright.
bool radianceNeedsFloat(const VoxelGrid& grid, const Scene& scene) {
    if (textureInternalFormat(grid.emission.id()) == GL_RGBA32F) return true;
    for (const Light& l : scene.lights) {
        float I = std::max(l.color.x, std::max(l.color.y, l.color.z));
        float E = l.type == LightType::Directional ? I : I / (0.25f * grid.voxelSize * grid.voxelSize);
        if (E / PI > HALF_SAFE_MAX) return true;
    }
    return false;
}

void dispatchGrid(const glm::ivec3& size) {
    const int g = gpu::VOX_GRID_GROUP;
    glDispatchCompute(groupCount(size.x, g), groupCount(size.y, g), groupCount(size.z, g));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace

void injectRadiance(VoxelGrid& grid, const GpuScene& gpuScene, const Scene& scene,
                    const ParamMap& params, PassTimer& timer, const std::vector<const VoxelGrid*>& outerLevels,
                    const std::string& scopeName) {
    if (!grid.opacity || !grid.albedo || !grid.normal || !grid.emission)
        throw InternalError("injectRadiance", "the grid is not voxelized");
    for (const Light& l : scene.lights)
        if (!std::isfinite(l.color.x + l.color.y + l.color.z) ||
            !std::isfinite(l.position.x + l.position.y + l.position.z) ||
            !std::isfinite(l.direction.x + l.direction.y + l.direction.z))
            throw std::runtime_error("injectRadiance: light '" + l.name + "' has a non-finite value");
    const VoxelSettings settings = voxelSettings().read(params);
    const float offset = settings.injectOffset;
    const bool useFloat = settings.precision == VoxelPrecision::Float ||
                          (settings.precision == VoxelPrecision::Auto && radianceNeedsFloat(grid, scene));
    const GLenum format = useFloat ? GL_RGBA32F : GL_RGBA16F;
    constexpr int maxOuter = 7, outerUnit = 20;  // clear of the scene textures (unit 8)
    if (int(outerLevels.size()) > maxOuter)
        throw InternalError("injectRadiance", "more than 7 outer clipmap levels");
    for (const VoxelGrid* o : outerLevels)
        if (!o || !o->opacity || o->resolution != glm::ivec3(o->resolution.x) ||
            o->resolution.x != outerLevels.front()->resolution.x)
            throw InternalError("injectRadiance", "outer levels must be voxelized cubic grids of one size");
    const bool twoSided = bool(grid.twoSided);
    const GLuint p = cachedProgram(injectProgramKey(format, int(outerLevels.size()), twoSided));
    const glm::ivec3 res = grid.resolution;
    grid.radiance = createTexture3D(format, res.x, res.y, res.z, grid.levels);

    auto scope = timer.scope(scopeName, true, Reruns::WhenSceneChanges);

    // Direct light and emission.
    bindSceneBuffers(gpuScene);
    glBindTextureUnit(0, grid.opacity.id());
    glBindTextureUnit(1, grid.albedo.id());
    glBindTextureUnit(2, grid.normal.id());
    glBindTextureUnit(3, grid.emission.id());
    bindImage3D(0, grid.radiance.id(), 0, GL_WRITE_ONLY, format);
    if (twoSided) {
        // Two-sided voxels write their facing normal into level 0 of the normal texture; every
        // other voxel reads its own through unit 2, so no texel is both read and written.
        glBindTextureUnit(4, grid.twoSided.id());
        bindImage3D(1, grid.normal.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
    }
    setUniform(p, "uResolution", res);
    setUniform(p, "uGridOrigin", grid.origin);
    setUniform(p, "uVoxelSize", grid.voxelSize);
    setUniform(p, "uLightCount", gpuScene.lightCount);
    setUniform(p, "uShadowOffset", offset);
    for (size_t k = 0; k < outerLevels.size(); ++k) {
        const VoxelGrid& o = *outerLevels[k];
        const std::string idx = "[" + std::to_string(k) + "]";
        glBindTextureUnit(GLuint(outerUnit + k), o.opacity.id());
        setUniform(p, ("uOuterOpacity" + idx).c_str(), int(outerUnit + k));
        glProgramUniform4f(p, glGetUniformLocation(p, ("uOuterGrid" + idx).c_str()), o.origin.x, o.origin.y,
                           o.origin.z, o.voxelSize);
    }
    if (!outerLevels.empty()) {
        setUniform(p, "uOuterResolution", outerLevels.front()->resolution.x);
        setUniform(p, "uOuterCount", int(outerLevels.size()));
    }
    glUseProgram(p);
    dispatchGrid(res);

    for (GLuint u = 0; u < 5; ++u) glBindTextureUnit(u, 0);
    for (size_t k = 0; k < outerLevels.size(); ++k) glBindTextureUnit(GLuint(outerUnit + k), 0);
    for (GLuint u = 0; u < 2; ++u) glBindImageTexture(u, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
}

}  // namespace vct
