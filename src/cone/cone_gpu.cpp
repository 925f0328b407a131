#include "cone/cone_gpu.h"

#include "cone/cone_set.h"
#include "core/errors.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace vct::conedetail {

void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid) {
    u.voxelFromWorld = grid.voxelFromWorld;
    u.gridResolution = glm::vec4(glm::vec3(grid.resolution), float(grid.levels));
}

GlBuffer bindConeUniforms(const gpu::ConeUniforms& u) {
    GlBuffer ubo = createBuffer(sizeof(u), &u, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::CONE_UBO_BINDING, ubo.id());
    return ubo;
}

namespace {

bool useAniso(const VoxelGrid& grid, const ConeSettings& s) {
    if (!s.anisotropic || !grid.anisotropic || grid.levels < 2) return false;
    for (const auto& t : grid.anisoRadiance)
        if (!t) return false;
    return true;
}

}  // namespace

gpu::ConeUniforms coneUniforms(bool gi, const VoxelGrid& grid, float maxDistWorld, float sky,
                               const ConeSettings& settings) {
    gpu::ConeUniforms u{};
    setGridUniforms(u, grid);
    const int maxRes = std::max(grid.resolution.x, std::max(grid.resolution.y, grid.resolution.z));
    const ConeLanes lanes = coneMarchLanes(settings, maxRes);
    const float halfAperture = 0.5f * lanes.apertureDeg * float(M_PI) / 180.f;
    const float maxDist = maxDistWorld / grid.voxelSize;
    u.march = glm::vec4(std::tan(halfAperture), settings.stepFactor, settings.offsetVoxels, settings.maxAlpha);
    const float falloff = (!gi && settings.aoMapping == ConeAoMapping::Falloff && maxDist > 0.f)
                              ? gpu::CONE_FALLOFF_LAMBDA_R / maxDist
                              : 0.f;
    u.limits = glm::vec4(maxDist, sky, falloff, settings.planeLimit ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f);
    const std::vector<glm::vec4>& cones = lanes.cones;
    u.config = glm::ivec4(int(cones.size()), gi ? gpu::CONE_AO_LINEAR : int(settings.aoMapping), 0, 0);
    for (size_t i = 0; i < cones.size(); ++i) u.cones[i] = cones[i];
    u.camera.w = grid.depthLevels && useAniso(grid, settings) ? 1.f : 0.f;
    return u;
}

glm::ivec4 conePixelImage(const GBuffer& gbuffer, const ConeSettings& settings) {
    return glm::ivec4(gbuffer.width, gbuffer.height, settings.jitter ? 1 : 0, int(settings.seed));
}

bool bindGridTextures(bool gi, const VoxelGrid& grid, const ConeSettings& settings) {
    const bool aniso = useAniso(grid, settings);
    glBindTextureUnit(gpu::CONE_UNIT_OPACITY, gi ? grid.radiance.id() : grid.opacity.id());
    if (gi) glBindTextureUnit(gpu::CONE_UNIT_NORMAL, grid.normal.id());
    if (aniso)
        for (int i = 0; i < 6; ++i) glBindTextureUnit(gpu::CONE_UNIT_ANISO + i, grid.anisoRadiance[i].id());
    return aniso;
}

BoundConePass bindConePass(bool gi, const VoxelGrid& grid, const GBuffer& gbuffer, float maxDistWorld, float sky,
                           const ConeSettings& settings) {
    gpu::ConeUniforms u = coneUniforms(gi, grid, maxDistWorld, sky, settings);
    u.image = conePixelImage(gbuffer, settings);
    BoundConePass bound;
    bound.ubo = bindConeUniforms(u);
    bindGBufferTextures(gbuffer);  // the shaders texelFetch position, normal, geomNormal, albedo
    bound.aniso = bindGridTextures(gi, grid, settings);
    return bound;
}

GlTexture dispatchPixelPass(GLuint program, bool gi, const GBuffer& gbuffer, GlBuffer& counts) {
    const GLenum format = gi ? GL_RGBA32F : GL_R32F;
    GlTexture out = createTexture2D(format, gbuffer.width, gbuffer.height);
    glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
    const size_t pixels = size_t(gbuffer.width) * size_t(gbuffer.height);
    counts = createBuffer(pixels * 2 * sizeof(float));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_COUNTS, counts.id());
    glUseProgram(program);
    glDispatchCompute(groupCount(gbuffer.width, gpu::CONE_LOCAL_SIZE),
                      groupCount(gbuffer.height, gpu::CONE_LOCAL_SIZE), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_COUNTS, 0);
    return out;
}

GlTexture timedConePass(PassTimer& timer, const char* name, const GBuffer& gbuffer, ConeCost* cost,
                        const std::function<GlTexture(GlBuffer& counts)>& trace) {
    GlBuffer counts;
    GlTexture out;
    {
        auto scope = timer.scope(name);
        out = trace(counts);
    }
    if (cost) {
        std::vector<float> c(size_t(gbuffer.width) * size_t(gbuffer.height) * 2);
        glGetNamedBufferSubData(counts.id(), 0, GLsizeiptr(c.size() * sizeof(float)), c.data());
        *cost = ConeCost{};
        for (size_t i = 0; i + 1 < c.size(); i += 2) cost->addPixel(c[i], c[i + 1]);
    }
    return out;
}

void checkGrid(const VoxelGrid& grid, const std::string& pass) {
    if (glm::any(glm::lessThan(grid.resolution, glm::ivec3(1))))
        throw InternalError(pass, "voxel grid has no resolution");
    if (!(grid.voxelSize > 0.f) || !std::isfinite(grid.voxelSize))
        throw InternalError(pass, "voxel grid has voxelSize " + std::to_string(grid.voxelSize));
    if (grid.levels < 1) throw InternalError(pass, "voxel grid has no mip levels");
    if (!grid.opacity) throw InternalError(pass, "voxel grid has no opacity texture");
}

}  // namespace vct::conedetail
