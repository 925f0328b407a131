// vbao: visibility-bitmask AO (Therrien, Levesque and Gilet 2023, "Screen Space Indirect
// Lighting with Visibility Bitmask"): GTAO's slices, each with a 32-bit mask of occluded
// sectors and an assumed thickness behind every visible point, so that a thin object no
// longer occludes everything behind it.
#pragma once

#include "ao/screen_space.h"
#include "ao/vbao_shared.h"
#include "core/settings.h"

namespace vct {

struct VbaoSettings {
    int slices = gpu::VBAO_DEFAULT_SLICES;
    int steps = gpu::VBAO_DEFAULT_STEPS;  // per side of a slice
    float thickness = gpu::VBAO_DEFAULT_THICKNESS;  // x R
    float radiusMultiplier = gpu::VBAO_DEFAULT_RADIUS_MULTIPLIER;
    float samplePower = gpu::VBAO_DEFAULT_SAMPLE_POWER;
};

const SettingsTable<VbaoSettings>& vbaoSettings();
// `filtered`: a blur or upsample follows, so values up to AO_WORKING_MAX are kept for it.
GlTexture runVbao(const AoPassContext& ctx, const VbaoSettings& settings, bool filtered);

const ScreenSpaceAo& vbaoEstimator();
const Method& vbaoMethod();

}  // namespace vct
