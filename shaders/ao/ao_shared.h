// Constants and the per-view uniform block shared by every screen-space AO pass (C++ and
// GLSL). Each technique adds its own block in <technique>_shared.h.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

// Compute work-group size of every AO pass; the C++ dispatch divides by the same numbers.
VCT_CONST int AO_LOCAL_SIZE_X = 8;
VCT_CONST int AO_LOCAL_SIZE_Y = 8;

// Uniform-block binding points (std140).
VCT_CONST int AO_BINDING_VIEW = 0;       // AoViewUniforms
VCT_CONST int AO_BINDING_TECHNIQUE = 1;  // the technique's own block
// Shader-storage binding of sample kernels (std430 vec4[]).
VCT_CONST int AO_BINDING_KERNEL = 2;

// Texture units: the G-buffer's own (must equal vct::GBufferUnit, checked in C++), plus the
// AO input of the blur and upsample passes. Image unit 0 is every pass's R32F output.
VCT_CONST int AO_UNIT_POSITION = 0;
VCT_CONST int AO_UNIT_NORMAL = 1;
VCT_CONST int AO_UNIT_ALBEDO = 3;
VCT_CONST int AO_UNIT_INPUT = 6;
VCT_CONST int AO_IMAGE_OUTPUT = 0;

// Values above 1 may travel between passes (gtao's final power lifts visibility above 1 in
// some slices, and XeGTAO keeps up to 1.5 through its denoiser so that the average of a
// noisy pixel stays unbiased); the last pass of every chain clamps to [0, 1].
VCT_CONST float AO_WORKING_MAX = 1.5;

struct AoViewUniforms {
    mat4 viewFromWorld;
    // Full-resolution pinhole projection in pixels: pixel = xy * view.xy / (-view.z) + zw.
    // x, y = focal lengths in pixels (0.5 * size * clipFromView[i][i]); z, w = principal point.
    vec4 pixelFromView;
    ivec4 size;     // x, y = evaluation size; z, w = G-buffer (full) size
    vec4 radius;    // x = R (world units), y = R^2, zw unused
    uvec4 noise;    // x = per-run seed hash for pixel noise; y = G-buffer pixels per evaluation pixel
};

VCT_END_NAMESPACE
