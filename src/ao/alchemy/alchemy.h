// alchemy: McGuire et al., "The Alchemy Screen-Space Ambient Obscurance Algorithm", HPG 2011.
#pragma once

#include "ao/alchemy_shared.h"
#include "ao/screen_space.h"
#include "core/settings.h"

namespace vct {

struct AlchemySettings {
    int samples = gpu::ALCHEMY_DEFAULT_SAMPLES;   // spiral taps s
    int turns = gpu::ALCHEMY_DEFAULT_TURNS;       // spiral turns
    // Intensity. The paper's sum has units 1/length; multiplying sigma by R makes it
    // dimensionless, so sigma = 1 means the same at every scene scale (and R = 1 is the paper).
    float sigma = gpu::ALCHEMY_DEFAULT_SIGMA;
    float beta = gpu::ALCHEMY_DEFAULT_BETA;       // bias, times linear depth
    float k = gpu::ALCHEMY_DEFAULT_K;             // contrast exponent
    float epsilon = gpu::ALCHEMY_DEFAULT_EPSILON; // in units of R^2
};

const SettingsTable<AlchemySettings>& alchemySettings();
GlTexture runAlchemy(const AoPassContext& ctx, const AlchemySettings& settings);

const ScreenSpaceAo& alchemyEstimator();
const Method& alchemyMethod();

}  // namespace vct
