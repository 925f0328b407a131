// Voxel cone traced ambient occlusion: per pixel, the cone set around the shading normal,
// each cone limited to distance R; A = 1 - sum_c w_c alpha_c (CONE_AO_LINEAR), which
// estimates the reference's A_R. Sky pixels read 1. Dense grid, or (CONE_CLIPMAP) clipmap.
#include "cone/cone_common.glsl"
#ifndef CONE_RESOLVE_STAGE  // the resolve program reads no volume
#ifdef CONE_CLIPMAP
#include "cone/clipmap_march.glsl"
#else
#include "cone/cone_march.glsl"
#endif
#endif

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(r32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D cone_aoOut;
layout(r32f, binding = CONE_IMAGE_TRACED) uniform readonly image2D cone_aoTraced;  // resolve stage
// Per pixel: (volume samples, texture fetches) of its cones; zero for sky and resolved pixels.
layout(std430, binding = CONE_BINDING_COUNTS) buffer ConeCounts { vec2 cone_counts[]; };

#ifndef CONE_RESOLVE_STAGE
vec4 cone_passTrace(ivec2 pix, vec3 p, vec3 n, vec3 ng, out vec2 counts) {
    cone_jitterPixel(pix);
    cone_fetches = 0.0;
    uint slot = uint(pix.y) * uint(u.image.x) + uint(pix.x);
    ConeGather g = cone_gather(cone_gatherStart(slot), p, n, ng, u.limits.x, u.limits.z, 0.0);
    cone_gatherCarry(slot, g);
    counts = vec2(g.samples, cone_fetches);
    return vec4(clamp(1.0 - g.occlusion, 0.0, 1.0), 0.0, 0.0, 0.0);
}
#endif
vec4 cone_passFinish(ivec2 pix, vec4 traced) { return traced; }
vec4 cone_passSky() { return vec4(1.0, 0.0, 0.0, 0.0); }
vec4 cone_passTraced(ivec2 cell) { return vec4(imageLoad(cone_aoTraced, cell).r, 0.0, 0.0, 0.0); }
void cone_passStore(ivec2 at, vec4 v) { imageStore(cone_aoOut, at, vec4(v.r, 0.0, 0.0, 0.0)); }

#include "cone/cone_resolve.glsl"
