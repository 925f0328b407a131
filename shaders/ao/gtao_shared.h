// gtao (Jimenez et al. 2016, following Intel's XeGTAO): constants shared by src/ao/gtao.cpp
// and shaders/ao/gtao.glsl. Defaults are XeGTAO's (XeGTAO.h, v1.30), which its authors
// tuned against their ray-traced reference with an auto-tuner.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int GTAO_MAX_SLICES = 64;
VCT_CONST int GTAO_MAX_STEPS = 64;
// XeGTAO quality presets, slices x steps per side.
VCT_CONST int GTAO_PRESET_LOW_SLICES = 1, GTAO_PRESET_LOW_STEPS = 2;
VCT_CONST int GTAO_PRESET_MEDIUM_SLICES = 2, GTAO_PRESET_MEDIUM_STEPS = 2;
VCT_CONST int GTAO_PRESET_HIGH_SLICES = 3, GTAO_PRESET_HIGH_STEPS = 3;
VCT_CONST int GTAO_PRESET_ULTRA_SLICES = 9, GTAO_PRESET_ULTRA_STEPS = 3;

// Samples reach R x 1.457 and fade linearly over the last 61.5 %: the fade's midpoint sits
// near R itself, which is how XeGTAO's soft falloff approximates a binary radius.
VCT_CONST float GTAO_DEFAULT_RADIUS_MULTIPLIER = 1.457;
VCT_CONST float GTAO_DEFAULT_FALLOFF_RANGE = 0.615;
VCT_CONST float GTAO_DEFAULT_SAMPLE_POWER = 2.0;    // steps crowd near p: small crevices matter most
VCT_CONST float GTAO_DEFAULT_THIN_OCCLUDER = 0.0;   // XeGTAO ships with the heuristic off
VCT_CONST float GTAO_DEFAULT_FINAL_POWER = 2.2;     // XeGTAO's tuned output curve
// XeGTAO's "pixelTooCloseThreshold": the first step lands at least this many pixels out.
VCT_CONST float GTAO_MIN_STEP_PIXELS = 1.3;
// XeGTAO's fudge against over-darkening on steep slopes (its comment: PSNR 21.34 vs 21.45).
VCT_CONST float GTAO_PROJECTED_NORMAL_FUDGE = 0.05;

struct GtaoUniforms {
    ivec4 config;  // x = slices, y = steps per side, z = multi-bounce on (1) / off (0), w unused
    // x = effect radius (R x multiplier), y = falloff multiplier, z = falloff add, w = sample power
    vec4 falloff;
    // x = thin-occluder compensation, y = final power, z = output clamp (1, or AO_WORKING_MAX
    // when a filter follows), w unused
    vec4 shaping;
};

VCT_END_NAMESPACE
