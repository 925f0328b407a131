#include "cone/cone_gpu.h"

#include "cone/cone_set.h"
#include "core/errors.h"
#include "gl/readback.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <vector>

namespace vct::conedetail {

void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid) {
    u.voxelFromWorld = grid.voxelFromWorld;
    u.gridResolution = glm::vec4(glm::vec3(grid.resolution), float(grid.levels));
}

GlBuffer bindConeUniforms(const gpu::ConeUniforms& u) {
    GlBuffer ubo = createBuffer(sizeof(u), &u);  // dynamic: a reduced-resolution pass sets its stage
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
    u.trace = glm::ivec4(settings.traceScale, gpu::CONE_STAGE_TRACE, 0, 0);
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

GlTexture dispatchPixelPass(GLuint program, bool gi, const GBuffer& gbuffer, GlBuffer& counts, GLuint ubo,
                            int traceScale) {
    const GLenum format = gi ? GL_RGBA32F : GL_R32F;
    const int s = std::max(1, traceScale);
    GlTexture out = createTexture2D(format, gbuffer.width, gbuffer.height);
    const size_t pixels = size_t(gbuffer.width) * size_t(gbuffer.height);
    // Zeroed: with a trace scale only the traced pixels (and those that trace their own) write.
    counts = createBuffer(pixels * 2 * sizeof(float));
    glClearNamedBufferData(counts.id(), GL_R32F, GL_RED, GL_FLOAT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_COUNTS, counts.id());
    glUseProgram(program);
    const GLbitfield written = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                               GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                               GL_SHADER_STORAGE_BARRIER_BIT;
    if (s == 1) {
        glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        glDispatchCompute(groupCount(gbuffer.width, gpu::CONE_LOCAL_SIZE),
                          groupCount(gbuffer.height, gpu::CONE_LOCAL_SIZE), 1);
        glMemoryBarrier(written);
    } else {
        // The trace stage: one pixel per s x s block into the traced image.
        const int tw = (gbuffer.width + s - 1) / s, th = (gbuffer.height + s - 1) / s;
        GlTexture traced = createTexture2D(format, tw, th);
        glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, traced.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        glDispatchCompute(groupCount(tw, gpu::CONE_LOCAL_SIZE), groupCount(th, gpu::CONE_LOCAL_SIZE), 1);
        glMemoryBarrier(written);
        // The resolve stage over every pixel (cone_resolve.glsl).
        const GLint stage = gpu::CONE_STAGE_RESOLVE;
        glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, trace) + sizeof(GLint)), sizeof(stage), &stage);
        glBindImageTexture(gpu::CONE_IMAGE_TRACED, traced.id(), 0, GL_FALSE, 0, GL_READ_ONLY, format);
        glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        glDispatchCompute(groupCount(gbuffer.width, gpu::CONE_LOCAL_SIZE),
                          groupCount(gbuffer.height, gpu::CONE_LOCAL_SIZE), 1);
        glMemoryBarrier(written);
        glBindImageTexture(gpu::CONE_IMAGE_TRACED, 0, 0, GL_FALSE, 0, GL_READ_ONLY, format);
    }
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
        const size_t pixels = size_t(gbuffer.width) * size_t(gbuffer.height);
        std::vector<float> c(pixels * 2);
        glGetNamedBufferSubData(counts.id(), 0, GLsizeiptr(c.size() * sizeof(float)), c.data());
        // Surface pixels as the passes see them (position w > 0): the per-pixel figures' divisor,
        // whether a pixel traced its own cones or was resolved from its neighbours'.
        const Image position = readTexture2D(gbuffer.position.id(), gbuffer.width, gbuffer.height, 4);
        *cost = ConeCost{};
        for (size_t i = 0; i < pixels; ++i) cost->addPixel(c[2 * i], c[2 * i + 1], position.pixels[4 * i + 3] > 0.f);
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
