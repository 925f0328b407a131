// LearnOpenGL's SSAO blur: the mean over the 4x4 block of offsets -2..1, which exactly
// averages out the 4x4 rotation tile. Taps off screen or on sky are left out of the mean.
#include "ao/ao_common.glsl"
#include "ao/blur_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(binding = AO_UNIT_INPUT) uniform sampler2D aoIn;
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

float box_evaluate(ivec2 e) {
    if (ao_isSky(texelFetch(aoGPosition, ao_gbufferPixel(e), 0))) return 1.0;
    float sum = 0.0;
    int count = 0;
    for (int y = -BLUR_BOX_SIZE / 2; y < BLUR_BOX_SIZE / 2; ++y)
        for (int x = -BLUR_BOX_SIZE / 2; x < BLUR_BOX_SIZE / 2; ++x) {
            ivec2 ei = e + ivec2(x, y);
            if (any(lessThan(ei, ivec2(0))) || any(greaterThanEqual(ei, ao_evalSize()))) continue;
            if (ao_isSky(texelFetch(aoGPosition, ao_gbufferPixel(ei), 0))) continue;
            sum += texelFetch(aoIn, ei, 0).r;
            ++count;
        }
    return count > 0 ? sum / float(count) : 1.0;
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(box_evaluate(e))));
}
