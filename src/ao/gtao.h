// gtao: ground-truth-based AO (Jimenez et al. 2016) after Intel's XeGTAO.
#pragma once

#include "ao/ao_pass.h"
#include "ao/gtao_shared.h"
#include "render/params.h"

#include <string>

namespace vct {

struct GtaoSettings {
    std::string preset = "high";  // low | medium | high | ultra (XeGTAO's)
    int slices = gpu::GTAO_PRESET_HIGH_SLICES;  // [1, 64]; overrides the preset's
    int steps = gpu::GTAO_PRESET_HIGH_STEPS;    // per side, [1, 64]; overrides the preset's
    float radiusMultiplier = gpu::GTAO_DEFAULT_RADIUS_MULTIPLIER;  // [0.1, 10]
    float falloffRange = gpu::GTAO_DEFAULT_FALLOFF_RANGE;          // fraction of the radius, [0.01, 1]
    float samplePower = gpu::GTAO_DEFAULT_SAMPLE_POWER;            // [1, 4]
    float thinOccluder = gpu::GTAO_DEFAULT_THIN_OCCLUDER;          // [0, 0.7]
    float finalPower = gpu::GTAO_DEFAULT_FINAL_POWER;              // [0.25, 5]
    bool multiBounce = false;  // Jimenez et al.'s multi-bounce fit from the G-buffer's albedo
};

// Slices and steps per side of an XeGTAO preset; throws std::invalid_argument on other names.
void gtaoPresetCounts(const std::string& preset, int& slices, int& steps);
GtaoSettings readGtaoSettings(const ParamMap& params);
// `filtered`: a blur or upsample follows, so values up to AO_WORKING_MAX are kept for it
// (XeGTAO's working range) and the filter clamps to [0, 1]; otherwise clamped here.
GlTexture runGtao(const AoPassContext& ctx, const GtaoSettings& settings, bool filtered);

}  // namespace vct
