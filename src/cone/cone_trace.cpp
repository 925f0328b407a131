#include "cone/cone_trace.h"

#include "cone/cone_gpu.h"
#include "cone/cone_programs.h"
#include "cone/cone_set.h"
#include "core/errors.h"

#include <cmath>
#include <stdexcept>

namespace vct {

using namespace conedetail;

static_assert(sizeof(gpu::ConeUniforms) ==
                  2 * 64 + 9 * 16 + gpu::CONE_MAX_SET_CONES * 16 + gpu::CONE_BLOCK_CONES * 16,
              "ConeUniforms must match its std140 layout");
static_assert(sizeof(gpu::ConeUniforms) <= 16384, "GL 4.5 guarantees uniform blocks of 16 KiB (MAX_UNIFORM_BLOCK_SIZE)");

namespace {

enum class ConeMode { AO, GI };

void checkGBuffer(const GBuffer& g, const View& view, const std::string& pass, bool albedo) {
    requireGBuffer(g, pass, albedo);
    if (g.width != view.width || g.height != view.height)
        throw InternalError(pass, "G-buffer " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                                      " does not match the view " + std::to_string(view.width) + "x" +
                                      std::to_string(view.height));
}

// One cone pass: AO (R32F) or GI (RGBA32F).
GlTexture tracePass(ConeMode mode, const VoxelGrid& grid, const GBuffer& gbuffer, float maxDistWorld, float sky,
                    const ConeSettings& settings, GlBuffer& counts, int& dispatches) {
    const bool gi = mode == ConeMode::GI;
    BoundConePass bound = bindConePass(gi, grid, gbuffer, maxDistWorld, sky, settings);
    dispatches = bound.slices.count();
    return dispatchPixelPass(cachedProgram(conePassProgramKey(gi, bound.directional, bound.depthLevels, bound.sharpen, bound.sheets)), gi, gbuffer, counts, bound.ubo.id(),
                             settings.traceScale, bound.slices);
}

}  // namespace

GlTexture coneTraceAO(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float radius,
                      const ConeSettings& settings, PassTimer& timer, ConeCost* cost) {
    checkGrid(grid, "coneTraceAO");
    checkGBuffer(gbuffer, view, "coneTraceAO", false);
    settings.validate();
    if (!(radius >= 0.f) || !std::isfinite(radius))
        throw InternalError("coneTraceAO", "radius " + std::to_string(radius) + " must be finite and >= 0");
    return timedConePass(timer, "cone_ao", gbuffer, cost, [&](GlBuffer& counts, int& dispatches) {
        return tracePass(ConeMode::AO, grid, gbuffer, radius, 0.f, settings, counts, dispatches);
    });
}

GlTexture coneTraceGI(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float sky,
                      const ConeSettings& settings, PassTimer& timer, ConeCost* cost) {
    checkGrid(grid, "coneTraceGI");
    checkGBuffer(gbuffer, view, "coneTraceGI", true);
    settings.validate();
    if (!grid.radiance) throw InternalError("coneTraceGI", "voxel grid has no radiance (inject first)");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw InternalError("coneTraceGI", "sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    // GI cones run until they leave the grid: the box diagonal bounds every path inside it.
    float diagonal = glm::length(glm::vec3(grid.resolution)) * grid.voxelSize;
    return timedConePass(timer, "cone_gi", gbuffer, cost, [&](GlBuffer& counts, int& dispatches) {
        return tracePass(ConeMode::GI, grid, gbuffer, 2.f * diagonal, sky, settings, counts, dispatches);
    });
}

}  // namespace vct
