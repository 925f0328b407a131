#include "reference/reference_methods.h"

#include "cone/cone_set.h"
#include "cone/cone_settings.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "reference/reference_gi.h"

#include <memory>

namespace vct {

namespace {

constexpr const char* kName = "reference";

// The BVH is built on first use by any ray-tracing method and kept for the session.
struct ReferenceSession {
    std::unique_ptr<EmbreeScene> embree;
};

ReferenceSettings settingsOf(const RenderRequest& r) {
    ReferenceSettings base;
    base.radius = r.radius;
    base.spp = r.spp;
    base.seed = r.seed;
    base.sky = r.sky;
    return referenceSettings().read(r.params, base);
}

std::vector<SurfacePoint> surfacePoints(const GBuffer& g) {
    std::vector<SurfacePoint> pts;
    for (const GBufferPoint& p : readGBufferPoints(g)) pts.push_back({p.position, p.normal, p.geomNormal, p.valid});
    return pts;
}

// The cone model of the request's cone set (vct.cones, vct.aperture, vct.jitter,
// vct.below-plane) for a w x h image, or an empty sampler when reference.cone-model is off.
ConeModelSampler coneModelOf(const RenderRequest& request, const ReferenceSettings& settings, int w, int h) {
    ConeModelSampler cones;
    if (!settings.coneModel) return cones;
    const ConeSettings c = readConeSettings(request.params);
    cones = ConeModelSampler(diffuseConeSet(c.coneCount), c.apertureDeg, c.belowPlane == ConeBelowPlane::Mirror);
    if (c.jitter) {
        // The images run top row first; the cone passes' pixels are GL's, bottom row 0.
        const uint32_t seed = coneJitterSeed(request.seed);
        std::vector<float> rotations(size_t(w) * size_t(h));
        for (int row = 0; row < h; ++row)
            for (int x = 0; x < w; ++x)
                rotations[size_t(row) * size_t(w) + size_t(x)] = gpu::cone_jitterAngle(uint32_t(x), uint32_t(h - 1 - row), seed);
        cones.setRotations(std::move(rotations));
    }
    return cones;
}

void executeAo(MethodContext& ctx) {
    if (!ctx.plan.runs(kPassReferenceAo)) return;
    const ReferenceSettings settings = settingsOf(ctx.request);
    if (settings.coneModel && settings.pixelArea)
        throw UsageError("--param reference.cone-model=1 needs reference.pixel=center for --ao reference");
    const ConeModelSampler cones = coneModelOf(ctx.request, settings, ctx.gbuffer->width, ctx.gbuffer->height);
    const EmbreeScene& embree = sessionEmbreeScene(ctx);
    auto scope = ctx.timer.scope("reference_ao", false);
    ReferenceAO ao = settings.pixelArea ? referenceAOPixelArea(embree, ctx.view, settings) : [&] {
        ReferenceAO a = referenceAO(embree, surfacePoints(*ctx.gbuffer), settings, cones);
        a.width = ctx.gbuffer->width;
        a.height = ctx.gbuffer->height;
        return a;
    }();
    ctx.outputs.setImage(kAo, ao.aoImage());
    ctx.outputs.setImage(kAoStderr, ao.stderrImage());
    ctx.extra["reference_ao"] = {{"spp", ao.sppUsed}, {"mean_stderr", ao.meanStderr}, {"rays", ao.raysTraced},
                                 {"primary_rays", ao.primaryRays}, {"rays_per_second", ao.raysPerSecond},
                                 {"pixel", settings.pixelArea ? "area" : "center"},
                                 {"model", settings.coneModel ? "cones" : "hemisphere"}};
}

void executeGi(MethodContext& ctx) {
    if (!ctx.plan.runs(kPassReferenceGi)) return;
    const ReferenceSettings settings = settingsOf(ctx.request);
    const EmbreeScene& embree = sessionEmbreeScene(ctx);
    auto scope = ctx.timer.scope("reference_gi", false);
    const ConeModelSampler cones = coneModelOf(ctx.request, settings, ctx.view.width, ctx.view.height);
    ReferenceGI gi = referenceGI(embree, ctx.view, settings, settings.pixelArea, cones);
    ctx.outputs.setImage(kGiIndirect, gi.indirect);
    ctx.outputs.setImage(kDirect, gi.direct);
    ctx.outputs.setImage(kBeauty, gi.beauty);
    // One channel: the mean of the RGB standard errors.
    ctx.outputs.setImage(kIndirectStderr, channelMean(gi.indirectStderr));
    ctx.extra["reference_gi"] = {{"spp", gi.sppUsed}, {"mean_stderr", gi.meanStderr}, {"rays", gi.raysTraced},
                                 {"rays_per_second", gi.raysPerSecond}, {"bounces", settings.bounces},
                                 {"model", settings.coneModel ? "cones" : "hemisphere"}};
}

}  // namespace

const EmbreeScene& sessionEmbreeScene(MethodContext& ctx) {
    ReferenceSession& s = ctx.session.get<ReferenceSession>("reference");
    // Built once per session, or anew when the request times a cold start; either way its
    // time is the BVH's, which a static scene's next frame does not pay again.
    struct Built {
        bool done = false;
    };
    Built& thisRender = ctx.frame.get<Built>("reference.bvh");
    if (!s.embree || (!ctx.request.reuseSceneData && !thisRender.done)) {
        thisRender.done = true;
        s.embree.reset();
        auto scope = ctx.timer.scope("bvh", false, Reruns::WhenSceneChanges);
        s.embree = std::make_unique<EmbreeScene>(ctx.scene);
    }
    return *s.embree;
}

const Method& referenceAoMethod() {
    static const Method m = [] {
        Method r;
        r.name = kName;
        r.kind = MethodKind::AO;
        r.summary = "ray-traced AO (Embree): the ground truth every AO method is scored against";
        r.groundTruth = true;
        r.passes = {{kPassReferenceAo, "--ao is not reference"}};
        r.aovs = {{{"ao_stderr", 1, "reference AO: per-pixel standard error"}, kAoStderr}};
        r.settings = [] { return referenceSettings().docs(); };
        r.programs = [] { return std::vector<ProgramKey>{}; };
        r.declare = [](const PlanContext&, PassDeclarations& d) {
            // Its own noise is always reported with it.
            d.add({kPassReferenceAo, {kGBufferSurface}, {kAo, kAoStderr}, "ray-traced AO at the G-buffer's points", true});
        };
        r.execute = executeAo;
        return r;
    }();
    return m;
}

const Method& referenceGiMethod() {
    static const Method m = [] {
        Method r;
        r.name = kName;
        r.kind = MethodKind::GI;
        r.summary = "path-traced GI (Embree): the ground truth every GI method is scored against";
        r.groundTruth = true;
        r.lightsTheImage = true;
        r.passes = {{kPassReferenceGi, "--gi is not reference"}};
        r.aovs = {{{"indirect_stderr", 1, "reference GI: per-pixel standard error of indirect"}, kIndirectStderr}};
        r.settings = [] { return referenceSettings().docs(); };
        r.programs = [] { return std::vector<ProgramKey>{}; };
        r.declare = [](const PlanContext&, PassDeclarations& d) {
            d.add({kPassReferenceGi, {}, {kGiIndirect, kDirect, kBeauty, kIndirectStderr}, "path-traced ground truth",
                   true});
        };
        r.execute = executeGi;
        return r;
    }();
    return m;
}

}  // namespace vct
