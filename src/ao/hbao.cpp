#include "ao/hbao.h"

namespace vct {

HbaoSettings readHbaoSettings(const ParamMap& params) {
    HbaoSettings s;
    s.directions = params.getInt("hbao.directions", s.directions, 1, 32, "hbao: marching directions (gl_ssao: 8)");
    s.steps = params.getInt("hbao.steps", s.steps, 1, 64, "hbao: steps per direction (gl_ssao: 4)");
    s.angleBias = params.getFloat("hbao.angle-bias", s.angleBias, 0.f, 1.f,
                                  "hbao: radians added to the tangent angle against creases");
    return s;
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

}  // namespace vct
