// Filters shared by every screen-space AO method: the depth- and normal-aware bilateral blur
// (so occlusion does not bleed across depth and normal edges), LearnOpenGL's 4x4 box blur (ssao-crytek, ssao-hemisphere) and the
// depth-aware upsample from half resolution.
#pragma once

#include "ao/ao_pass.h"
#include "ao/blur_shared.h"
#include "core/settings.h"

#include <vector>

namespace vct {

enum class AoBlurMode { Bilateral, Box };

// What follows a screen-space evaluation (ranges and docs in aoFilterSettings()).
struct AoFilterSettings {
    bool blur = true;
    AoBlurMode mode = AoBlurMode::Bilateral;
    int radius = gpu::BLUR_DEFAULT_RADIUS;               // taps each side
    float sigma = gpu::BLUR_DEFAULT_SIGMA;               // spatial Gaussian, pixels
    float depthSigma = gpu::BLUR_DEFAULT_DEPTH_SIGMA;    // fraction of the centre depth
    float normalPower = gpu::BLUR_DEFAULT_NORMAL_POWER;  // exponent of max(0, n.n_i)
    bool halfRes = false;  // evaluate at half resolution, then a depth-aware upsample
};
const SettingsTable<AoFilterSettings>& aoFilterSettings();

// `boxAllowed`: the method has a 4x4 noise tile for the box blur to undo (ssao-crytek,
// ssao-hemisphere); asking for the box elsewhere is a UsageError.
AoFilterSettings readAoFilterSettings(const ParamMap& params, bool boxAllowed);

// w_0 .. w_radius of a 1D Gaussian of standard deviation sigma, normalized so that the full
// symmetric kernel sums to 1: w_0 + 2 sum_{i>0} w_i = 1. radius 0 gives {1}.
std::vector<float> bilateralGaussianWeights(int radius, float sigma);

// Separable bilateral blur (x then y) of an evaluation-resolution AO texture. `lastPass`:
// clamp the result to [0, 1] (else to AO_WORKING_MAX, for the upsample that follows).
GlTexture runBilateralBlur(const AoPassContext& ctx, const GlTexture& ao, const AoFilterSettings& settings,
                           bool lastPass = true);
GlTexture runBoxBlur(const AoPassContext& ctx, const GlTexture& ao);
// Half-resolution AO (ctx.scale 2) to the G-buffer's resolution; uses the blur's depth and
// normal terms.
GlTexture runDepthAwareUpsample(const AoPassContext& ctx, const GlTexture& ao, const AoFilterSettings& settings);

}  // namespace vct
