// hbao: horizon-based AO (Bavoil and Sainz 2008; NVIDIA gl_ssao).
#pragma once

#include "ao/screen_space.h"
#include "ao/hbao_shared.h"
#include "core/settings.h"

namespace vct {

struct HbaoSettings {
    int directions = gpu::HBAO_DEFAULT_DIRECTIONS;
    int steps = gpu::HBAO_DEFAULT_STEPS;            // per direction
    float angleBias = gpu::HBAO_DEFAULT_ANGLE_BIAS; // radians added to the tangent angle
};

const SettingsTable<HbaoSettings>& hbaoSettings();
GlTexture runHbao(const AoPassContext& ctx, const HbaoSettings& settings);

const ScreenSpaceAo& hbaoEstimator();
const Method& hbaoMethod();

}  // namespace vct
