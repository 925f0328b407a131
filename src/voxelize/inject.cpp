#include "voxelize/voxelize.h"

#include "common/loop_budget.h"
#include "core/errors.h"
#include "gl/program_cache.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxel_programs.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

}  // namespace

int injectLightsPerDispatch(const glm::ivec3& resolution, int outerLevels, int outerResolution, bool twoSided,
                            int requested) {
    // inject.glsl's loops for one light and one face: the light loop's own iteration; the
    // walk's two set-up loops over the axes (6) and its cells (at most the three axes' voxels
    // + 3); each outer level's loop, exit distance (3) and walk through it.
    const long long walk = 6 + resolution.x + resolution.y + resolution.z + 3;
    const long long outerWalk = 1 + 3 + 6 + 3LL * outerResolution + 3;
    const long long perLight = (twoSided ? 2 : 1) * (1 + walk + outerLevels * outerWalk);
    const long long fit = std::max<long long>(1, gpu::SHADER_LOOP_BUDGET / perLight);
    const long long lights = requested > 0 ? std::min<long long>(fit, requested) : fit;
    return int(std::min<long long>(lights, std::numeric_limits<int>::max()));
}

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
    const glm::ivec3 res = grid.resolution;
    const int outerRes = outerLevels.empty() ? 0 : outerLevels.front()->resolution.x;
    const int perDispatch = injectLightsPerDispatch(res, int(outerLevels.size()), outerRes, twoSided,
                                                    settings.dispatchLights);
    const int lightCount = gpuScene.lightCount;
    const bool batched = lightCount > perDispatch;
    const GLuint p = cachedProgram(injectProgramKey(format, int(outerLevels.size()), twoSided, batched));
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
    // The irradiance one dispatch carries to the next when the lights take several (float, so
    // the sums are those of one dispatch bit for bit); freed when the pass ends.
    GlTexture irradiance, irradianceBack;
    if (batched) {
        irradiance = createTexture3D(GL_RGBA32F, res.x, res.y, res.z, 1);
        bindImage3D(2, irradiance.id(), 0, GL_READ_WRITE, GL_RGBA32F);
        if (twoSided) {
            irradianceBack = createTexture3D(GL_RGBA32F, res.x, res.y, res.z, 1);
            bindImage3D(3, irradianceBack.id(), 0, GL_READ_WRITE, GL_RGBA32F);
        }
    }
    setUniform(p, "uResolution", res);
    setUniform(p, "uGridOrigin", grid.origin);
    setUniform(p, "uVoxelSize", grid.voxelSize);
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
        setUniform(p, "uOuterResolution", outerRes);
        setUniform(p, "uOuterCount", int(outerLevels.size()));
    }
    glUseProgram(p);
    int first = 0;
    grid.injectDispatches = 0;
    do {
        const int end = batched ? std::min(lightCount, first + perDispatch) : lightCount;
        setUniform(p, "uLightFirst", first);
        setUniform(p, "uLightEnd", end);
        if (batched) setUniform(p, "uLastBatch", int(end == lightCount));
        dispatchGrid(res);
        ++grid.injectDispatches;
        first = end;
    } while (first < lightCount);

    for (GLuint u = 0; u < 5; ++u) glBindTextureUnit(u, 0);
    for (size_t k = 0; k < outerLevels.size(); ++k) glBindTextureUnit(GLuint(outerUnit + k), 0);
    for (GLuint u = 0; u < 4; ++u) glBindImageTexture(u, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
}

}  // namespace vct
