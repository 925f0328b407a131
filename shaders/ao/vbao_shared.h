// vbao: visibility-bitmask AO (Therrien, Levesque and Gilet 2023): constants shared by
// src/ao/vbao/vbao.cpp and shaders/ao/vbao.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int VBAO_MAX_SLICES = 64;
VCT_CONST int VBAO_MAX_STEPS = 64;

// Defaults: one set for every scene, chosen by RMSE against the reference (128 spp, 96 px,
// R = 0.5 and 1) averaged over the nine scenes in scenes/ and the thin pole of
// tests/gpu/vbao_test.cpp (GTAO High with XeGTAO's defaults: 0.1059 there):
// - 3 slices, as GTAO's High preset (2 slices: 0.0936 against 0.0927 for 3);
// - 16 steps per side: a height field fills everything below its highest sample, but a mask
//   of finite samples has gaps between them, so it needs denser samples to find the same
//   occluders; at a thickness of 0.3 R, 8 / 12 / 16 / 24 / 32 steps give 0.0996 / 0.0961 /
//   0.0927 / 0.0912 / 0.0908: 16 is where doubling stops paying;
// - a thickness of 0.4 R (0.3 / 0.4 / 0.5 / 0.7 / 1 / infinite at 16 steps: 0.0927 / 0.0926 /
//   0.0940 / 0.0960 / 0.0968 / 0.0971; the nine scenes alone, whose occluders are solid
//   blocks, are flat from 0.4 to 0.7 at 0.0998 / 0.0994 / 0.0998 (infinite: 0.1010), and 0.4
//   is the thinnest of that plateau, which keeps the most of the gain on thin occluders: the
//   pole's RMSE at R = 1 is 0.052 against 0.088 at 0.5 and GTAO's 0.091);
// - a sampling radius of exactly R: a sample occludes when it lies within R of p, the
//   reference's binary V_R, with no soft falloff to tune;
// - steps spread uniformly along the slice (power 1): with gaps between finite samples a
//   crowd near p leaves the far part of the radius unsampled (power 2 at 12 steps: 0.0966
//   against 0.0954 at a thickness of 0.5 R).
VCT_CONST int VBAO_DEFAULT_SLICES = 3;
VCT_CONST int VBAO_DEFAULT_STEPS = 16;
VCT_CONST float VBAO_DEFAULT_RADIUS_MULTIPLIER = 1.0;
VCT_CONST float VBAO_DEFAULT_SAMPLE_POWER = 1.0;
// The thickness assumed behind every visible point, as a fraction of R: R is the scale of the
// occluders that count, so the default serves every scene scale. Below the gap between a thin
// occluder and what is behind it, that occluder stops darkening the far surface; a solid
// object deeper than it lets light through behind its visible face.
VCT_CONST float VBAO_DEFAULT_THICKNESS = 0.4;
VCT_CONST float VBAO_MAX_THICKNESS = 10000.0;  // x R: the height field (GTAO) for any scene
// As GTAO (XeGTAO's "pixelTooCloseThreshold"): the first step lands this many pixels out.
VCT_CONST float VBAO_MIN_STEP_PIXELS = 1.3;

struct VbaoUniforms {
    ivec4 config;  // x = slices, y = steps per side, zw unused
    // x = sampling radius (R x multiplier), y = thickness (world units), z = sample power,
    // w = output clamp (1, or AO_WORKING_MAX when a filter follows)
    vec4 params;
};

VCT_END_NAMESPACE
