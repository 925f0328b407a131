#include "vct/voxel_volume.h"

#include "cone/cone_bounce.h"
#include "core/errors.h"
#include "gl/context.h"
#include "vct/vct_passes.h"
#include "vct/voxel_region.h"
#include "voxelize/voxelize.h"

#include <algorithm>
#include <sstream>

namespace vct {

bool voxelAttributesNeeded(const MethodContext& ctx) {
    return ctx.plan.runs(kPassInject) || ctx.plan.runs(kPassConeGi) || ctx.plan.runs(kPassVoxelView);
}

std::string voxelGridKey(const RenderRequest& r, bool inject, bool aniso, bool attributes) {
    std::string k = std::to_string(r.voxelRes) + (inject ? "+inject" : "") + (aniso ? "+aniso" : "") +
                    (attributes ? "" : "+opacity-only");
    // Bounces trace with the pixel cones' settings: then every cone parameter shapes the grid.
    const bool bounced = inject && readVctBounces(r.params) > 0;
    for (const auto& [key, value] : r.params.values())
        if (key.rfind("vct.voxel.", 0) == 0 || key.rfind("vct.inject.", 0) == 0 || key.rfind("vct.bounce", 0) == 0 ||
            (bounced && key.rfind("vct.", 0) == 0 && key.rfind("vct.view.", 0) != 0))
            k += ";" + key + "=" + value;
    if (inject) k += ";sky=" + std::to_string(r.sky);
    return k;
}

std::string boundsKey(const Bounds3& b) {
    std::string k;
    for (int a = 0; a < 3; ++a) k += std::to_string(b.min[a]) + "," + std::to_string(b.max[a]) + ",";
    return k;
}

namespace {

// A scene with no lights and no emission injects nothing: its voxels emit no radiance, and
// GI cones see only the sky through them. A 1^3 zero texture (zero border) stands in for
// the radiance volume so the cone shaders sample 0 everywhere without a special case.
void attachDarkRadiance(VoxelGrid& g) {
    if (g.radiance) return;
    g.radiance = createTexture3D(GL_RGBA16F, 1, 1, 1, 1);
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(g.radiance.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

}  // namespace

namespace {

// Caches a volume, dropping the oldest once the cache holds kMaxCachedVolumes: a camera path with a
// view-fitted region or a moving clipmap asks for a new volume on many frames.
template <typename T>
void keepBounded(std::map<std::string, std::shared_ptr<T>>& map, std::deque<std::string>& order,
                 const std::string& key, const std::shared_ptr<T>& value) {
    map[key] = value;
    order.push_back(key);
    while (order.size() > kMaxCachedVolumes) {
        const std::string& old = order.front();
        if (std::count(order.begin(), order.end(), old) == 1) {
            // Only one of the two maps holds it; erase is a no-op on the other.
            map.erase(old);
        }
        order.pop_front();
    }
}

}  // namespace

namespace {

// What follows voxelization on the dense path: radiance injected and bounced (when lit), then
// the mips. Also what a moved light reruns on voxels it keeps.
void lightAndFilter(MethodContext& ctx, VoxelGrid& grid, const ConeSettings& cone, bool inject, bool aniso) {
    GlContext& gl = GlContext::shared();
    if (inject) {
        injectRadiance(grid, ctx.gpu, ctx.scene, ctx.request.params, ctx.timer);
        gl.checkErrors("inject");
        ctx.runCounts["inject"]++;
        traceVoxelBounces(grid, ctx.request.sky, cone, ctx.request.params, ctx.timer);
        gl.checkErrors("bounce");
    }
    buildMips(grid, aniso, ctx.timer, "mips", aniso && wantsDepthLevels(cone));
    gl.checkErrors("mips");
    ctx.runCounts["mips"]++;
}

}  // namespace

std::string lightsKey(const Scene& scene) {
    std::ostringstream k;
    k << std::hexfloat;
    for (const Light& l : scene.lights)
        k << int(l.type) << ':' << l.position.x << ',' << l.position.y << ',' << l.position.z << ':' << l.direction.x
          << ',' << l.direction.y << ',' << l.direction.z << ':' << l.color.x << ',' << l.color.y << ',' << l.color.z
          << ';';
    return k.str();
}

VoxelVolume voxelVolumeFor(MethodContext& ctx, const ConeSettings& cone, VoxelVolumeCache& cache) {
    const RenderRequest& r = ctx.request;
    const bool inject = ctx.plan.runs(kPassInject);
    const int levels = clipmapLevelCount(r);
    const VoxelRegion region = chooseVoxelRegion(r, ctx.scene, ctx.gbuffer, cone);
    // Clipmaps keep isotropic mips only (clipmap/clipmap.h).
    const bool aniso = levels == 0 && cone.anisotropic;
    if (levels > 0 && cone.opacity == ConeOpacity::Depth)
        throw UsageError("--param vct.opacity=depth: clipmaps keep isotropic levels only (vct.clipmap.levels=" +
                         std::to_string(levels) + "); use the dense grid or the sparse backend");
    if (levels > 0 && sharpensLevels(cone))
        throw UsageError("--param vct.sharpen: it filters the directional levels, and clipmaps keep isotropic levels "
                         "only (vct.clipmap.levels=" + std::to_string(levels) +
                         "); use the dense grid or the sparse backend");
    const bool attributes = voxelAttributesNeeded(ctx);
    std::string key = voxelGridKey(r, inject, aniso, attributes) + ";region=" + boundsKey(region.bounds);
    if (aniso && wantsDepthLevels(cone)) key += ";depth";
    // A clipmap is its layout: the cascades' origins snap to their voxels, so a camera moving
    // less than a snap step keeps the same cascades (the same voxels), a larger move builds new ones.
    const std::string lights = inject ? lightsKey(ctx.scene) : std::string();
    ClipmapLayout layout;
    if (levels > 0) {
        layout = computeClipmapLayout(region.bounds, clipmapFocus(region.bounds, r.camera, levels, r.voxelRes), levels,
                                      r.voxelRes);
        key += ";clipmap=" + std::to_string(levels);
        for (const glm::ivec3& o : layout.originIndex)
            key += "@" + std::to_string(o.x) + "," + std::to_string(o.y) + "," + std::to_string(o.z);
        // Lights that move rebuild a clipmap whole (its levels inject through each other).
        if (inject) key += ";lights=" + lights;
    }
    // A region fitted to the visible points inside the scene moves with the camera: its voxels
    // are built anew for every new view, so they count in the frame's cost.
    PassTimer::ViewDependent viewDependent(ctx.timer, region.followsView);
    VoxelVolume v;
    if (r.reuseSceneData) {
        if (levels > 0) {
            auto it = cache.clipmaps.find(key);
            if (it != cache.clipmaps.end()) v.clipmap = it->second;
        } else {
            auto it = cache.grids.find(key);
            if (it != cache.grids.end()) v.grid = it->second;
        }
    }
    GlContext& gl = GlContext::shared();
    if (levels > 0 && !v.clipmap) {
        // Bounce cones would run inside one level and take its border for the sky: clipmap
        // levels hold direct light only.
        refuseVctBounces(r.params, inject, "vct.clipmap.levels");
        v.clipmap = std::make_shared<Clipmap>(
            buildClipmap(ctx.gpu, ctx.scene, layout, inject, r.params, ctx.timer, attributes));
        gl.checkErrors("clipmap");
        ctx.runCounts["voxelize"]++;
        if (inject) ctx.runCounts["inject"]++;
        ctx.runCounts["mips"]++;
        if (r.reuseSceneData) keepBounded(cache.clipmaps, cache.order, key, v.clipmap);
    } else if (levels == 0 && !v.grid) {
        v.grid = std::make_shared<VoxelGrid>(
            voxelizeScene(ctx.gpu, region.bounds, r.voxelRes, r.params, ctx.timer, inject, attributes));
        gl.checkErrors("voxelize");
        ctx.runCounts["voxelize"]++;
        lightAndFilter(ctx, *v.grid, cone, inject, aniso);
        if (r.reuseSceneData) {
            keepBounded(cache.grids, cache.order, key, v.grid);
            cache.litBy[key] = lights;
        }
    } else if (levels == 0 && inject && cache.litBy[key] != lights) {
        // The lights moved, the geometry did not: the voxels stay, their radiance is injected
        // and bounced anew and its mips rebuilt (the opacity's come out the same).
        lightAndFilter(ctx, *v.grid, cone, true, aniso);
        cache.litBy[key] = lights;
    }
    if (!inject && ctx.plan.runs(kPassConeGi)) {
        if (v.clipmap)
            for (VoxelGrid& level : v.clipmap->levels) attachDarkRadiance(level);
        else
            attachDarkRadiance(*v.grid);
    }
    if (v.clipmap) {
        // The coarsest level covers the region: it serves the voxel_* views. Aliasing
        // shared_ptr: the level lives as long as the clipmap.
        v.grid = std::shared_ptr<VoxelGrid>(v.clipmap, &v.clipmap->levels.back());
        v.stats = clipmapStats(*v.clipmap);
    } else {
        const VoxelGrid& g = *v.grid;
        const glm::vec3 hi = g.origin + glm::vec3(g.resolution) * g.voxelSize;
        v.stats = {{"resolution", {g.resolution.x, g.resolution.y, g.resolution.z}},
                   {"voxel_size", g.voxelSize},
                   {"grid_min", {g.origin.x, g.origin.y, g.origin.z}},
                   {"grid_max", {hi.x, hi.y, hi.z}},
                   {"occupied", g.occupiedVoxels},
                   {"inject_dispatches", g.injectDispatches},
                   {"memory_bytes", g.memoryBytes},
                   {"mips", g.anisotropic ? "anisotropic" : "isotropic"},
                   {"level_opacity", g.depthLevels ? "depth" : "alpha"},
                   {"dense_voxels", size_t(g.resolution.x) * g.resolution.y * g.resolution.z}};
    }
    v.stats["region"] = region.toJson();
    v.stats["clipmap_levels"] = levels;
    // Extra bounces in the voxels: the dense grid's vct.bounces; clipmaps hold direct light only.
    v.stats["bounces"] = inject && levels == 0 ? readVctBounces(r.params) : 0;
    return v;
}

}  // namespace vct
