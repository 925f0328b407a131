// gtao: ground-truth-based AO (Jimenez et al. 2016) after Intel's XeGTAO.
#pragma once

#include "ao/screen_space.h"
#include "ao/gtao_shared.h"
#include "core/settings.h"

#include <string>

namespace vct {

struct GtaoSettings {
    std::string preset = "high";  // low | medium | high | ultra (XeGTAO's)
    int slices = gpu::GTAO_PRESET_HIGH_SLICES;  // default: the preset's
    int steps = gpu::GTAO_PRESET_HIGH_STEPS;    // per side; default: the preset's
    float radiusMultiplier = gpu::GTAO_DEFAULT_RADIUS_MULTIPLIER;
    float falloffRange = gpu::GTAO_DEFAULT_FALLOFF_RANGE;  // fraction of the radius
    float samplePower = gpu::GTAO_DEFAULT_SAMPLE_POWER;
    float thinOccluder = gpu::GTAO_DEFAULT_THIN_OCCLUDER;
    float finalPower = gpu::GTAO_DEFAULT_FINAL_POWER;
    bool multiBounce = false;  // Jimenez et al.'s multi-bounce fit from the G-buffer's albedo
};

// Slices and steps per side of an XeGTAO preset (low, medium, high, ultra).
void gtaoPresetCounts(const std::string& preset, int& slices, int& steps);
const SettingsTable<GtaoSettings>& gtaoSettings();
// `filtered`: a blur or upsample follows, so values up to AO_WORKING_MAX are kept for it
// (XeGTAO's working range) and the filter clamps to [0, 1]; otherwise clamped here.
GlTexture runGtao(const AoPassContext& ctx, const GtaoSettings& settings, bool filtered);

const ScreenSpaceAo& gtaoEstimator();
const Method& gtaoMethod();

}  // namespace vct
