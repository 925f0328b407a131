// Half-resolution AO to full resolution: the four nearest low-resolution pixels, bilinear
// weights times the bilateral depth and normal terms, renormalized; when every neighbour
// lies across an edge, the one nearest in depth. Runs with aoView.size.xy = the low size.
#include "ao/ao_common.glsl"
#include "ao/blur_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform BlurBlock { BlurUniforms blur; };
layout(binding = AO_UNIT_INPUT) uniform sampler2D aoIn;
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

float upsample_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    float d = -p.z;
    float s = blur.terms.x * d;
    float inv2s2 = 1.0 / max(2.0 * s * s, 1e-30);
    // Low-res pixel e stands for G-buffer pixel scale * e (ao_gbufferPixel).
    vec2 low = vec2(g) / float(aoView.noise.y);
    ivec2 base = ivec2(floor(low));
    vec2 f = low - vec2(base);

    float sum = 0.0, weightSum = 0.0, nearestDepthError = 1e38, nearest = 1.0;
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) {
            ivec2 e = base + ivec2(i, j);
            if (any(greaterThanEqual(e, ao_evalSize()))) continue;
            vec3 pe;
            if (!ao_fetchViewPosition(ao_gbufferPixel(e), pe)) continue;
            float a = texelFetch(aoIn, e, 0).r;
            float dd = d - (-pe.z);
            if (abs(dd) < nearestDepthError) { nearestDepthError = abs(dd); nearest = a; }
            float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
            float w = bilinear * exp(-dd * dd * inv2s2) *
                      pow(max(0.0, dot(n, ao_fetchViewNormal(ao_gbufferPixel(e), pe))), blur.terms.y);
            sum += w * a;
            weightSum += w;
        }
    return weightSum > 1e-6 ? sum / weightSum : nearest;
}

void main() {
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(g, ao_fullSize()))) return;
    imageStore(aoOut, g, vec4(ao_sanitize(upsample_evaluate(g))));
}
