#include "ao/alchemy.h"

namespace vct {

AlchemySettings readAlchemySettings(const ParamMap& params) {
    AlchemySettings s;
    s.samples = params.getInt("alchemy.samples", s.samples, 1, gpu::ALCHEMY_MAX_SAMPLES,
                              "alchemy: spiral taps per pixel s (the paper's timings: 12)");
    s.turns = params.getInt("alchemy.turns", s.turns, 1, 64, "alchemy: turns of the tap spiral");
    s.sigma = params.getFloat("alchemy.sigma", s.sigma, 0.f, 10.f,
                              "alchemy: intensity sigma (applied as sigma * R, dimensionless)");
    s.beta = params.getFloat("alchemy.beta", s.beta, 0.f, 0.1f, "alchemy: bias beta, times linear depth");
    s.k = params.getFloat("alchemy.k", s.k, 0.1f, 8.f, "alchemy: contrast exponent k");
    s.epsilon = params.getFloat("alchemy.epsilon", s.epsilon, 1e-8f, 1.f,
                                "alchemy: epsilon in the denominator, in units of R^2");
    return s;
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

}  // namespace vct
