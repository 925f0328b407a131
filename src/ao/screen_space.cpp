#include "ao/screen_space.h"

#include "gl/context.h"

#include <cmath>

namespace vct {

namespace {

// The passes of one screen-space render, from its filter settings.
void declareScreenSpacePasses(const ScreenSpaceAo& ao, const PlanContext& ctx, PassDeclarations& d) {
    const AoFilterSettings f = readAoFilterSettings(ctx.request.params, ao.noiseTile);
    ResourceId produced = kAoRaw;
    const ResourceId gbuffer = ao.readsAlbedo && ao.readsAlbedo(ctx.request.params) ? kGBuffer : kGBufferSurface;
    d.add({kPassSsao, {gbuffer}, {produced}, "screen-space AO estimator " + ao.name});
    if (f.blur) {
        d.add({kPassBlur, {kGBufferSurface, produced}, {kAoBlurred}, "edge-aware denoise"});
        produced = kAoBlurred;
    } else {
        d.skip(kPassBlur, "--param blur=0");
    }
    if (f.halfRes) d.add({kPassUpsample, {kGBufferSurface, produced}, {kAo}, "depth-aware upsample to full size"});
    else d.skip(kPassUpsample, "full-resolution AO (ao.half-res=0)");
    if (!f.halfRes) d.passes.back().writes = {kAo};
}

}  // namespace

std::vector<ProgramKey> screenSpaceFilterPrograms() {
    return {computeProgramKey("ao/bilateral_blur.glsl"), computeProgramKey("ao/box_blur.glsl"),
            computeProgramKey("ao/upsample.glsl")};
}

Method screenSpaceMethod(const ScreenSpaceAo& ao) {
    Method m;
    m.name = ao.name;
    m.kind = MethodKind::AO;
    m.summary = ao.summary;
    const std::string notScreenSpace = "--ao {ao} is not a screen-space method";
    m.passes = {{kPassSsao, notScreenSpace}, {kPassBlur, notScreenSpace}, {kPassUpsample, notScreenSpace}};
    m.settings = [ao] {
        std::vector<SettingDoc> docs = ao.settings ? ao.settings() : std::vector<SettingDoc>{};
        for (const SettingDoc& d : aoFilterSettings().docs()) docs.push_back(d);
        return docs;
    };
    m.presetValues = ao.presetValues;
    m.programs = [ao] {
        std::vector<ProgramKey> keys = ao.programs;
        for (const ProgramKey& k : screenSpaceFilterPrograms()) keys.push_back(k);
        return keys;
    };
    m.declare = [ao](const PlanContext& ctx, PassDeclarations& d) { declareScreenSpacePasses(ao, ctx, d); };
    m.execute = [ao](MethodContext& ctx) {
        if (!ctx.plan.runs(kPassSsao)) return;
        const RenderRequest& r = ctx.request;
        ctx.outputs.setTexture(kAo, computeScreenSpaceAO(ao, *ctx.gbuffer, ctx.view, r.radius, r.params, r.seed, ctx.timer),
                               1);
        GlContext::shared().checkErrors("ssao");
    };
    return m;
}

GlTexture computeScreenSpaceAO(const ScreenSpaceAo& ao, const GBuffer& gbuffer, const View& view, float radius,
                               const ParamMap& params, uint64_t seed, PassTimer& timer) {
    if (!std::isfinite(radius) || !(radius > 0.f))
        throw InternalError(ao.name, "AO radius must be finite and > 0, got " + std::to_string(radius));
    if (gbuffer.width <= 0 || gbuffer.height <= 0 || !gbuffer.position || !gbuffer.normal)
        throw InternalError(ao.name, "G-buffer has no position/normal attachments");
    if (view.width != gbuffer.width || view.height != gbuffer.height)
        throw InternalError(ao.name, "view is " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                                         " but the G-buffer is " + std::to_string(gbuffer.width) + "x" +
                                         std::to_string(gbuffer.height));

    // Read every parameter before any GL work, so a bad value fails fast.
    const AoFilterSettings filter = readAoFilterSettings(params, ao.noiseTile);
    AoPassContext ctx = makeAoPassContext(gbuffer, view, radius, filter.halfRes ? 2 : 1, seed);

    GlTexture out;
    {
        auto scope = timer.scope("ssao");
        out = ao.evaluate(ctx, params, filter.blur || filter.halfRes);
    }
    if (filter.blur) {
        auto scope = timer.scope("blur");
        out = filter.mode == AoBlurMode::Box ? runBoxBlur(ctx, out) : runBilateralBlur(ctx, out, filter, !filter.halfRes);
    }
    if (filter.halfRes) {
        auto scope = timer.scope("upsample");
        out = runDepthAwareUpsample(ctx, out, filter);
    }
    return out;
}

}  // namespace vct
