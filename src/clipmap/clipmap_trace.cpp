// coneTraceClipmapAO / coneTraceClipmapGI (clipmap/clipmap.h): the dense path's cone passes
// (cone/cone_trace.cpp) with the clipmap's levels bound instead of one grid.
#include "clipmap/clipmap.h"

#include "cone/clipmap_shared.h"
#include "cone/cone_gpu.h"
#include "cone/cone_programs.h"
#include "cone/cone_set.h"
#include "core/errors.h"

#include <cmath>
#include <stdexcept>

namespace vct {

using namespace conedetail;

static_assert(sizeof(gpu::ClipmapUniforms) == (gpu::CLIPMAP_MAX_LEVELS + 2) * 16,
              "ClipmapUniforms must match its std140 layout");

namespace {

void checkInputs(const Clipmap& cm, const GBuffer& g, const View& view, const std::string& pass, bool albedo) {
    if (cm.layout.levelCount < 1 || int(cm.levels.size()) != cm.layout.levelCount)
        throw InternalError(pass, "clipmap has no levels");
    for (const VoxelGrid& level : cm.levels) checkGrid(level, pass);
    requireGBuffer(g, pass, albedo);
    if (g.width != view.width || g.height != view.height)
        throw InternalError(pass, "G-buffer size does not match the view");
}

GlTexture traceClipmap(bool gi, const Clipmap& cm, const GBuffer& gbuffer, float maxDistWorld, float sky,
                       const ConeSettings& settings, GlBuffer& counts, int& dispatches) {
    const ClipmapLayout& layout = cm.layout;
    const VoxelGrid& base = cm.levels.front();
    gpu::ConeUniforms u = coneUniforms(gi, base, maxDistWorld, sky, settings);
    u.image = conePixelImage(gbuffer, settings);

    gpu::ClipmapUniforms c{};
    for (int l = 0; l < layout.levelCount; ++l) {
        const float w = 1.f / float(1 << l);
        // x_l = (x_0 * s_0 + origin_0 - origin_l) / s_l, origins in whole level-0 voxels.
        const glm::vec3 shift = glm::vec3(layout.originIndex[0] - layout.originIndex[size_t(l)]) * w;
        c.levelFromLevel0[l] = glm::vec4(shift, w);
    }
    c.info = glm::vec4(float(layout.levelCount), float(layout.resolution), float(base.levels), 0.f);
    c.band = glm::vec4(gpu::CLIPMAP_BORDER_MARGIN, gpu::CLIPMAP_BLEND_WIDTH, 0.f, 0.f);

    const GLuint program = cachedProgram(clipmapConePassProgramKey(gi));
    GlBuffer ubo = bindConeUniforms(u);
    GlBuffer clipUbo = createBuffer(sizeof(c), &c, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::CLIPMAP_UBO_BINDING, clipUbo.id());

    bindGBufferTextures(gbuffer);
    for (int l = 0; l < layout.levelCount; ++l) {
        const VoxelGrid& g = cm.levels[size_t(l)];
        glBindTextureUnit(GLuint(gpu::CLIPMAP_UNIT_LEVEL0 + l), gi ? g.radiance.id() : g.opacity.id());
    }
    // Per step: the march and its plane-limit search (denseLoopsPerStep), and the level
    // search over the clipmap's levels (clip_positionLod) for each of the step's two lods.
    const ConeSlices slices = coneSlices(u, settings, denseLoopsPerStep(settings) + 2 * (layout.levelCount - 1));
    dispatches = slices.count();
    GlTexture out = dispatchPixelPass(program, gi, gbuffer, counts, ubo.id(), settings.traceScale, slices);
    for (int l = 0; l < layout.levelCount; ++l) glBindTextureUnit(GLuint(gpu::CLIPMAP_UNIT_LEVEL0 + l), 0);
    return out;
}

}  // namespace

GlTexture coneTraceClipmapAO(const Clipmap& cm, const GBuffer& gbuffer, const View& view, float radius,
                             const ConeSettings& settings, PassTimer& timer, ConeCost* cost) {
    checkInputs(cm, gbuffer, view, "coneTraceClipmapAO", false);
    settings.validate();
    if (!(radius >= 0.f) || !std::isfinite(radius))
        throw InternalError("coneTraceClipmapAO", "radius " + std::to_string(radius) + " must be finite and >= 0");
    return timedConePass(timer, "cone_ao", gbuffer, cost, [&](GlBuffer& counts, int& dispatches) {
        return traceClipmap(false, cm, gbuffer, radius, 0.f, settings, counts, dispatches);
    });
}

GlTexture coneTraceClipmapGI(const Clipmap& cm, const GBuffer& gbuffer, const View& view, float sky,
                             const ConeSettings& settings, PassTimer& timer, ConeCost* cost) {
    checkInputs(cm, gbuffer, view, "coneTraceClipmapGI", true);
    settings.validate();
    for (const VoxelGrid& g : cm.levels)
        if (!g.radiance) throw InternalError("coneTraceClipmapGI", "clipmap has no radiance (inject first)");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw InternalError("coneTraceClipmapGI", "sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    // As the dense path: twice the coarsest level's diagonal bounds every path inside it.
    const float diagonal = std::sqrt(3.f) * float(cm.layout.resolution) *
                           cm.layout.voxelSize(cm.layout.levelCount - 1);
    return timedConePass(timer, "cone_gi", gbuffer, cost, [&](GlBuffer& counts, int& dispatches) {
        return traceClipmap(true, cm, gbuffer, 2.f * diagonal, sky, settings, counts, dispatches);
    });
}

}  // namespace vct
