// The voxelizer's geometry pass: the albedo, normal and weight accumulators, and (TWO_SIDED:
// the scene has a doubleSided material) the weight of doubleSided materials: 7 or 8 of the 8
// image units GL 4.5 guarantees; OPACITY_ONLY (a grid for AO, which reads opacity alone): the
// weight accumulator only. The algorithm and both passes: voxelize_pass.glsl.
#include "common/scene.glsl"
#include "voxelize/voxelize_shared.h"

#ifndef OPACITY_ONLY
layout(r32ui, binding = VOX_ACC_ALBEDO + 0) uniform coherent uimage3D accAlbedoR;
layout(r32ui, binding = VOX_ACC_ALBEDO + 1) uniform coherent uimage3D accAlbedoG;
layout(r32ui, binding = VOX_ACC_ALBEDO + 2) uniform coherent uimage3D accAlbedoB;
layout(r32ui, binding = VOX_ACC_NORMAL + 0) uniform coherent uimage3D accNormalX;
layout(r32ui, binding = VOX_ACC_NORMAL + 1) uniform coherent uimage3D accNormalY;
layout(r32ui, binding = VOX_ACC_NORMAL + 2) uniform coherent uimage3D accNormalZ;
#endif
layout(r32ui, binding = VOX_ACC_WEIGHT) uniform coherent uimage3D accWeight;
#ifdef TWO_SIDED
layout(r32ui, binding = VOX_ACC_TWO_SIDED) uniform coherent uimage3D accTwoSided;
#endif

#include "voxelize/voxelize_pass.glsl"
