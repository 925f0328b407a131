// vct.voxel.edges=sheet: level 0's sheet texels (vox_sheetTexel: opacity, the span of the
// voxel's sheets along their one dominant axis, that axis; -1 where it has none), from the
// resolved opacity and the coverage pass's axis bits and span maxima, which it reads through
// texture units (texelFetch). The march reads them in cone_sampleSheets
// (cone/cone_march_shared.h); the sparse voxelizer builds the same texels on the CPU.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(binding = VOX_ACC_AXES) uniform usampler3D accAxes;
layout(binding = VOX_ACC_SHEET_LO) uniform usampler3D accSheetLo;
layout(binding = VOX_ACC_SHEET_HI) uniform usampler3D accSheetHi;
layout(binding = VOX_UNIT_SHEETS_OPACITY) uniform sampler3D opacity;

layout(rgba16f, binding = VOX_IMAGE_SHEETS) uniform writeonly image3D outSheets;

uniform ivec3 uResolution;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uResolution))) return;
    imageStore(outSheets, v,
               vox_sheetTexel(texelFetch(opacity, v, 0).r, texelFetch(accAxes, v, 0).r,
                              texelFetch(accSheetLo, v, 0).r, texelFetch(accSheetHi, v, 0).r));
}
