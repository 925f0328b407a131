// The voxelizer's coverage pass (vct.voxel.edges=coverage): the fixed-point area each
// voxel's column holds of the triangles crossing it, and the bits of their dominant axes,
// at image units 0 and 1 (accumulators VOX_ACC_COVERAGE and VOX_ACC_AXES); resolve.glsl
// turns them into level 0's opacity (vox_edgeOpacity). The algorithm and the other passes:
// voxelize_pass.glsl.
#define COVERAGE_PASS 1
#include "common/scene.glsl"
#include "voxelize/voxelize_shared.h"

layout(r32ui, binding = 0) uniform coherent uimage3D accCoverage;
layout(r32ui, binding = 1) uniform coherent uimage3D accAxes;
#ifdef EDGE_SHEETS
// vct.voxel.edges=sheet: the span's two maxima (vox_sheetSpanFixed) and the extent bits
// (vox_extentBits), accumulators VOX_ACC_SHEET_LO, VOX_ACC_SHEET_HI and VOX_ACC_SHEET_EXTENT.
layout(r32ui, binding = 2) uniform coherent uimage3D accSheetLo;
layout(r32ui, binding = 3) uniform coherent uimage3D accSheetHi;
layout(r32ui, binding = 4) uniform coherent uimage3D accSheetExtent;
#endif

#include "voxelize/voxelize_pass.glsl"
