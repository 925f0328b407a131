// ssao-crytek (Mittring 2007) and ssao-hemisphere (Chapman; LearnOpenGL "SSAO"): constants
// shared by src/ao/ssao.cpp and shaders/ao/ssao.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int SSAO_MAX_SAMPLES = 256;
VCT_CONST int SSAO_NOISE_TILE = 4;        // 4x4 rotation tile, undone by the 4x4 box blur
VCT_CONST int SSAO_KERNEL_SPHERE = 0;     // Crysis: points in the whole ball
VCT_CONST int SSAO_KERNEL_HEMISPHERE = 1; // normal-oriented hemisphere

// LearnOpenGL's tutorial: 64 samples, bias 0.025 at radius 0.5 -> 0.05 R here, so the bias
// scales with the scene (scenes from 1e-4 to 1e5 units).
VCT_CONST int SSAO_DEFAULT_SAMPLES = 64;
VCT_CONST float SSAO_DEFAULT_BIAS = 0.05;  // fraction of R

struct SsaoUniforms {
    // x = kernel kind (SSAO_KERNEL_*), y = sample count, z = range check on (1) / off (0), w unused
    ivec4 config;
    vec4 bias;      // x = depth bias in world units, yzw unused
    // 4x4 tile: hemisphere: xy = random tangent-plane vector (z = 0, LearnOpenGL);
    // sphere: xyz = random unit vector the kernel is reflected about (Crysis).
    vec4 noise[16];
};

VCT_END_NAMESPACE
