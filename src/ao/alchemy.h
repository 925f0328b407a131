// alchemy: McGuire et al., "The Alchemy Screen-Space Ambient Obscurance Algorithm", HPG 2011.
#pragma once

#include "ao/alchemy_shared.h"
#include "ao/ao_pass.h"
#include "render/params.h"

namespace vct {

struct AlchemySettings {
    int samples = gpu::ALCHEMY_DEFAULT_SAMPLES;   // spiral taps s, [1, 256]
    int turns = gpu::ALCHEMY_DEFAULT_TURNS;       // spiral turns, [1, 64]
    // Intensity. The paper's sum has units 1/length; multiplying sigma by R makes it
    // dimensionless, so sigma = 1 means the same at every scene scale (and R = 1 is the paper).
    float sigma = gpu::ALCHEMY_DEFAULT_SIGMA;     // [0, 10]
    float beta = gpu::ALCHEMY_DEFAULT_BETA;       // bias, times linear depth, [0, 0.1]
    float k = gpu::ALCHEMY_DEFAULT_K;             // contrast exponent, [0.1, 8]
    float epsilon = gpu::ALCHEMY_DEFAULT_EPSILON; // in units of R^2, [1e-8, 1]
};

AlchemySettings readAlchemySettings(const ParamMap& params);
GlTexture runAlchemy(const AoPassContext& ctx, const AlchemySettings& settings);

}  // namespace vct
