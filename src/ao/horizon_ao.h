// ssao-horizon: tinyrenderer's height-field AO (maximum elevation angle per direction).
#pragma once

#include "ao/ao_pass.h"
#include "ao/horizon_shared.h"
#include "render/params.h"

namespace vct {

struct HorizonSettings {
    int directions = gpu::HORIZON_DEFAULT_DIRECTIONS;  // [1, 64]
    int steps = gpu::HORIZON_DEFAULT_STEPS;            // samples per direction over R, [1, 128]
};

HorizonSettings readHorizonSettings(const ParamMap& params);
GlTexture runHorizonAo(const AoPassContext& ctx, const HorizonSettings& settings);

}  // namespace vct
