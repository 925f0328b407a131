// The voxelizer's emission pass: three 64-bit emission sums as (lo, hi) r32ui pairs, 6 of the
// 8 image units GL 4.5 guarantees; accumulator k at unit k - VOX_ACC_EMISSION. The algorithm
// and both passes: voxelize_pass.glsl.
#define EMISSION_PASS 1
#include "common/scene.glsl"
#include "voxelize/voxelize_shared.h"

layout(r32ui, binding = 0) uniform coherent uimage3D accEmissionRLo;
layout(r32ui, binding = 1) uniform coherent uimage3D accEmissionRHi;
layout(r32ui, binding = 2) uniform coherent uimage3D accEmissionGLo;
layout(r32ui, binding = 3) uniform coherent uimage3D accEmissionGHi;
layout(r32ui, binding = 4) uniform coherent uimage3D accEmissionBLo;
layout(r32ui, binding = 5) uniform coherent uimage3D accEmissionBHi;

#include "voxelize/voxelize_pass.glsl"
