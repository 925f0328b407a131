#include "vct/voxel_region.h"

#include "cone/cone_set.h"
#include "gl/readback.h"
#include "vct/vct_passes.h"
#include "vct/vct_settings.h"
#include "voxelize/voxel_grid.h"
#include "voxelize/voxel_settings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vct {

std::string voxelRegionMode(const RenderRequest& r) {
    const std::string mode = vctSettings().read(r.params).region;
    if (mode != "auto") return mode;
    // A clipmap follows the camera over the whole scene: a region fitted to each view would move
    // its lattice with every frame.
    if (clipmapLevelCount(r) > 0) return "scene";
    return (r.ao == kVctMethodName && r.gi != kVctMethodName) ? "fit" : "scene";
}

int clipmapLevelCount(const RenderRequest& r) {
    return vctSettings().read(r.params).clipmapLevels;
}

std::string voxelRegionExplanation(const RenderRequest& r) {
    std::ostringstream s;
    const VctSettings vs = vctSettings().read(r.params);
    const std::string mode = voxelRegionMode(r);
    const bool explicitMode = r.params.has("vct.region") && r.params.values().at("vct.region") != "auto";
    if (mode == "fit")
        s << "region fit to the visible points grown by R = " << r.radius
          << (vs.fitReach == "lanes" ? " + the lanes' footprint" : " + cone footprint")
          << (r.gi == kVctMethodName ? " (vct.region=fit: GI cones see only that)" : " (AO only: nothing farther occludes)");
    else
        s << "region = scene bounds"
          << (explicitMode                  ? " (vct.region=scene)"
              : clipmapLevelCount(r) > 0     ? " (clipmap: its lattice is the scene's, the levels follow the camera)"
              : r.gi == kVctMethodName       ? " (GI: light travels far)"
                                             : "");
    const int levels = clipmapLevelCount(r);
    if (levels > 0)
        s << "; " << levels << " clipmap levels of " << r.voxelRes << "^3 around the camera (isotropic mips)";
    else
        s << "; one dense grid of " << r.voxelRes << " voxels along its longest axis";
    if (vs.grid == "cube") s << ", padded to a cube (vct.grid=cube)";
    if (vs.gridShift != 0.f) s << ", moved by " << vs.gridShift << " voxel (vct.grid-shift)";
    const VoxelEdges edges = voxelSettings().read(r.params).edges;
    if (edges == VoxelEdges::Coverage)
        s << "; each voxel holds the share of its column its sheets cover (vct.voxel.edges=coverage)";
    if (edges == VoxelEdges::Sheet)
        s << "; each voxel holds the share of its column its sheets cover and where in it they lie, the "
             "pixels' AO and GI cones meet them there, and an AO lane meeting a sheet near the maximum "
             "distance is closed by its share that meets it before (vct.voxel.edges=sheet)";
    return s.str();
}

