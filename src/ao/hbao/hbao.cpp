#include "ao/hbao/hbao.h"

namespace vct {

const SettingsTable<HbaoSettings>& hbaoSettings() {
    static const auto table =
        SettingsTable<HbaoSettings>()
            .integer("hbao.directions", &HbaoSettings::directions, 1, 32, "hbao: marching directions (gl_ssao: 8)")
            .integer("hbao.steps", &HbaoSettings::steps, 1, 64, "hbao: steps per direction (gl_ssao: 4)")
            .real("hbao.angle-bias", &HbaoSettings::angleBias, 0.f, 1.f,
                  "hbao: radians added to the tangent angle against creases");
    return table;
}

GlTexture runHbao(const AoPassContext& ctx, const HbaoSettings& settings) {
    gpu::HbaoUniforms u{};
    u.config = glm::ivec4(settings.directions, settings.steps, 0, 0);
    u.angles = glm::vec4(settings.angleBias, 0.f, 0.f, 0.f);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/hbao.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}


const ScreenSpaceAo& hbaoEstimator() {
    static const ScreenSpaceAo e = [] {
        ScreenSpaceAo s;
        s.name = "hbao";
        s.summary = "horizon-based AO (Bavoil and Sainz 2008)";
        s.settings = [] { return hbaoSettings().docs(); };
        s.evaluate = [](const AoPassContext& ctx, const ParamMap& params, bool ) {
            return runHbao(ctx, hbaoSettings().read(params));
        };
        s.programs = {computeProgramKey("ao/hbao.glsl")};
        return s;
    }();
    return e;
}

const Method& hbaoMethod() {
    static const Method m = screenSpaceMethod(hbaoEstimator());
    return m;
}

}  // namespace vct
