// Voxel cone traced ambient occlusion: per pixel, the cone set around the shading normal,
// each cone limited to distance R; A = 1 - sum_c w_c alpha_c (CONE_AO_LINEAR), which
// estimates the reference's A_R. Sky pixels read 1. Dense grid, or (CONE_CLIPMAP) clipmap.
#include "cone/cone_common.glsl"
#ifdef CONE_CLIPMAP
#include "cone/clipmap_march.glsl"
#else
#include "cone/cone_march.glsl"
#endif

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(r32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D cone_aoOut;
// Per pixel: (volume samples, texture fetches) of its cones; zero for sky.
layout(std430, binding = CONE_BINDING_COUNTS) writeonly buffer ConeCounts { vec2 cone_counts[]; };

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec3 p, n, ng;
    float ao = 1.0;
    vec2 counts = vec2(0.0);
    if (cone_surface(pix, p, n, ng)) {
        cone_jitterPixel(pix);
        ConeGather g = cone_gather(p, n, ng, u.limits.x, u.limits.z, 0.0);
        ao = clamp(1.0 - g.occlusion, 0.0, 1.0);
        counts = vec2(g.samples, cone_fetches);
    }
    cone_counts[pix.y * u.image.x + pix.x] = counts;
    imageStore(cone_aoOut, pix, vec4(ao, 0.0, 0.0, 0.0));
}
