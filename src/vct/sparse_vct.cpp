#include "vct/sparse_vct.h"

#include "cone/cone_bounce.h"
#include "core/errors.h"

#include "vct/vct_passes.h"
#include "vct/voxel_region.h"
#include "vct/voxel_volume.h"

namespace vct {

namespace {
// The render's state key of its SparseFrame.
const char* const kSparseFrameKey = "vct.sparse";
}  // namespace

SparseFrame& sparseFrameFor(MethodContext& ctx, SparseVolumeCache& cache, const ConeSettings& cone) {
    SparseFrame& f = ctx.frame.get<SparseFrame>(kSparseFrameKey);
    if (f.voxels) return f;
    const RenderRequest& r = ctx.request;
    const bool inject = ctx.plan.runs(kPassInject);
    // The dense path's choices, so that the backends differ only in storage and sampling:
    // its region (fit to the view for AO) and its directional levels.
    const VoxelRegion region = chooseVoxelRegion(r, ctx.scene, ctx.gbuffer, cone);
    SparseBuildOptions options;
    options.region = region.bounds;
    options.anisotropic = cone.anisotropic;
    options.depthLevels = wantsDepthLevels(cone);
    options.attributes = voxelAttributesNeeded(ctx);
    // Lights that move rebuild the sparse grids whole (they are built and lit in one pass).
    const std::string key = voxelGridKey(r, inject, options.anisotropic, options.attributes) +
                            (options.depthLevels ? ";depth" : "") + ";region=" + boundsKey(region.bounds) +
                            (inject ? ";lights=" + lightsKey(ctx.scene) : std::string());
    // A camera path with a view-fitted region asks for new grids as it moves: keep a few.
    if (!cache.grids.count(key) && cache.grids.size() >= kMaxCachedVolumes) cache.grids.clear();
    auto& slot = cache.grids[key];
    if (!slot || !r.reuseSceneData) {
        // A region that follows the view is built anew for every new view (the dense path's rule).
        PassTimer::ViewDependent viewDependent(ctx.timer, region.followsView);
        auto scope = ctx.timer.scope("voxelize", false, Reruns::WhenSceneChanges);
        slot = std::make_shared<SparseVoxelScene>(
            buildSparseVoxels(ctx.scene, r.voxelRes, inject, r.sky, r.params, options));
        ctx.runCounts["voxelize"]++;
    }
    f.voxels = slot;
    const SparseVoxelScene& sv = *slot;
    ctx.extra["voxels"] = {{"backend", "vdb"},
                           {"resolution", {sv.resolution.x, sv.resolution.y, sv.resolution.z}},
                           {"voxel_size", sv.voxelSize},
                           {"active_voxels", sv.stats.activeVoxels},
                           {"memory_bytes", sv.stats.memoryBytes},
                           {"dense_bytes", sv.stats.denseBytes},
                           {"voxelize_s", sv.stats.voxelizeSeconds},
                           {"inject_s", sv.stats.injectSeconds},
                           {"levels_s", sv.stats.levelsSeconds},
                           {"mips", sv.anisotropic() ? "anisotropic" : "isotropic"},
                           {"level_opacity", sv.depthLevels ? "depth" : "alpha"},
                           {"region", region.toJson()},
                           {"bounce_s", sv.stats.bounceSeconds},
                           {"bounces", inject ? readVctBounces(r.params) : 0}};
    // Albedo where the G-buffer has it (GI reads it; an AO-only render draws none).
    for (const GBufferPoint& g : readGBufferPoints(*ctx.gbuffer, ctx.gbuffer->hasMaterials())) {
        SparsePoint p;
        p.position = g.position;
        p.normal = g.normal;
        p.geomNormal = g.geomNormal;
        p.albedo = g.albedo;
        p.valid = g.valid;
        f.points.push_back(p);
    }
    return f;
}

const SparseFrame& renderedSparseFrame(MethodContext& ctx) {
    const SparseFrame& f = ctx.frame.get<SparseFrame>(kSparseFrameKey);
    if (!f.voxels) throw InternalError("renderedSparseFrame", "no sparse voxels in this render (--backend vdb)");
    return f;
}

void traceSparse(MethodContext& ctx, MethodKind kind, const SparseFrame& f, const ConeSettings& cone) {
    const GBuffer& g = *ctx.gbuffer;
    if (kind == MethodKind::AO && ctx.plan.runs(kPassConeAo)) {
        auto scope = ctx.timer.scope("cone_ao", false);
        Image ao(g.width, g.height, 1);
        ConeCost cost;
        ao.pixels = sparseConeAO(*f.voxels, f.points, ctx.request.radius, cone, &cost);
        ctx.outputs.setImage(kAo, std::move(ao));
        ctx.extra["cone_ao"] = coneCostJson(cost, cone, ctx.request.voxelRes);
    }
    if (kind == MethodKind::GI && ctx.plan.runs(kPassConeGi)) {
        auto scope = ctx.timer.scope("cone_gi", false);
        ConeCost cost;
        const std::vector<glm::vec3> gi = sparseConeGI(*f.voxels, f.points, ctx.request.sky, cone, &cost);
        ctx.extra["cone_gi"] = coneCostJson(cost, cone, ctx.request.voxelRes);
        Image indirect(g.width, g.height, 3);
        for (size_t i = 0; i < gi.size(); ++i)
            for (int c = 0; c < 3; ++c) indirect.pixels[3 * i + c] = gi[i][c];
        ctx.outputs.setImage(kGiIndirect, std::move(indirect));
    }
}

}  // namespace vct
