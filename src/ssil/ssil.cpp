#include "ssil/ssil.h"

#include "ao/ao_pass.h"
#include "denoise/atrous.h"
#include "gl/context.h"
#include "gl/program.h"

#include <algorithm>

namespace vct {

namespace {

static_assert(gpu::SSIL_UNIT_EMISSION == kUnitEmission, "ssil reads the emission at the G-buffer's unit");

ProgramKey ssilProgramKey() { return computeProgramKey("ssil/ssil.glsl"); }

void executeSsil(MethodContext& ctx) {
    if (!ctx.plan.runs(kPassSsil)) return;
    const RenderRequest& r = ctx.request;
    const SsilSettings settings = ssilSettings().read(r.params);
    const AtrousSettings filter = atrousSettings().read(r.params);
    GlTexture raw;
    {
        auto scope = ctx.timer.scope("ssil");
        raw = runSsil(*ctx.gbuffer, ctx.view, ctx.rendererTexture(kDirect), r.sky, settings, r.seed);
        GlContext::shared().checkErrors("ssil");
    }
    if (ctx.plan.runs(kPassSsilFilter)) {
        auto scope = ctx.timer.scope("ssil_atrous");
        raw = runAtrousFilter(*ctx.gbuffer, raw, 3, filter, true);
        GlContext::shared().checkErrors("ssil_atrous");
    }
    ctx.outputs.setTexture(kGiIndirect, std::move(raw), 4);
}

}  // namespace

const SettingsTable<SsilSettings>& ssilSettings() {
    static const auto table =
        SettingsTable<SsilSettings>()
            .integer("ssil.slices", &SsilSettings::slices, 1, gpu::SSIL_MAX_SLICES, "ssil: slices per pixel")
            .integer("ssil.steps", &SsilSettings::steps, 1, gpu::SSIL_MAX_STEPS, "ssil: samples per side of a slice")
            .real("ssil.extent", &SsilSettings::extent, 0.01f, 4.f,
                  "ssil: how far slices reach, x the image's longer side (light may come from anywhere on screen)")
            .real("ssil.thickness", &SsilSettings::thickness, 0.f, gpu::SSIL_MAX_THICKNESS,
                  "ssil: thickness assumed behind every visible point, x the view depth (the maximum: a height "
                  "field)")
            .real("ssil.sample-power", &SsilSettings::samplePower, 1.f, 4.f,
                  "ssil: step distribution exponent (1: uniform along the slice)")
            .flag("ssil.filter", &SsilSettings::filter, "ssil: denoise the gather with the a-trous filter (atrous.*)");
    return table;
}

GlTexture runSsil(const GBuffer& gbuffer, const View& view, const GlTexture* direct, float sky,
                  const SsilSettings& settings, uint64_t seed) {
    if (view.width != gbuffer.width || view.height != gbuffer.height)
        throw InternalError("ssil", "view and G-buffer sizes differ");
    // The AO passes' view block and G-buffer bindings; the radius is not read by ssil.glsl.
    AoPassContext ctx = makeAoPassContext(gbuffer, view, 1.f, 1, seed);
    gpu::SsilUniforms u{};
    u.config = glm::ivec4(settings.slices, settings.steps, direct ? 1 : 0, 0);
    u.params = glm::vec4(settings.extent * float(std::max(gbuffer.width, gbuffer.height)), settings.thickness,
                         settings.samplePower, sky);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    glBindTextureUnit(gpu::SSIL_UNIT_EMISSION, gbuffer.emission.id());
    glBindTextureUnit(gpu::SSIL_UNIT_DIRECT, direct ? direct->id() : 0);
    GlTexture out = createTexture2D(GL_RGBA32F, gbuffer.width, gbuffer.height);
    glUseProgram(cachedProgram(ssilProgramKey()));
    glBindImageTexture(gpu::SSIL_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groupCount(gbuffer.width, gpu::AO_LOCAL_SIZE_X), groupCount(gbuffer.height, gpu::AO_LOCAL_SIZE_Y),
                      1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindTextureUnit(gpu::SSIL_UNIT_DIRECT, 0);
    return out;
}

const Method& ssilMethod() {
    static const Method m = [] {
        Method r;
        r.name = "ssil";
        r.kind = MethodKind::GI;
        r.summary = "screen-space indirect light with visibility bitmasks (Therrien et al. 2023)";
        r.passes = {{kPassSsil, "--gi is not ssil"}, {kPassSsilFilter, "--gi is not ssil"}};
        r.settings = [] { return withAtrousDocs(ssilSettings().docs()); };
        r.programs = [] {
            std::vector<ProgramKey> keys = {ssilProgramKey()};
            for (const ProgramKey& k : atrousPrograms()) keys.push_back(k);
            return keys;
        };
        r.declare = [](const PlanContext& ctx, PassDeclarations& d) {
            std::vector<ResourceId> reads = {kGBuffer};
            if (ctx.lights()) reads.push_back(kDirect);  // the lit G-buffer: what each sample sends
            const bool filtered = ssilSettings().read(ctx.request.params).filter;
            d.add({kPassSsil, reads, {filtered ? kSsilRaw : kGiIndirect}, "one bounce of the lit G-buffer's light"});
            if (filtered) d.add({kPassSsilFilter, {kGBuffer, kSsilRaw}, {kGiIndirect}, "edge-avoiding a-trous filter"});
            else d.skip(kPassSsilFilter, "--param ssil.filter=0");
        };
        r.execute = executeSsil;
        return r;
    }();
    return m;
}

}  // namespace vct
