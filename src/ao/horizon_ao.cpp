#include "ao/horizon_ao.h"

namespace vct {

HorizonSettings readHorizonSettings(const ParamMap& params) {
    HorizonSettings s;
    s.directions = params.getInt("horizon.directions", s.directions, 1, 64,
                                 "ssao-horizon: marching directions (tinyrenderer: 8)");
    s.steps = params.getInt("horizon.steps", s.steps, 1, 128,
                            "ssao-horizon: depth samples per direction, spread evenly over R on screen");
    return s;
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

}  // namespace vct
