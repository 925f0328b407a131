// Voxel cone traced indirect diffuse: per pixel, albedo / pi * integral of L_in cos over the
// hemisphere ~= albedo * sum_c w_c L_c (the weights already carry the 1 / pi of the cosine
// lobe), where L_c is the premultiplied radiance a cone gathers front to back plus the sky
// seen through what it left unoccluded. Sky pixels read 0. Dense grid, or (CONE_CLIPMAP)
// clipmap.
#include "cone/cone_common.glsl"
#ifdef CONE_CLIPMAP
#include "cone/clipmap_march.glsl"
#else
#include "cone/cone_march.glsl"
#endif

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(rgba32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D cone_giOut;
// Per pixel: (volume samples, texture fetches) of its cones; zero for sky.
layout(std430, binding = CONE_BINDING_COUNTS) writeonly buffer ConeCounts { vec2 cone_counts[]; };

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec3 p, n, ng;
    vec4 result = vec4(0.0);
    vec2 counts = vec2(0.0);
    if (cone_surface(pix, p, n, ng)) {
        cone_jitterPixel(pix);
        vec3 albedo = max(texelFetch(gbufAlbedo, pix, 0).rgb, vec3(0.0));
        ConeGather g = cone_gather(p, n, ng, u.limits.x, 0.0, u.limits.y);
        result = vec4(albedo * g.radiance, 1.0);
        counts = vec2(g.samples, cone_fetches);
    }
    cone_counts[pix.y * u.image.x + pix.x] = counts;
    imageStore(cone_giOut, pix, result);
}
