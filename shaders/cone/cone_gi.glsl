// Voxel cone traced indirect diffuse: per pixel, albedo / pi * integral of L_in cos over the
// hemisphere ~= albedo * sum_c w_c L_c (the weights already carry the 1 / pi of the cosine
// lobe), where L_c is the premultiplied radiance a cone gathers front to back plus the sky
// seen through what it left unoccluded. Sky pixels read 0. Dense grid, or (CONE_CLIPMAP)
// clipmap.
#include "cone/cone_common.glsl"
#ifndef CONE_RESOLVE_STAGE  // the resolve program reads no volume
#ifdef CONE_CLIPMAP
#include "cone/clipmap_march.glsl"
#else
#include "cone/cone_march.glsl"
#endif
#endif

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(rgba32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D cone_giOut;
layout(rgba32f, binding = CONE_IMAGE_TRACED) uniform readonly image2D cone_giTraced;  // resolve stage
// Per pixel: (volume samples, texture fetches) of its cones; zero for sky and resolved pixels.
layout(std430, binding = CONE_BINDING_COUNTS) buffer ConeCounts { vec2 cone_counts[]; };

// The traced value is the light the cones gather (sum_c w_c L_c); the pixel's own albedo
// multiplies it when it is finished, so a resolved pixel keeps its texture.
#ifndef CONE_RESOLVE_STAGE
vec4 cone_passTrace(ivec2 pix, vec3 p, vec3 n, vec3 ng, out vec2 counts) {
    cone_jitterPixel(pix);
    cone_fetches = 0.0;
    uint slot = uint(pix.y) * uint(u.image.x) + uint(pix.x);
    ConeGather g = cone_gather(cone_gatherStart(slot), p, n, ng, u.limits.x, 0.0, u.limits.y);
    cone_gatherCarry(slot, g);
    counts = vec2(g.samples, cone_fetches);
    return vec4(g.radiance, 1.0);
}
#endif
vec4 cone_passFinish(ivec2 pix, vec4 traced) {
    vec3 albedo = max(texelFetch(gbufAlbedo, pix, 0).rgb, vec3(0.0));
    return vec4(albedo * traced.rgb, 1.0);
}
vec4 cone_passSky() { return vec4(0.0); }
vec4 cone_passTraced(ivec2 cell) { return imageLoad(cone_giTraced, cell); }
void cone_passStore(ivec2 at, vec4 v) { imageStore(cone_giOut, at, v); }

#include "cone/cone_resolve.glsl"
