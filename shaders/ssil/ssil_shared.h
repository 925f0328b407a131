// ssil: screen-space indirect lighting with visibility bitmasks (Therrien, Levesque and Gilet
// 2023): constants shared by src/ssil/ssil.cpp and shaders/ssil/ssil.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int SSIL_MAX_SLICES = 64;
VCT_CONST int SSIL_MAX_STEPS = 64;

// Defaults, the same for every scene (tests/gpu/ssil_test.cpp prints the Cornell box's
// error against the path tracer):
// - 4 slices of 12 steps per side: light comes from anywhere on screen, not only from within
//   an AO radius, so slices reach across the whole image and need more steps than VBAO's;
// - the sampling extent is the image's longer side, so a pixel at one edge still gathers from
//   a wall at the other (a screen-space method sees nothing beyond the image anyway);
// - steps spread uniformly (power 1): every distance along the slice may hold a light;
// - a thickness of 0.2 x the view depth: about the depth of furniture-sized objects seen
//   from a few metres (the Cornell box's blocks are 0.15-0.2 of the camera distance deep).
//   Relative to depth because a GI method has no radius to scale by, and a screen-space
//   method sees the same image at any scene scale.
VCT_CONST int SSIL_DEFAULT_SLICES = 4;
VCT_CONST int SSIL_DEFAULT_STEPS = 12;
VCT_CONST float SSIL_DEFAULT_EXTENT = 1.0;     // x the image's longer side, pixels
VCT_CONST float SSIL_DEFAULT_SAMPLE_POWER = 1.0;
VCT_CONST float SSIL_DEFAULT_THICKNESS = 0.2;  // x the centre's view depth
VCT_CONST float SSIL_MAX_THICKNESS = 10000.0;
VCT_CONST float SSIL_MIN_STEP_PIXELS = 1.3;   // as GTAO and VBAO

// Texture units beyond the G-buffer's (position 0, normal 1, albedo 3, emission 4).
VCT_CONST int SSIL_UNIT_EMISSION = 4;
VCT_CONST int SSIL_UNIT_DIRECT = 7;
VCT_CONST int SSIL_IMAGE_OUTPUT = 0;

struct SsilUniforms {
    ivec4 config;  // x = slices, y = steps per side, z = direct light bound (1) or none (0), w unused
    // x = sampling extent (pixels), y = thickness (fraction of view depth), z = sample power,
    // w = sky radiance
    vec4 params;
};

VCT_END_NAMESPACE
