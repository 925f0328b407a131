#include "ao/horizon/horizon_ao.h"

namespace vct {

const SettingsTable<HorizonSettings>& horizonSettings() {
    static const auto table =
        SettingsTable<HorizonSettings>()
            .integer("horizon.directions", &HorizonSettings::directions, 1, 64,
                     "ssao-horizon: marching directions (tinyrenderer: 8)")
            .integer("horizon.steps", &HorizonSettings::steps, 1, 128,
                     "ssao-horizon: depth samples per direction, spread evenly over R on screen");
    return table;
}

GlTexture runHorizonAo(const AoPassContext& ctx, const HorizonSettings& settings) {
    gpu::HorizonUniforms u{};
    u.config = glm::ivec4(settings.directions, settings.steps, 0, 0);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/horizon.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}


const ScreenSpaceAo& horizonEstimator() {
    static const ScreenSpaceAo e = [] {
        ScreenSpaceAo s;
        s.name = "ssao-horizon";
        s.summary = "height-field AO (tinyrenderer): highest horizon per direction";
        s.settings = [] { return horizonSettings().docs(); };
        s.evaluate = [](const AoPassContext& ctx, const ParamMap& params, bool ) {
            return runHorizonAo(ctx, horizonSettings().read(params));
        };
        s.programs = {computeProgramKey("ao/horizon.glsl")};
        return s;
    }();
    return e;
}

const Method& horizonMethod() {
    static const Method m = screenSpaceMethod(horizonEstimator());
    return m;
}

}  // namespace vct
