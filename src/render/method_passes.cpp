#include "render/method_passes.h"

#include "ao/screen_space_ao.h"
#include "clipmap/clipmap.h"
#include "cone/cone_bounce.h"
#include "cone/cone_trace.h"
#include "voxelize/voxelize.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "reference/reference_gi.h"
#include "render/voxel_region.h"
#include "vdb/sparse_cone.h"
#include "vdb/sparse_voxels.h"

#include <stdexcept>

namespace vct {

struct MethodCache::Impl {
    std::unique_ptr<EmbreeScene> embree;  // built on first use by a reference pass
    // Voxel grids keyed by everything that shapes them (resolution, injection, bounces, ...).
    std::map<std::string, std::shared_ptr<VoxelGrid>> grids;
    std::map<std::string, std::shared_ptr<Clipmap>> clipmaps;  // vct.clipmap.levels > 0, same keys
    std::map<std::string, std::shared_ptr<SparseVoxelScene>> sparse;  // --backend vdb
};

namespace {

MethodCache::Impl& cacheOf(MethodCache& c) {
    if (!c.impl) c.impl = std::make_shared<MethodCache::Impl>();
    return *c.impl;
}

const EmbreeScene& embreeOf(MethodCache& c, const Scene& scene) {
    auto& impl = cacheOf(c);
    if (!impl.embree) impl.embree = std::make_unique<EmbreeScene>(scene);
    return *impl.embree;
}

ReferenceSettings referenceSettings(const RenderRequest& r) {
    ReferenceSettings base;
    base.radius = r.radius;
    base.spp = r.spp;
    base.seed = r.seed;
    base.sky = r.sky;
    return referenceSettingsFromParams(r.params, base);
}

// The G-buffer's surface points (pixel centres), top row first, for the reference.
std::vector<SurfacePoint> gbufferPoints(const GBuffer& g) {
    Image pos = readTexture2D(g.position.id(), g.width, g.height, 4);
    Image nrm = readTexture2D(g.normal.id(), g.width, g.height, 4);
    Image geo = readTexture2D(g.geomNormal.id(), g.width, g.height, 4);
    std::vector<SurfacePoint> pts(size_t(g.width) * g.height);
    for (size_t i = 0; i < pts.size(); ++i) {
        const float* p = &pos.pixels[4 * i];
        const float* n = &nrm.pixels[4 * i];
        const float* q = &geo.pixels[4 * i];
        pts[i].position = glm::vec3(p[0], p[1], p[2]);
        pts[i].normal = glm::vec3(n[0], n[1], n[2]);
        pts[i].geomNormal = glm::vec3(q[0], q[1], q[2]);
        pts[i].valid = p[3] > 0.f;
    }
    return pts;
}

void runReferenceAo(const RenderRequest& r, const Scene& scene, const GBuffer& g, const View& view,
                    PassTimer& timer, MethodCache& cache, MethodOutputs& out, nlohmann::json& extra) {
    const ReferenceSettings settings = referenceSettings(r);
    const bool area = referencePixelAreaFromParams(r.params);
    const EmbreeScene& embree = embreeOf(cache, scene);
    auto scope = timer.scope("reference_ao", false);
    ReferenceAO ao = area ? referenceAOPixelArea(embree, view, settings)
                          : [&] {
                                ReferenceAO a = referenceAO(embree, gbufferPoints(g), settings);
                                a.width = g.width;
                                a.height = g.height;
                                return a;
                            }();
    out.aoImage = ao.aoImage();
    out.aoStderr = ao.stderrImage();
    extra["reference_ao"] = {{"spp", ao.sppUsed}, {"mean_stderr", ao.meanStderr}, {"rays", ao.raysTraced},
                             {"primary_rays", ao.primaryRays}, {"rays_per_second", ao.raysPerSecond},
                             {"pixel", area ? "area" : "center"}};
}

void runReferenceGi(const RenderRequest& r, const Scene& scene, const View& view, PassTimer& timer,
                    MethodCache& cache, MethodOutputs& out, nlohmann::json& extra) {
    const ReferenceSettings settings = referenceSettings(r);
    const bool area = referencePixelAreaFromParams(r.params);
    const EmbreeScene& embree = embreeOf(cache, scene);
    auto scope = timer.scope("reference_gi", false);
    ReferenceGI gi = referenceGI(embree, view, settings, area);
    out.indirectImage = gi.indirect;
    out.ptDirect = gi.direct;
    out.ptBeauty = gi.beauty;
    // One channel: the mean of the RGB standard errors.
    out.indirectStderr = Image(gi.width, gi.height, 1);
    for (size_t i = 0; i < size_t(gi.width) * gi.height; ++i) {
        const float* s = &gi.indirectStderr.pixels[3 * i];
        out.indirectStderr.pixels[i] = (s[0] + s[1] + s[2]) / 3.f;
    }
    extra["reference_gi"] = {{"spp", gi.sppUsed}, {"mean_stderr", gi.meanStderr}, {"rays", gi.raysTraced},
                             {"rays_per_second", gi.raysPerSecond}, {"bounces", settings.bounces}};
}

// A key of everything a grid depends on: two requests with the same key share one grid.
std::string gridKey(const RenderRequest& r, bool inject, bool aniso) {
    std::string k = std::to_string(r.voxelRes) + (inject ? "+inject" : "") + (aniso ? "+aniso" : "");
    // Bounces trace with the pixel cones' settings: then every cone parameter shapes the grid.
    const bool bounced = inject && readVctBounces(r.params) > 0;
    for (const auto& [key, value] : r.params.values())
        if (key.rfind("vct.voxel.", 0) == 0 || key.rfind("vct.inject.", 0) == 0 || key.rfind("vct.bounce", 0) == 0 ||
            (bounced && key.rfind("vct.", 0) == 0 && key.rfind("vct.view.", 0) != 0))
            k += ";" + key + "=" + value;
    if (inject) k += ";sky=" + std::to_string(r.sky);
    return k;
}

// The voxels of one render: a dense grid, or a clipmap (vct.clipmap.levels > 0).
struct VoxelVolume {
    std::shared_ptr<VoxelGrid> grid;     // dense path; the clipmap's coarsest level otherwise
    std::shared_ptr<Clipmap> clipmap;    // null on the dense path
    nlohmann::json stats;                // extra["voxels"]
};

std::string boundsKey(const Bounds3& b) {
    std::string k;
    for (int a = 0; a < 3; ++a) k += std::to_string(b.min[a]) + "," + std::to_string(b.max[a]) + ",";
    return k;
}

// --backend vdb: sparse OpenVDB voxels and the CPU cone tracer (src/vdb), on the same
// G-buffer points as every other method. Whole-scene grid, isotropic levels.
void runSparseVct(const RenderPlan& plan, const RenderRequest& r, const Scene& scene, const GBuffer& g,
                  PassTimer& timer, MethodCache& cache, std::map<std::string, int>& runCounts, MethodOutputs& out,
                  nlohmann::json& extra) {
    const ConeSettings cone = readConeSettings(r.params);
    const bool inject = plan.runs("inject");
    const std::string key = gridKey(r, inject, false);
    auto& slot = cacheOf(cache).sparse[key];
    if (!slot || !r.reuseVoxels) {
        auto scope = timer.scope("voxelize", false);
        slot = std::make_shared<SparseVoxelScene>(buildSparseVoxels(scene, r.voxelRes, inject, r.sky, r.params));
        runCounts["voxelize"]++;
    }
    const SparseVoxelScene& sv = *slot;
    extra["voxels"] = {{"backend", "vdb"},
                       {"resolution", {sv.resolution.x, sv.resolution.y, sv.resolution.z}},
                       {"voxel_size", sv.voxelSize},
                       {"active_voxels", sv.stats.activeVoxels},
                       {"memory_bytes", sv.stats.memoryBytes},
                       {"dense_bytes", sv.stats.denseBytes},
                       {"voxelize_s", sv.stats.voxelizeSeconds},
                       {"inject_s", sv.stats.injectSeconds},
                       {"levels_s", sv.stats.levelsSeconds},
                       {"bounces", 0}};  // the sparse path injects direct light only
    Image alb = readTexture2D(g.albedo.id(), g.width, g.height, 4);
    std::vector<SurfacePoint> base = gbufferPoints(g);
    std::vector<SparsePoint> pts(base.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        pts[i].position = base[i].position;
        pts[i].normal = base[i].normal;
        pts[i].geomNormal = base[i].geomNormal;
        pts[i].albedo = glm::vec3(alb.pixels[4 * i], alb.pixels[4 * i + 1], alb.pixels[4 * i + 2]);
        pts[i].valid = base[i].valid;
    }
    if (plan.runs("cone_ao")) {
        auto scope = timer.scope("cone_ao", false);
        std::vector<float> ao = sparseConeAO(sv, pts, r.radius, cone);
        out.aoImage = Image(g.width, g.height, 1);
        out.aoImage.pixels = std::move(ao);
    }
    if (plan.runs("cone_gi")) {
        auto scope = timer.scope("cone_gi", false);
        std::vector<glm::vec3> gi = sparseConeGI(sv, pts, r.sky, cone);
        out.indirectImage = Image(g.width, g.height, 3);
        for (size_t i = 0; i < gi.size(); ++i)
            for (int c = 0; c < 3; ++c) out.indirectImage.pixels[3 * i + c] = gi[i][c];
    }
    if (plan.runs("voxel_view"))
        throw std::invalid_argument("voxel_* AOVs show the dense grid: use --backend gl");
}

// A scene with no lights and no emission injects nothing: its voxels emit no radiance, and
// GI cones see only the sky through them. A 1^3 zero texture (zero border) stands in for
// the radiance volume so the cone shaders sample 0 everywhere without a special case.
void attachDarkRadiance(VoxelGrid& g) {
    if (g.radiance) return;
    g.radiance = createTexture3D(GL_RGBA16F, 1, 1, 1, 1);
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(g.radiance.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

// Voxelize, inject and filter as the plan says, or reuse the session's grid. The region
// (render/voxel_region.h) and the clipmap levels are part of the cache key.
VoxelVolume voxelGridFor(const RenderPlan& plan, const RenderRequest& r, const Scene& scene, const GpuScene& gpu,
                         const GBuffer* gbuffer, const ConeSettings& cone, PassTimer& timer, MethodCache& cache,
                         std::map<std::string, int>& runCounts) {
    const bool inject = plan.runs("inject");
    const int levels = clipmapLevelCount(r);
    const VoxelRegion region = chooseVoxelRegion(r, scene, gbuffer, cone.apertureDeg, cone.offsetVoxels);
    // Clipmaps keep isotropic mips only (clipmap/clipmap.h).
    const bool aniso = levels == 0 && cone.anisotropic;
    std::string key = gridKey(r, inject, aniso) + ";region=" + boundsKey(region.bounds);
    if (levels > 0) {
        const glm::vec3 e = r.camera.eye;
        key += ";clipmap=" + std::to_string(levels) + "@" + std::to_string(e.x) + "," + std::to_string(e.y) + "," +
               std::to_string(e.z);
    }
    VoxelVolume v;
    auto& impl = cacheOf(cache);
    if (r.reuseVoxels) {
        if (levels > 0) {
            auto it = impl.clipmaps.find(key);
            if (it != impl.clipmaps.end()) v.clipmap = it->second;
        } else {
            auto it = impl.grids.find(key);
            if (it != impl.grids.end()) v.grid = it->second;
        }
    }
    GlContext& gl = GlContext::shared();
    if (levels > 0 && !v.clipmap) {
        // Bounce cones would run inside one level and take its border for the sky: clipmap
        // levels hold direct light only.
        refuseVctBounces(r.params, inject, "vct.clipmap.levels");
        const ClipmapLayout layout = computeClipmapLayout(region.bounds, r.camera.eye, levels, r.voxelRes);
        v.clipmap = std::make_shared<Clipmap>(buildClipmap(gpu, scene, layout, inject, r.params, timer));
        gl.checkErrors("clipmap");
        runCounts["voxelize"]++;
        if (inject) runCounts["inject"]++;
        runCounts["mips"]++;
        if (r.reuseVoxels) impl.clipmaps[key] = v.clipmap;
    } else if (levels == 0 && !v.grid) {
        v.grid = std::make_shared<VoxelGrid>(voxelizeScene(gpu, region.bounds, r.voxelRes, r.params, timer));
        gl.checkErrors("voxelize");
        runCounts["voxelize"]++;
        if (inject) {
            injectRadiance(*v.grid, gpu, scene, r.params, timer);
            gl.checkErrors("inject");
            runCounts["inject"]++;
            traceVoxelBounces(*v.grid, r.sky, cone, r.params, timer);
            gl.checkErrors("bounce");
        }
        buildMips(*v.grid, aniso, timer);
        gl.checkErrors("mips");
        runCounts["mips"]++;
        if (r.reuseVoxels) impl.grids[key] = v.grid;
    }
    if (!inject && plan.runs("cone_gi")) {
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
                   {"memory_bytes", g.memoryBytes},
                   {"mips", g.anisotropic ? "anisotropic" : "isotropic"},
                   {"dense_voxels", size_t(g.resolution.x) * g.resolution.y * g.resolution.z}};
    }
    v.stats["region"] = region.toJson();
    v.stats["clipmap_levels"] = levels;
    // Extra bounces in the voxels: the dense grid's vct.bounces; clipmaps hold direct light only.
    v.stats["bounces"] = inject && levels == 0 ? readVctBounces(r.params) : 0;
    return v;
}

}  // namespace

MethodOutputs runMethodPasses(const RenderPlan& plan, const RenderRequest& request, const Scene& scene,
                              const GpuScene& gpu, const GBuffer* gbuffer, const View& view, PassTimer& timer,
                              MethodCache& cache, std::map<std::string, int>& runCounts, nlohmann::json& extra) {
    MethodOutputs out;
    GlContext& gl = GlContext::shared();
    if (plan.runs("ssao")) {
        out.ao = computeScreenSpaceAO(request.ao, *gbuffer, view, request.radius, request.params, request.seed, timer);
        gl.checkErrors("ssao");
    }
    if (plan.runs("reference_ao")) runReferenceAo(request, scene, *gbuffer, view, timer, cache, out, extra);
    if (plan.runs("reference_gi")) runReferenceGi(request, scene, view, timer, cache, out, extra);
    if (plan.runs("voxelize") && request.backend == "vdb") {
        runSparseVct(plan, request, scene, *gbuffer, timer, cache, runCounts, out, extra);
    } else if (plan.runs("voxelize")) {
        const ConeSettings cone = readConeSettings(request.params);
        VoxelVolume volume = voxelGridFor(plan, request, scene, gpu, gbuffer, cone, timer, cache, runCounts);
        std::shared_ptr<VoxelGrid> grid = volume.grid;
        extra["voxels"] = volume.stats;
        if (plan.runs("cone_ao")) {
            out.ao = volume.clipmap ? coneTraceClipmapAO(*volume.clipmap, *gbuffer, view, request.radius, cone, timer)
                                    : coneTraceAO(*grid, *gbuffer, view, request.radius, cone, timer);
            gl.checkErrors("cone_ao");
        }
        if (plan.runs("cone_gi")) {
            out.indirect = volume.clipmap ? coneTraceClipmapGI(*volume.clipmap, *gbuffer, view, request.sky, cone, timer)
                                          : coneTraceGI(*grid, *gbuffer, view, request.sky, cone, timer);
            gl.checkErrors("cone_gi");
        }
        if (plan.runs("voxel_view")) {
            const int level = request.params.getInt("vct.view.level", 0, 0, 16, "mip level shown by voxel_* AOVs");
            for (const std::string& aov : request.aovs) {
                if (aov.rfind("voxel_", 0) != 0) continue;
                const std::string what = aov.substr(6);
                GlTexture t = rayMarchVoxels(*grid, view, what, level, timer);
                gl.checkErrors("voxel_view");
                Image rgba = readTexture2D(t.id(), view.width, view.height, 4);
                const int channels = what == "opacity" ? 1 : 3;
                Image img(view.width, view.height, channels);
                for (size_t i = 0; i < size_t(view.width) * view.height; ++i)
                    for (int c = 0; c < channels; ++c)
                        img.pixels[i * channels + c] = rgba.pixels[4 * i + (what == "opacity" ? 3 : c)];
                out.voxelViews[aov] = std::move(img);
            }
        }
    }
    return out;
}

}  // namespace vct
