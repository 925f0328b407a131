// The cone passes (cone/cone_ao.glsl, cone/cone_gi.glsl) with every 3D-texture fetch counted:
// cone/cone_march.glsl is included unchanged, with `textureLod` renamed to a wrapper that
// increments a per-invocation counter, so the count follows the real march (its footprint
// schedule, plane limit, grid exit and alpha saturation) exactly. G-buffer reads are
// texelFetch and are not counted. Writes the pass's own output too, so the benchmark can
// check that this copy reproduces the real pass bit for bit.
//
// One dispatch over the whole cone set (its uniforms split nothing: cone_gatherStart starts at
// zero): the benchmark's sets stay within one dispatch's loop budget (CONE_LOOP_BUDGET).
//
// Defines: CONE_GI, CONE_ANISO (as the cone passes).
uint bench_fetches = 0u;

vec4 bench_countedLod(sampler3D s, vec3 tc, float lod) {
    bench_fetches += 1u;
    return textureLod(s, tc, lod);
}

#define textureLod bench_countedLod
#include "cone/cone_march.glsl"
#undef textureLod

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(rgba32f, binding = 0) uniform writeonly image2D bench_valueOut;  // AO in r, or GI rgba
layout(r32ui, binding = 1) uniform writeonly uimage2D bench_countOut;   // fetches per pixel

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec3 p, n, ng;
#if CONE_GI
    vec4 result = vec4(0.0);
    if (cone_surface(pix, p, n, ng)) {
        vec3 albedo = max(texelFetch(gbufAlbedo, pix, 0).rgb, vec3(0.0));
        ConeGather g = cone_gather(cone_gatherStart(0u), p, n, ng, u.limits.x, 0.0, u.limits.y);
        result = vec4(albedo * g.radiance, 1.0);
    }
#else
    float ao = 1.0;
    if (cone_surface(pix, p, n, ng)) {
        ConeGather g = cone_gather(cone_gatherStart(0u), p, n, ng, u.limits.x, u.limits.z, 0.0);
        ao = clamp(1.0 - g.occlusion, 0.0, 1.0);
    }
    vec4 result = vec4(ao, 0.0, 0.0, 0.0);
#endif
    imageStore(bench_valueOut, pix, result);
    imageStore(bench_countOut, pix, uvec4(bench_fetches, 0u, 0u, 0u));
}
