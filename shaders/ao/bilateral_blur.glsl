// One axis of the separable bilateral blur. Tap weight = Gaussian w_|i| x max(0, n.n_i)^p x
// exp(-(d - d_i)^2 / (2 s^2)); the result is divided by the sum of the weights actually used,
// so taps dropped at the border, on sky or across edges never darken or brighten the result.
#include "ao/ao_common.glsl"
#include "ao/blur_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform BlurBlock { BlurUniforms blur; };
layout(binding = AO_UNIT_INPUT) uniform sampler2D aoIn;
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

float blur_gaussian(int i) { return blur.weights[i / 4][i % 4]; }

float blur_evaluate(ivec2 e) {
    ivec2 g = ao_gbufferPixel(e);
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    float d = -p.z;
    float s = blur.terms.x * d;
    float inv2s2 = 1.0 / max(2.0 * s * s, 1e-30);
    ivec2 axis = blur.config.y == 0 ? ivec2(1, 0) : ivec2(0, 1);

    float sum = 0.0, weightSum = 0.0;
    for (int i = -blur.config.x; i <= blur.config.x; ++i) {
        ivec2 ei = e + i * axis;
        if (any(lessThan(ei, ivec2(0))) || any(greaterThanEqual(ei, ao_evalSize()))) continue;
        ivec2 gi = ao_gbufferPixel(ei);
        vec3 pi;
        if (!ao_fetchViewPosition(gi, pi)) continue;
        float dd = d - (-pi.z);
        float w = blur_gaussian(abs(i)) * exp(-dd * dd * inv2s2);
        if (i != 0) w *= pow(max(0.0, dot(n, ao_fetchViewNormal(gi, pi))), blur.terms.y);
        sum += w * texelFetch(aoIn, ei, 0).r;
        weightSum += w;
    }
    return weightSum > 0.0 ? sum / weightSum : texelFetch(aoIn, e, 0).r;
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(blur_evaluate(e), blur.terms.z)));
}
