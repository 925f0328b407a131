// alchemy (McGuire et al., "The Alchemy Screen-Space Ambient Obscurance Algorithm", HPG 2011):
// constants shared by src/ao/alchemy.cpp and shaders/ao/alchemy.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int ALCHEMY_MAX_SAMPLES = 256;
VCT_CONST int ALCHEMY_DEFAULT_SAMPLES = 12;     // the paper's timing figure (12 spp, 720p)
VCT_CONST int ALCHEMY_DEFAULT_TURNS = 7;        // spiral turns (SAO's NUM_SPIRAL_TURNS)
VCT_CONST float ALCHEMY_DEFAULT_SIGMA = 1.0;    // intensity; the paper's images use 1
VCT_CONST float ALCHEMY_DEFAULT_BETA = 1e-4;    // the paper's bias, times linear depth
VCT_CONST float ALCHEMY_DEFAULT_K = 1.0;        // contrast; 1 keeps the estimator linear
VCT_CONST float ALCHEMY_DEFAULT_EPSILON = 1e-4; // the paper's epsilon, here in units of R^2

struct AlchemyUniforms {
    ivec4 config;  // x = samples s, y = spiral turns, zw unused
    // x = 2 sigma R / s (sigma made dimensionless by R), y = beta, z = k, w = epsilon R^2
    vec4 terms;
};

VCT_END_NAMESPACE
