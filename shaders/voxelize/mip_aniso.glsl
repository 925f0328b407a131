// One level of the directional (anisotropic) textures (Crassin 2011): for a cone travelling
// along +axis (uSign = 1) or -axis (uSign = -1), the children of each line along the axis
// are composited front to back (premultiplied: c = c_front + (1 - a_front) c_back), and the
// lines across the axis are averaged. With optical-depth levels (opacity_depth.h) the
// composite runs on opacity as before; only what is read from a directional level and what
// is stored is converted.
//
// A lit grid has one RGBA texture per direction (uAxis, uSign). An AO grid has opacity alone,
// which is the same both ways along an axis (1 - prod(1 - alpha_k) in either order), and packs
// the three axes into one texture (DEST_PACKED: r, g, b = X, Y, Z, composited along +axis), so
// a cone reads its three directions in one fetch instead of three; one invocation writes all
// three.
// Sources: the base opacity (SOURCE_OPACITY, R16F), a packed level (SOURCE_PACKED: the
// axis's channel), or a directional RGBA level.
#include "voxelize/voxelize_shared.h"
#include "voxelize/opacity_depth.h"
#include "voxelize/mip_common.glsl"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(SRC_FORMAT, binding = 0) uniform readonly image3D src;  // radiance, opacity or aniso
layout(DST_FORMAT, binding = 1) uniform writeonly image3D dst;

uniform ivec3 uSrcSize;
uniform ivec3 uDstSize;
uniform int uAxis;  // 0, 1, 2 (DEST_PACKED: unused, every axis)
uniform int uSign;  // +1 or -1: direction of travel
uniform int uDepthIn;   // 1: the source is a directional level holding optical depth
uniform int uDepthOut;  // 1: store optical depth (vox_depthFromAlpha)

// The source texel, as (premultiplied radiance, alpha) for a cone along `axis`.
vec4 mip_source(ivec3 p, int axis) {
#if defined(SOURCE_OPACITY)
    vec4 s = vec4(0.0, 0.0, 0.0, imageLoad(src, p).r);
#elif defined(SOURCE_PACKED)
    vec4 s = vec4(0.0, 0.0, 0.0, imageLoad(src, p)[axis]);
#else
    vec4 s = imageLoad(src, p);
#endif
    if (uDepthIn != 0) s = vox_alphaFromDepth(s);
    return s;
}

// Texel v of the level for a cone along `sign` * `axis`: its children [lo, hi].
vec4 mip_directional(ivec3 lo, ivec3 hi, int axis, int sign) {
    int a = axis, b = (axis + 1) % 3, c = (axis + 2) % 3;
    vec4 sum = vec4(0.0);
    for (int j = lo[c]; j <= hi[c]; ++j)
        for (int i = lo[b]; i <= hi[b]; ++i) {
            vec4 acc = vec4(0.0);
            int count = hi[a] - lo[a] + 1;
            for (int k = 0; k < count; ++k) {
                ivec3 p;
                p[a] = sign > 0 ? lo[a] + k : hi[a] - k;
                p[b] = i;
                p[c] = j;
                acc += (1.0 - acc.a) * mip_source(p, axis);
            }
            sum += acc;
        }
    float lines = float((hi[b] - lo[b] + 1) * (hi[c] - lo[c] + 1));
    vec4 mean = sum / lines;
    if (uDepthOut != 0) mean = vox_depthFromAlpha(mean);
    return mean;
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uDstSize))) return;
    ivec3 lo, hi;
    mip_childRange(v, uSrcSize, uDstSize, lo, hi);
#ifdef DEST_PACKED
    vec4 axes = vec4(0.0);
    for (int axis = 0; axis < 3; ++axis) axes[axis] = mip_directional(lo, hi, axis, uSign).a;
    imageStore(dst, v, axes);
#else
    imageStore(dst, v, mip_directional(lo, hi, uAxis, uSign));
#endif
}
