// The filters every screen-space AO method can use: the depth- and normal-aware bilateral
// blur (separable), LearnOpenGL's 4x4 box blur, and the depth-aware upsample from half
// resolution. Shared by src/ao/ao_filters.cpp and the shaders/ao/*_blur.glsl passes.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int BLUR_MAX_RADIUS = 16;  // taps each side; the weights fill vec4 weights[5]
// 4 px each side with sigma 2 px spans the 4x4 noise tile of the ssao methods twice and
// XeGTAO-like per-pixel noise well enough; larger radii smear contact shadows.
VCT_CONST int BLUR_DEFAULT_RADIUS = 4;
VCT_CONST float BLUR_DEFAULT_SIGMA = 2.0;          // pixels
// Depth term exp(-(d - d_i)^2 / (2 s^2)) with s relative to the centre depth: 2 % keeps
// steep floors (depth changing ~1 % per pixel at grazing angles) blurring, stops at steps.
VCT_CONST float BLUR_DEFAULT_DEPTH_SIGMA = 0.02;
VCT_CONST float BLUR_DEFAULT_NORMAL_POWER = 8.0;   // max(0, n.n_i)^8 halves at 23 degrees
VCT_CONST int BLUR_BOX_SIZE = 4;                   // LearnOpenGL: offsets -2..1 in x and y

struct BlurUniforms {
    // x = radius in taps, y = axis (0 = x, 1 = y), z = is half-resolution (1) / not (0), w unused
    ivec4 config;
    // x = depth sigma (fraction of depth), y = normal power, z = output clamp (1 for a chain's
    // last pass, else AO_WORKING_MAX), w unused
    vec4 terms;
    vec4 weights[5];   // w_0 .. w_16 of the normalized 1D Gaussian: w_0 + 2 sum_{i>0} w_i = 1
};

VCT_END_NAMESPACE
