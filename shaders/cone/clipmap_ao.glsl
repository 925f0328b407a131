// Clipmap variant of cone_ao.glsl: the same AO estimator over the levels of a clipmap.
#include "cone/clipmap_march.glsl"

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(r32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D clip_aoOut;

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec3 p, n, ng;
    float ao = 1.0;
    if (cone_surface(pix, p, n, ng)) {
        ConeGather g = cone_gather(p, n, ng, u.limits.x, u.limits.z, 0.0);
        ao = clamp(1.0 - g.occlusion, 0.0, 1.0);
    }
    imageStore(clip_aoOut, pix, vec4(ao, 0.0, 0.0, 0.0));
}
