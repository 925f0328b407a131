#include "denoised/denoised_methods.h"

#include "denoise/atrous.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "reference/reference_ao.h"
#include "reference/reference_gi.h"
#include "reference/reference_methods.h"

namespace vct {

namespace {

// Samples of their own: the reference's streams hashed with a salt, so a comparison never
// scores an estimator against the very samples it drew.
uint64_t ownSeed(uint64_t seed, uint64_t salt) {
    uint64_t z = seed + salt * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

ReferenceSettings lowSppSettings(const RenderRequest& r, int spp, uint64_t salt) {
    ReferenceSettings s;
    s.radius = r.radius;
    s.sky = r.sky;
    s.spp = spp;
    s.seed = ownSeed(r.seed, salt);
    s.replicates = 1;  // below 8 spp there is one stream anyway; no error bar is reported
    s.minSpp = 1;
    s.progress = false;
    return s;
}

GlTexture uploaded(const Image& image, GLenum format) {
    GlTexture t = createTexture2D(format, image.width, image.height);
    uploadTexture2D(t.id(), image);
    return t;
}

void executeRtao(MethodContext& ctx) {
    if (!ctx.plan.runs(kPassRtao)) return;
    const RtaoDenoisedSettings settings = rtaoDenoisedSettings().read(ctx.request.params);
    const AtrousSettings filter = atrousSettings().read(ctx.request.params);
    const EmbreeScene& embree = sessionEmbreeScene(ctx);
    Image noisy;
    {
        auto scope = ctx.timer.scope("rtao", false);
        std::vector<SurfacePoint> points;
        for (const GBufferPoint& p : readGBufferPoints(*ctx.gbuffer))
            points.push_back({p.position, p.normal, p.geomNormal, p.valid});
        ReferenceAO ao = referenceAO(embree, points, lowSppSettings(ctx.request, settings.spp, 0xA0));
        ao.width = ctx.gbuffer->width;
        ao.height = ctx.gbuffer->height;
        noisy = ao.aoImage();
        ctx.extra["rtao_denoised"] = {{"spp", ao.sppUsed}, {"rays", ao.raysTraced}};
    }
    if (ctx.plan.runs(kPassRtaoFilter)) {
        auto scope = ctx.timer.scope("rtao_atrous");
        ctx.outputs.setTexture(kAo, runAtrousFilter(*ctx.gbuffer, uploaded(noisy, GL_R32F), 1, filter, false), 1);
        GlContext::shared().checkErrors("rtao_atrous");
    }
    ctx.outputs.setImage(kRtaoNoisy, std::move(noisy));
}

void executePt(MethodContext& ctx) {
    if (!ctx.plan.runs(kPassPt)) return;
    const PtDenoisedSettings settings = ptDenoisedSettings().read(ctx.request.params);
    const AtrousSettings filter = atrousSettings().read(ctx.request.params);
    const EmbreeScene& embree = sessionEmbreeScene(ctx);
    Image noisy;
    {
        auto scope = ctx.timer.scope("pt", false);
        ReferenceSettings s = lowSppSettings(ctx.request, settings.spp, 0x61);
        s.bounces = settings.bounces;
        ReferenceGI gi = referenceGI(embree, ctx.view, s, false);
        noisy = std::move(gi.indirect);
        ctx.extra["pt_denoised"] = {{"spp", gi.sppUsed}, {"rays", gi.raysTraced}, {"bounces", s.bounces}};
    }
    if (ctx.plan.runs(kPassPtFilter)) {
        auto scope = ctx.timer.scope("pt_atrous");
        ctx.outputs.setTexture(kGiIndirect, runAtrousFilter(*ctx.gbuffer, uploaded(noisy, GL_RGBA32F), 3, filter, true),
                               4);
        GlContext::shared().checkErrors("pt_atrous");
    }
    ctx.outputs.setImage(kPtNoisy, std::move(noisy));
}

}  // namespace

const SettingsTable<RtaoDenoisedSettings>& rtaoDenoisedSettings() {
    static const auto table = SettingsTable<RtaoDenoisedSettings>().integer(
        "rtao-denoised.spp", &RtaoDenoisedSettings::spp, 1, 64,
        "rtao-denoised: AO rays per pixel before the a-trous filter");
    return table;
}

const SettingsTable<PtDenoisedSettings>& ptDenoisedSettings() {
    static const auto table =
        SettingsTable<PtDenoisedSettings>()
            .integer("pt-denoised.spp", &PtDenoisedSettings::spp, 1, 64,
                     "pt-denoised: paths per pixel before the a-trous filter")
            .integer("pt-denoised.bounces", &PtDenoisedSettings::bounces, 1, 1024,
                     "pt-denoised: max diffuse reflections per path (as reference.bounces)");
    return table;
}

const Method& rtaoDenoisedMethod() {
    static const Method m = [] {
        Method r;
        r.name = "rtao-denoised";
        r.kind = MethodKind::AO;
        r.summary = "ray-traced AO at 1-4 spp (Embree), then the edge-avoiding a-trous filter";
        r.passes = {{kPassRtao, "--ao is not rtao-denoised"}, {kPassRtaoFilter, "--ao is not rtao-denoised"}};
        r.aovs = {{{"rtao_noisy", 1, "rtao-denoised: the AO estimate before the filter"}, kRtaoNoisy}};
        r.settings = [] { return withAtrousDocs(rtaoDenoisedSettings().docs()); };
        r.programs = atrousPrograms;
        r.declare = [](const PlanContext&, PassDeclarations& d) {
            d.add({kPassRtao, {kGBuffer}, {kRtaoNoisy}, "low-spp ray-traced AO at the G-buffer's points"});
            d.add({kPassRtaoFilter, {kGBuffer, kRtaoNoisy}, {kAo}, "edge-avoiding a-trous filter"});
        };
        r.execute = executeRtao;
        return r;
    }();
    return m;
}

const Method& ptDenoisedMethod() {
    static const Method m = [] {
        Method r;
        r.name = "pt-denoised";
        r.kind = MethodKind::GI;
        r.summary = "path-traced indirect light at 1-4 spp (Embree), then the edge-avoiding a-trous filter";
        r.passes = {{kPassPt, "--gi is not pt-denoised"}, {kPassPtFilter, "--gi is not pt-denoised"}};
        r.aovs = {{{"pt_noisy", 3, "pt-denoised: the indirect light before the filter"}, kPtNoisy}};
        r.settings = [] { return withAtrousDocs(ptDenoisedSettings().docs()); };
        r.programs = atrousPrograms;
        r.declare = [](const PlanContext&, PassDeclarations& d) {
            d.add({kPassPt, {kGBuffer}, {kPtNoisy}, "low-spp path-traced indirect light"});
            d.add({kPassPtFilter, {kGBuffer, kPtNoisy}, {kGiIndirect}, "edge-avoiding a-trous filter (irradiance)"});
        };
        r.execute = executePt;
        return r;
    }();
    return m;
}

}  // namespace vct
