// ssao-horizon: tinyrenderer's height-field AO (maximum elevation angle per direction).
#pragma once

#include "ao/screen_space.h"
#include "ao/horizon_shared.h"
#include "core/settings.h"

namespace vct {

struct HorizonSettings {
    int directions = gpu::HORIZON_DEFAULT_DIRECTIONS;
    int steps = gpu::HORIZON_DEFAULT_STEPS;            // samples per direction over R
};

const SettingsTable<HorizonSettings>& horizonSettings();
GlTexture runHorizonAo(const AoPassContext& ctx, const HorizonSettings& settings);

const ScreenSpaceAo& horizonEstimator();
const Method& horizonMethod();

}  // namespace vct
