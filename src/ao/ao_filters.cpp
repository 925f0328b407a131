#include "ao/ao_filters.h"

#include <cmath>
#include <stdexcept>

namespace vct {

const SettingsTable<AoFilterSettings>& aoFilterSettings() {
    static const auto table =
        SettingsTable<AoFilterSettings>()
            .flag("blur", &AoFilterSettings::blur, "screen-space AO: blur the estimate (1) or not (0)")
            .choice("blur.mode", &AoFilterSettings::mode, {{"bilateral", AoBlurMode::Bilateral}, {"box", AoBlurMode::Box}},
                    "screen-space AO blur: depth/normal-aware bilateral, or the 4x4 box (ssao-crytek, "
                    "ssao-hemisphere only)")
            .integer("blur.radius", &AoFilterSettings::radius, 0, gpu::BLUR_MAX_RADIUS,
                     "bilateral blur: taps each side of the centre")
            .real("blur.sigma", &AoFilterSettings::sigma, 0.25f, 32.f, "bilateral blur: spatial Gaussian sigma, pixels")
            .real("blur.depth-sigma", &AoFilterSettings::depthSigma, 1e-4f, 1.f,
                  "bilateral blur and upsample: depth sigma as a fraction of the centre depth")
            .real("blur.normal-power", &AoFilterSettings::normalPower, 0.f, 128.f,
                  "bilateral blur and upsample: exponent p of max(0, n.n_i)^p")
            .flag("ao.half-res", &AoFilterSettings::halfRes,
                  "screen-space AO: evaluate at half resolution, then a depth-aware upsample");
    return table;
}

AoFilterSettings readAoFilterSettings(const ParamMap& params, bool boxAllowed) {
    AoFilterSettings s = aoFilterSettings().read(params);
    if (s.mode == AoBlurMode::Box && !boxAllowed)
        throw UsageError("--param blur.mode=box: only ssao-crytek and ssao-hemisphere have the 4x4 noise tile the box "
                         "blur is made for");
    return s;
}

std::vector<float> bilateralGaussianWeights(int radius, float sigma) {
    if (radius < 0 || radius > gpu::BLUR_MAX_RADIUS)
        throw InternalError("bilateralGaussianWeights", "radius " + std::to_string(radius) + " outside [0, " +
                                                            std::to_string(gpu::BLUR_MAX_RADIUS) + "]");
    if (!(sigma > 0.f)) throw InternalError("bilateralGaussianWeights", "sigma must be > 0");
    std::vector<double> w(size_t(radius) + 1);
    double sum = 0.0;
    for (int i = 0; i <= radius; ++i) {
        w[size_t(i)] = std::exp(-0.5 * double(i) * double(i) / (double(sigma) * double(sigma)));
        sum += (i == 0 ? 1.0 : 2.0) * w[size_t(i)];  // the symmetric kernel holds every i > 0 twice
    }
    std::vector<float> out(w.size());
    for (size_t i = 0; i < w.size(); ++i) out[i] = float(w[i] / sum);
    return out;
}

GlTexture runBilateralBlur(const AoPassContext& ctx, const GlTexture& ao, const AoFilterSettings& settings,
                           bool lastPass) {
    gpu::BlurUniforms u{};
    std::vector<float> weights = bilateralGaussianWeights(settings.radius, settings.sigma);
    for (size_t i = 0; i < weights.size(); ++i) u.weights[i / 4][int(i % 4)] = weights[i];
    GLuint program = cachedProgram(computeProgramKey("ao/bilateral_blur.glsl"));
    bindAoPassInputs(ctx);

    GlTexture current;
    const GlTexture* input = &ao;
    for (int axis = 0; axis < 2; ++axis) {
        u.config = glm::ivec4(settings.radius, axis, ctx.scale > 1 ? 1 : 0, 0);
        float outputMax = axis == 1 && lastPass ? 1.f : gpu::AO_WORKING_MAX;
        u.terms = glm::vec4(settings.depthSigma, settings.normalPower, outputMax, 0.f);
        GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
        glBindTextureUnit(gpu::AO_UNIT_INPUT, input->id());
        GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
        dispatchAoPass(program, out, ctx.evalWidth, ctx.evalHeight);
        current = std::move(out);
        input = &current;
    }
    glBindTextureUnit(gpu::AO_UNIT_INPUT, 0);
    return current;
}

GlTexture runBoxBlur(const AoPassContext& ctx, const GlTexture& ao) {
    bindAoPassInputs(ctx);
    glBindTextureUnit(gpu::AO_UNIT_INPUT, ao.id());
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/box_blur.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    glBindTextureUnit(gpu::AO_UNIT_INPUT, 0);
    return out;
}

GlTexture runDepthAwareUpsample(const AoPassContext& ctx, const GlTexture& ao, const AoFilterSettings& settings) {
    gpu::BlurUniforms u{};
    u.config = glm::ivec4(0, 0, 1, 0);
    u.terms = glm::vec4(settings.depthSigma, settings.normalPower, 1.f, 0.f);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    glBindTextureUnit(gpu::AO_UNIT_INPUT, ao.id());
    int width = ctx.gbuffer->width, height = ctx.gbuffer->height;
    GlTexture out = createAoTexture(width, height);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/upsample.glsl")), out, width, height);
    glBindTextureUnit(gpu::AO_UNIT_INPUT, 0);
    return out;
}

}  // namespace vct
