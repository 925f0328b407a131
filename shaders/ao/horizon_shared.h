// ssao-horizon (tinyrenderer's height-field AO): constants shared by src/ao/horizon_ao.cpp
// and shaders/ao/horizon.glsl.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int HORIZON_DEFAULT_DIRECTIONS = 8;  // the lesson's 8 directions
// The lesson walks every pixel; 16 steps over the projected radius is the same at the
// radii where the lesson's images were made (~16 px) and bounded elsewhere.
VCT_CONST int HORIZON_DEFAULT_STEPS = 16;

struct HorizonUniforms {
    ivec4 config;  // x = directions, y = steps per direction, zw unused
};

VCT_END_NAMESPACE
