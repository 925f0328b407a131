#include "cone/cone_trace.h"

#include "cone/cone_gpu.h"
#include "cone/cone_set.h"

#include <cmath>
#include <stdexcept>

namespace vct {

using namespace conedetail;

static_assert(sizeof(gpu::ConeUniforms) == 2 * 64 + 6 * 16 + gpu::CONE_MAX_CONES * 16,
              "ConeUniforms must match its std140 layout");

namespace {

enum class ConeMode { AO, GI };

bool useAniso(const VoxelGrid& grid, const ConeSettings& s) {
    if (!s.anisotropic || !grid.anisotropic || grid.levels < 2) return false;
    for (const auto& t : grid.anisoRadiance)
        if (!t) return false;
    return true;
}

void checkGBuffer(const GBuffer& g, const View& view, const std::string& pass) {
    if (g.width <= 0 || g.height <= 0 || !g.position || !g.normal || !g.geomNormal || !g.albedo)
        throw std::invalid_argument(pass + ": G-buffer is incomplete (position, normal, geomNormal, albedo)");
    if (g.width != view.width || g.height != view.height)
        throw std::invalid_argument(pass + ": G-buffer " + std::to_string(g.width) + "x" +
                                    std::to_string(g.height) + " does not match the view " +
                                    std::to_string(view.width) + "x" + std::to_string(view.height));
}

// One cone pass: AO (R32F) or GI (RGBA32F).
GlTexture tracePass(ConeMode mode, const VoxelGrid& grid, const GBuffer& gbuffer, float maxDistWorld, float sky,
                    const ConeSettings& settings) {
    const bool gi = mode == ConeMode::GI;
    const bool aniso = useAniso(grid, settings);

    gpu::ConeUniforms u{};
    setGridUniforms(u, grid);
    float halfAperture = 0.5f * settings.apertureDeg * float(M_PI) / 180.f;
    float maxDist = maxDistWorld / grid.voxelSize;
    u.march = glm::vec4(std::tan(halfAperture), settings.stepFactor, settings.offsetVoxels, settings.maxAlpha);
    float falloff = (!gi && settings.aoMapping == ConeAoMapping::Falloff && maxDist > 0.f)
                        ? gpu::CONE_FALLOFF_LAMBDA_R / maxDist
                        : 0.f;
    u.limits = glm::vec4(maxDist, sky, falloff, settings.planeLimit ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f);
    std::vector<glm::vec4> cones = diffuseConeSet(settings.coneCount);
    u.config = glm::ivec4(int(cones.size()), gi ? gpu::CONE_AO_LINEAR : int(settings.aoMapping), 0, 0);
    u.image = glm::ivec4(gbuffer.width, gbuffer.height, 0, 0);
    for (size_t i = 0; i < cones.size(); ++i) u.cones[i] = cones[i];

    GLuint program = coneProgram(gi ? "cone/cone_gi.glsl" : "cone/cone_ao.glsl",
                                 {{"CONE_GI", gi ? "1" : "0"}, {"CONE_ANISO", aniso ? "1" : "0"}});
    GlTexture out = createTexture2D(gi ? GL_RGBA32F : GL_R32F, gbuffer.width, gbuffer.height);
    GlBuffer ubo = bindConeUniforms(u);

    bindGBufferTextures(gbuffer);  // the shaders texelFetch position, normal, geomNormal, albedo
    glBindTextureUnit(gpu::CONE_UNIT_OPACITY, gi ? grid.radiance.id() : grid.opacity.id());
    if (gi) glBindTextureUnit(gpu::CONE_UNIT_NORMAL, grid.normal.id());
    if (aniso)
        for (int i = 0; i < 6; ++i) glBindTextureUnit(gpu::CONE_UNIT_ANISO + i, grid.anisoRadiance[i].id());
    glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       gi ? GL_RGBA32F : GL_R32F);

    glUseProgram(program);
    glDispatchCompute(groupCount(gbuffer.width, gpu::CONE_LOCAL_SIZE),
                      groupCount(gbuffer.height, gpu::CONE_LOCAL_SIZE), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    return out;
}

}  // namespace

GlTexture coneTraceAO(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float radius,
                      const ConeSettings& settings, PassTimer& timer) {
    checkGrid(grid, "coneTraceAO");
    checkGBuffer(gbuffer, view, "coneTraceAO");
    settings.validate();
    if (!(radius >= 0.f) || !std::isfinite(radius))
        throw std::invalid_argument("coneTraceAO: radius " + std::to_string(radius) + " must be finite and >= 0");
    auto scope = timer.scope("cone_ao");
    return tracePass(ConeMode::AO, grid, gbuffer, radius, 0.f, settings);
}

GlTexture coneTraceGI(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float sky,
                      const ConeSettings& settings, PassTimer& timer) {
    checkGrid(grid, "coneTraceGI");
    checkGBuffer(gbuffer, view, "coneTraceGI");
    settings.validate();
    if (!grid.radiance) throw std::invalid_argument("coneTraceGI: voxel grid has no radiance (inject first)");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw std::invalid_argument("coneTraceGI: sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    // GI cones run until they leave the grid: the box diagonal bounds every path inside it.
    float diagonal = glm::length(glm::vec3(grid.resolution)) * grid.voxelSize;
    auto scope = timer.scope("cone_gi");
    return tracePass(ConeMode::GI, grid, gbuffer, 2.f * diagonal, sky, settings);
}

}  // namespace vct
