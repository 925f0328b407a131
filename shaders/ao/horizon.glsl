// ssao-horizon: the depth buffer read as a height field above the image plane. Along each of
// N directions march over the disc of projected radius R, keep the largest elevation angle
// of (sample - p) above the view plane among samples within R of p, and average
// (pi/2 - elevation) / (pi/2). No noise: the directions are the same at every pixel.
#include "ao/ao_common.glsl"
#include "ao/horizon_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform HorizonBlock { HorizonUniforms horizon; };
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

float horizon_maxElevation(ivec2 g, vec3 p, vec2 dir, float radiusPx) {
    float R2 = aoView.radius.y;
    float elevation = 0.0;  // never below the view plane, as in the lesson
    int steps = horizon.config.y;
    for (int j = 1; j <= steps; ++j) {
        ivec2 q = ivec2(floor(vec2(g) + 0.5 + dir * (radiusPx * float(j) / float(steps))));
        if (q == g) continue;
        if (!ao_onScreen(q)) break;
        vec3 s;
        if (!ao_fetchViewPosition(q, s)) continue;
        vec3 v = s - p;
        if (dot(v, v) > R2) continue;  // binary visibility within R
        elevation = max(elevation, atan(v.z, length(v.xy)));
    }
    return elevation;
}

float horizon_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    float radiusPx = aoView.radius.x * ao_pixelsPerUnit(-p.z);
    int directions = horizon.config.x;
    float sum = 0.0;
    for (int i = 0; i < directions; ++i) {
        float phi = 2.0 * AO_PI * float(i) / float(directions);
        sum += (AO_HALF_PI - horizon_maxElevation(g, p, vec2(cos(phi), sin(phi)), radiusPx)) / AO_HALF_PI;
    }
    return sum / float(directions);
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(horizon_evaluate(ao_gbufferPixel(e)))));
}
