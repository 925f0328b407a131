// alchemy: s taps on a spiral in the disc of world radius R projected to the screen, rotated
// per pixel; A = max(0, 1 - (2 sigma / s) sum max(0, v.n - beta d) / (v.v + eps))^k, taps
// farther than R from p ignored.
#include "ao/ao_common.glsl"
#include "ao/alchemy_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform AlchemyBlock { AlchemyUniforms alchemy; };
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

float alchemy_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    float dP = -p.z;
    float radiusPx = aoView.radius.x * ao_pixelsPerUnit(dP);
    float rotation = 2.0 * AO_PI * ao_pixelNoise(g, 1u).x;
    int s = alchemy.config.x;
    float sum = 0.0;
    for (int i = 0; i < s; ++i) {
        float alpha = (float(i) + 0.5) / float(s);
        float angle = alpha * float(alchemy.config.y) * 2.0 * AO_PI + rotation;
        ivec2 q = ivec2(floor(vec2(g) + 0.5 + alpha * radiusPx * vec2(cos(angle), sin(angle))));
        if (q == g || !ao_onScreen(q)) continue;
        vec3 tap;
        if (!ao_fetchViewPosition(q, tap)) continue;
        vec3 v = tap - p;
        float vv = dot(v, v);
        if (vv > aoView.radius.y) continue;
        sum += max(0.0, dot(v, n) - alchemy.terms.y * dP) / (vv + alchemy.terms.w);
    }
    return pow(max(0.0, 1.0 - alchemy.terms.x * sum), alchemy.terms.z);
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(alchemy_evaluate(ao_gbufferPixel(e)))));
}
