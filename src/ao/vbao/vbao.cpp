#include "ao/vbao/vbao.h"

namespace vct {

const SettingsTable<VbaoSettings>& vbaoSettings() {
    static const auto table =
        SettingsTable<VbaoSettings>()
            .integer("vbao.slices", &VbaoSettings::slices, 1, gpu::VBAO_MAX_SLICES,
                     "vbao: slices per pixel (3: GTAO High's count)")
            .integer("vbao.steps", &VbaoSettings::steps, 1, gpu::VBAO_MAX_STEPS,
                     "vbao: samples per side of a slice (a bitmask needs denser samples than GTAO's horizon)")
            .real("vbao.thickness", &VbaoSettings::thickness, 0.f, gpu::VBAO_MAX_THICKNESS,
                  "vbao: thickness assumed behind every visible point, x R (0: nothing occludes; the "
                  "maximum: GTAO's height field)")
            .real("vbao.radius-multiplier", &VbaoSettings::radiusMultiplier, 0.1f, 10.f,
                  "vbao: sampling radius / R (1: a sample occludes within R, the reference's V_R)")
            .real("vbao.sample-power", &VbaoSettings::samplePower, 1.f, 4.f,
                  "vbao: step distribution exponent (1: uniform along the slice; GTAO's 2 crowds near p)");
    return table;
}

GlTexture runVbao(const AoPassContext& ctx, const VbaoSettings& settings, bool filtered) {
    const float radius = ctx.radius * settings.radiusMultiplier;
    gpu::VbaoUniforms u{};
    u.config = glm::ivec4(settings.slices, settings.steps, 0, 0);
    u.params = glm::vec4(radius, settings.thickness * ctx.radius, settings.samplePower,
                         filtered ? gpu::AO_WORKING_MAX : 1.f);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/vbao.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}

const ScreenSpaceAo& vbaoEstimator() {
    static const ScreenSpaceAo e = [] {
        ScreenSpaceAo s;
        s.name = "vbao";
        s.summary = "visibility-bitmask AO: GTAO slices with thickness (Therrien et al. 2023)";
        s.settings = [] { return vbaoSettings().docs(); };
        s.evaluate = [](const AoPassContext& ctx, const ParamMap& params, bool filtered) {
            return runVbao(ctx, vbaoSettings().read(params), filtered);
        };
        s.programs = {computeProgramKey("ao/vbao.glsl")};
        return s;
    }();
    return e;
}

const Method& vbaoMethod() {
    static const Method m = screenSpaceMethod(vbaoEstimator());
    return m;
}

}  // namespace vct
