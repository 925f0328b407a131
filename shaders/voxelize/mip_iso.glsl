// One isotropic mip level: the mean of the children, for opacity, (HAS_RADIANCE)
// premultiplied radiance and (HAS_NORMAL) the normals (xyz = unit normal, a = 1 where
// occupied, so the mean is coverage-weighted: xyz / a is the occupied voxels' mean normal). Averaging premultiplied values is exact for a box filter, and it
// preserves the grid's mean from level to level on power-of-two grids.
#include "voxelize/voxelize_shared.h"
#include "voxelize/mip_common.glsl"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(r16f, binding = 0) uniform readonly image3D srcOpacity;
layout(r16f, binding = 1) uniform writeonly image3D dstOpacity;
#ifdef HAS_RADIANCE
layout(RADIANCE_FORMAT, binding = 2) uniform readonly image3D srcRadiance;
layout(RADIANCE_FORMAT, binding = 3) uniform writeonly image3D dstRadiance;
#endif
#ifdef HAS_NORMAL
layout(rgba16f, binding = 4) uniform readonly image3D srcNormal;
layout(rgba16f, binding = 5) uniform writeonly image3D dstNormal;
#endif

uniform ivec3 uSrcSize;
uniform ivec3 uDstSize;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uDstSize))) return;
    ivec3 lo, hi;
    mip_childRange(v, uSrcSize, uDstSize, lo, hi);
    float opacity = 0.0;
    vec4 radiance = vec4(0.0);
    vec4 normal = vec4(0.0);
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                opacity += imageLoad(srcOpacity, ivec3(x, y, z)).r;
#ifdef HAS_RADIANCE
                radiance += imageLoad(srcRadiance, ivec3(x, y, z));
#endif
#ifdef HAS_NORMAL
                normal += imageLoad(srcNormal, ivec3(x, y, z));
#endif
            }
    ivec3 n = hi - lo + 1;
    float inv = 1.0 / float(n.x * n.y * n.z);
    imageStore(dstOpacity, v, vec4(opacity * inv));
#ifdef HAS_RADIANCE
    imageStore(dstRadiance, v, radiance * inv);
#endif
#ifdef HAS_NORMAL
    imageStore(dstNormal, v, normal * inv);
#endif
}
