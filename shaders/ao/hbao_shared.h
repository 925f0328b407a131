// hbao (Bavoil and Sainz 2008; NVIDIA gl_ssao): constants shared by src/ao/hbao.cpp and
// shaders/ao/hbao.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

// gl_ssao's timing configuration (8 directions x 4 steps).
VCT_CONST int HBAO_DEFAULT_DIRECTIONS = 8;
VCT_CONST int HBAO_DEFAULT_STEPS = 4;
// Added to the tangent angle to hide tessellation creases; the tangent here is exact for a
// plane (see hbao.glsl), so a small bias suffices (the 2008 SDK's 30 degrees darkens less
// but also drops real occlusion at shallow angles).
VCT_CONST float HBAO_DEFAULT_ANGLE_BIAS = 0.1;  // radians

struct HbaoUniforms {
    ivec4 config;  // x = directions, y = steps per direction, zw unused
    vec4 angles;   // x = angle bias (radians), yzw unused
};

VCT_END_NAMESPACE
