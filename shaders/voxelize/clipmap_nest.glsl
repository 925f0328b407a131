// Clipmap nesting (src/clipmap): level l's mip 1 replaces level l + 1's base voxels where the
// two overlap, so a cone that moves from the fine level to the coarse one sees the same data
// at the same voxel size (no jump in opacity or radiance at the switch, whatever the count of
// levels). Used for opacity (r16f) and radiance.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(binding = 0) uniform sampler3D uFine;  // level l, read at mip 1
layout(DST_FORMAT, binding = 0) uniform writeonly image3D uCoarse;  // level l + 1, mip 0

uniform ivec3 uFineSize;  // size of level l's mip 1
uniform ivec3 uOffset;    // level l's mip-1 voxel 0 in level l + 1's voxels

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uFineSize))) return;
    imageStore(uCoarse, v + uOffset, texelFetch(uFine, v, 1));
}
