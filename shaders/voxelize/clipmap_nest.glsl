// Clipmap nesting (src/clipmap): each voxel of level l + 1 that eight voxels of level l fill
// takes their mean, so a cone that moves from the fine level to the coarse one sees the same
// data at the same voxel size (no jump in opacity or radiance at the switch, whatever the count
// of levels). The mean is mip_iso.glsl's (the same children, summed in the same order), so
// where level l's origin is even it is level l's mip 1 bit for bit; the levels share one
// lattice, so an odd origin pairs other children and the mean is as exact. Used for opacity
// (r16f) and radiance.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(binding = 0) uniform sampler3D uFine;  // level l, base
layout(DST_FORMAT, binding = 0) uniform writeonly image3D uCoarse;  // level l + 1, base

uniform ivec3 uCount;        // the coarse voxels filled by fine ones, per axis
uniform ivec3 uCoarseFirst;  // the first of them, in level l + 1's voxels
uniform ivec3 uFineFirst;    // its first child, in level l's voxels

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uCount))) return;
    ivec3 lo = uFineFirst + 2 * v;
    vec4 sum = vec4(0.0);
    for (int z = lo.z; z <= lo.z + 1; ++z)
        for (int y = lo.y; y <= lo.y + 1; ++y)
            for (int x = lo.x; x <= lo.x + 1; ++x) sum += texelFetch(uFine, ivec3(x, y, z), 0);
    imageStore(uCoarse, uCoarseFirst + v, sum * (1.0 / 8.0));
}
