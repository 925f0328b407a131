// Clipmap variant of cone_gi.glsl: the same indirect diffuse estimator over a clipmap.
#include "cone/clipmap_march.glsl"

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(rgba32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D clip_giOut;

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec3 p, n, ng;
    vec4 result = vec4(0.0);
    if (cone_surface(pix, p, n, ng)) {
        vec3 albedo = max(texelFetch(gbufAlbedo, pix, 0).rgb, vec3(0.0));
        ConeGather g = cone_gather(p, n, ng, u.limits.x, 0.0, u.limits.y);
        result = vec4(albedo * g.radiance, 1.0);
    }
    imageStore(clip_giOut, pix, result);
}
