#include "ao/alchemy/alchemy.h"

namespace vct {

const SettingsTable<AlchemySettings>& alchemySettings() {
    static const auto table =
        SettingsTable<AlchemySettings>()
            .integer("alchemy.samples", &AlchemySettings::samples, 1, gpu::ALCHEMY_MAX_SAMPLES,
                     "alchemy: spiral taps per pixel s (the paper's timings: 12)")
            .integer("alchemy.turns", &AlchemySettings::turns, 1, 64, "alchemy: turns of the tap spiral")
            .real("alchemy.sigma", &AlchemySettings::sigma, 0.f, 10.f,
                  "alchemy: intensity sigma (applied as sigma * R, dimensionless)")
            .real("alchemy.beta", &AlchemySettings::beta, 0.f, 0.1f, "alchemy: bias beta, times linear depth")
            .real("alchemy.k", &AlchemySettings::k, 0.1f, 8.f, "alchemy: contrast exponent k")
            .real("alchemy.epsilon", &AlchemySettings::epsilon, 1e-8f, 1.f,
                  "alchemy: epsilon in the denominator, in units of R^2");
    return table;
}

GlTexture runAlchemy(const AoPassContext& ctx, const AlchemySettings& settings) {
    gpu::AlchemyUniforms u{};
    u.config = glm::ivec4(settings.samples, settings.turns, 0, 0);
    u.terms = glm::vec4(2.f * settings.sigma * ctx.radius / float(settings.samples), settings.beta, settings.k,
                        settings.epsilon * ctx.radius * ctx.radius);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/alchemy.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}


const ScreenSpaceAo& alchemyEstimator() {
    static const ScreenSpaceAo e = [] {
        ScreenSpaceAo s;
        s.name = "alchemy";
        s.summary = "Alchemy AO (McGuire et al. 2011): spiral taps, obscurance sum";
        s.settings = [] { return alchemySettings().docs(); };
        s.evaluate = [](const AoPassContext& ctx, const ParamMap& params, bool ) {
            return runAlchemy(ctx, alchemySettings().read(params));
        };
        s.programs = {computeProgramKey("ao/alchemy.glsl")};
        return s;
    }();
    return e;
}

const Method& alchemyMethod() {
    static const Method m = screenSpaceMethod(alchemyEstimator());
    return m;
}

}  // namespace vct
