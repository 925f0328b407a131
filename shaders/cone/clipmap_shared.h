// Constants and the uniform block of clipmap cone tracing (src/clipmap), shared by C++ and
// GLSL. A clipmap is a stack of nested cubic grids of one resolution, level l of voxel size
// 2^l times level 0's, each centred near the camera; cones work in level-0 voxel units.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int CLIPMAP_MAX_LEVELS = 8;
VCT_CONST int CLIPMAP_UBO_BINDING = 1;   // next to ConeUniforms (CONE_UBO_BINDING = 0)
VCT_CONST int CLIPMAP_UNIT_LEVEL0 = 10;  // levels at texture units 10..17 (isotropic only)

// Level borders, in voxels of the level: a sample whose footprint reaches mip 1 of a level
// (2 voxels of trilinear support) plus half a step of drift stays CLIPMAP_BORDER_MARGIN
// voxels inside the level's box; over the next CLIPMAP_BLEND_WIDTH voxels further in, the
// level of detail rises continuously to the next level, so no seam shows at the border.
VCT_CONST float CLIPMAP_BORDER_MARGIN = 3.0;
VCT_CONST float CLIPMAP_BLEND_WIDTH = 2.0;

struct ClipmapUniforms {
    // Level l's voxel coordinates from level 0's: x_l = x_0 * w + xyz (w = 2^-l).
    vec4 levelFromLevel0[CLIPMAP_MAX_LEVELS];
    vec4 info;  // x = level count, y = resolution (voxels per axis), z = mip levels per level, w unused
    vec4 band;  // x = border margin, y = blend width (voxels of the level), zw unused
};

VCT_END_NAMESPACE
