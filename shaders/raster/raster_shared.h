// Constants shared by the raster passes' C++ dispatch code and their compute shaders.
#pragma once
#include "common/shared_types.h"
VCT_BEGIN_NAMESPACE
VCT_CONST int RASTER_GROUP_SIZE = 8;  // 8x8 invocations: a common sweet spot on GPUs and llvmpipe alike
VCT_CONST int SHADOW_UNIT_MAPS = 10;   // sampler2DArrayShadow of directional and spot lights
VCT_CONST int SHADOW_UNIT_CUBES = 11;  // samplerCubeArray of point lights (distance to light)
// Default shadow map size (texels per side): 1024 resolves the Cornell box's box shadows
// cleanly at 256^2 images while rendering Sponza's shadow in tens of ms on llvmpipe.
VCT_CONST int SHADOW_DEFAULT_SIZE = 1024;
VCT_END_NAMESPACE