Bounds3 visibleBounds(const Image& position) {
    Bounds3 b;
    if (position.channels < 4) return b;
    const size_t n = size_t(position.width) * size_t(position.height);
    for (size_t i = 0; i < n; ++i) {
        const float* p = &position.pixels[4 * i];
        if (!(p[3] > 0.f) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        b.min = glm::min(b.min, glm::vec3(p[0], p[1], p[2]));
        b.max = glm::max(b.max, glm::vec3(p[0], p[1], p[2]));
    }
    return b;
}

Bounds3 fitAoRegion(const Bounds3& visible, const Bounds3& scene, float reach, float marginVoxels, int voxelRes) {
    if (visible.empty() || scene.empty()) return scene;
    // makeGridLayout gives voxel = longest extent / (res - 2); with the extent itself
    // (visible + 2 reach + 2 m voxel) that solves to voxel = (visible + 2 reach) / (res - 2 - 2 m).
    const float cells = std::max(1.f, float(voxelRes - 2) - 2.f * marginVoxels);
    const float voxel = (visible.maxExtent() + 2.f * reach) / cells;
    const float grow = reach + marginVoxels * voxel;
    Bounds3 b;
    b.min = glm::max(visible.min - glm::vec3(grow), scene.min);
    b.max = glm::min(visible.max + glm::vec3(grow), scene.max);
    return glm::any(glm::greaterThan(b.min, b.max)) ? scene : b;
}

Bounds3 cubeAround(const Bounds3& b) {
    if (b.empty()) return b;
    const glm::vec3 half(0.5f * b.maxExtent());
    Bounds3 c;
    c.min = b.center() - half;
    c.max = b.center() + half;
    return c;
}

nlohmann::json VoxelRegion::toJson() const {
    nlohmann::json j = {{"mode", mode},
                        {"why", why},
                        {"min", {bounds.min.x, bounds.min.y, bounds.min.z}},
                        {"max", {bounds.max.x, bounds.max.y, bounds.max.z}},
                        {"follows_view", followsView}};
    if (!visible.empty())
        j["visible"] = {{"min", {visible.min.x, visible.min.y, visible.min.z}},
                        {"max", {visible.max.x, visible.max.y, visible.max.z}}};
    return j;
}

namespace {

VoxelRegion chooseRegionBounds(const RenderRequest& r, const VctSettings& vs, const Scene& scene,
                               const GBuffer* gbuffer, const ConeSettings& cone) {
    VoxelRegion region;
    region.mode = voxelRegionMode(r);
    region.bounds = scene.bounds;
    if (region.mode == "scene") {
        region.why = r.gi == kVctMethodName       ? "GI: light reaches the view from the whole scene"
                     : clipmapLevelCount(r) > 0   ? "clipmap: one lattice over the scene, the levels follow the camera"
                                                  : "vct.region=scene";
        return region;
    }
    if (!gbuffer || !gbuffer->position) {
        region.mode = "scene";
        region.why = "fit needs the G-buffer, which this render does not have";
        return region;
    }
    region.visible = visibleBounds(readTexture2D(gbuffer->position.id(), gbuffer->width, gbuffer->height, 4));
    if (region.visible.empty()) {
        region.mode = "scene";
        region.why = "no visible surface (all sky): nothing to fit";
        return region;
    }
    // R and the footprint's radius there; then the start offset and one voxel of trilinear
    // support. The footprint is the cone set's (vct.fit-reach=cones), or that of the lanes the
    // march traces at its level bias (lanes: narrower lanes, so the same voxels cover less
    // space); those of a grid whose longest axis has r.voxelRes voxels, as every fitted or
    // cubic grid's has.
    const bool laneReach = vs.fitReach == "lanes";
    const float tangent = laneReach ? coneFootprintTangent(cone, coneMarchLanes(cone, r.voxelRes).apertureDeg)
                                    : coneTanHalfAperture(cone.apertureDeg);
    const float reach = r.radius * (1.f + tangent);
    region.bounds = fitAoRegion(region.visible, scene.bounds, reach, cone.offsetVoxels + 1.f, r.voxelRes);
    region.followsView = region.bounds.min != scene.bounds.min || region.bounds.max != scene.bounds.max;
    std::ostringstream why;
    why << "visible points grown by the cone reach " << reach << " (R = " << r.radius << ") + "
        << cone.offsetVoxels + 1.f << " voxels, clipped to the scene";
    if (laneReach) why << " (vct.fit-reach=lanes: the lanes' footprint at R)";
    if (r.gi == kVctMethodName) why << " (vct.region=fit with GI: light from outside is lost)";
    region.why = why.str();
    return region;
}

}  // namespace

Bounds3 shiftedGridRegion(const Bounds3& b, float shiftVoxels, int voxelRes) {
    if (shiftVoxels == 0.f || b.empty()) return b;
    // The voxel the layout itself gives b, so the move follows its rule.
    const glm::vec3 move(shiftVoxels * makeGridLayout(b, voxelRes).voxelSize);
    Bounds3 s;
    s.min = b.min - move;
    s.max = b.max - move;
    return s;
}

VoxelRegion chooseVoxelRegion(const RenderRequest& r, const Scene& scene, const GBuffer* gbuffer,
                              const ConeSettings& cone) {
    const VctSettings vs = vctSettings().read(r.params);
    VoxelRegion region = chooseRegionBounds(r, vs, scene, gbuffer, cone);
    if (vs.grid == "cube") {
        region.bounds = cubeAround(region.bounds);
        region.why += "; padded to a cube around its centre (vct.grid=cube)";
    }
    if (vs.gridShift != 0.f) {
        region.bounds = shiftedGridRegion(region.bounds, vs.gridShift, r.voxelRes);
        std::ostringstream why;
        why << "; the grid moved by " << vs.gridShift << " voxel (vct.grid-shift)";
        region.why += why.str();
    }
    return region;
}

}  // namespace vct
