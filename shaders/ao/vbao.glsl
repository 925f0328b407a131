// vbao: visibility-bitmask AO (Therrien, Levesque and Gilet 2023). GTAO's slices and steps
// (shaders/ao/gtao.glsl: the same slice angles, step positions and noise), but instead of
// one horizon per side each slice keeps a 32-bit mask of occluded sectors
// (ao/visibility_bitmask.h): a sample within the sampling radius occludes the sectors between
// its front and its back, the front pushed away from the eye by the assumed thickness. The
// result is the cosine-weighted measure of the clear sectors. Unlike GTAO there is no soft
// falloff and no output power: a sample counts when it lies within the radius (the
// reference's binary V_R), and the measure is already the reference's integral.
#include "ao/ao_common.glsl"
#include "ao/vbao_shared.h"
#include "ao/visibility_bitmask.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform VbaoBlock { VbaoUniforms vbao; };
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

// The sectors one sample at pixel offset `offset` occludes; `side` is +1 along the slice's
// screen direction (positive angles), -1 against it.
uint vbao_sampleSectors(ivec2 g, ivec2 offset, vec3 p, vec3 viewVec, float angleN, float side) {
    ivec2 q = g + offset;
    vec3 s;
    if (offset == ivec2(0) || !ao_onScreen(q) || !ao_fetchViewPosition(q, s)) return 0u;
    vec3 delta = s - p;
    float dist = length(delta);
    if (!(dist > 0.0) || dist > vbao.params.x) return 0u;
    // The back, s - viewVec * thickness, scaled by 1 / max(dist, thickness) so that a
    // thickness of 1e4 R stays finite when squared at every scene scale.
    float scale = 1.0 / max(dist, vbao.params.y);
    vec3 back = delta * scale - viewVec * (vbao.params.y * scale);
    float hFront = acos(clamp(dot(delta, viewVec) / dist, -1.0, 1.0));
    float hBack = acos(clamp(dot(back, viewVec) / max(length(back), 1e-30), -1.0, 1.0));
    return side > 0.0 ? vbm_occludedBits(hFront, hBack, angleN) : vbm_occludedBits(-hBack, -hFront, angleN);
}

float vbao_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    p *= 0.99999;  // as GTAO: the pixel's own plane never occludes it
    vec3 viewVec = normalize(-p);

    float screenRadius = vbao.params.x * ao_pixelsPerUnit(-p.z);
    float minS = VBAO_MIN_STEP_PIXELS / max(screenRadius, 1e-30);
    vec2 noise = ao_pixelNoise(g, 3u);  // GTAO's salt: the same slices and steps as gtao
    int slices = vbao.config.x, steps = vbao.config.y;

    float visibility = 0.0;
    for (int slice = 0; slice < slices; ++slice) {
        // The slice and its projected normal, as GTAO (Jimenez et al. 2016, Algorithm 1, lines 5-15).
        float phi = (float(slice) + noise.x) / float(slices) * AO_PI;
        AoSlice sl = ao_slice(phi, screenRadius, n, viewVec);

        uint occluded = 0u;
        for (int step = 0; step < steps; ++step) {
            float stepNoise = fract(noise.y + float(slice + step * steps) * 0.6180339887498948);
            float s = pow((float(step) + stepNoise) / float(steps), vbao.params.z) + minS;
            ivec2 offset = ivec2(round(s * sl.omega));
            occluded |= vbao_sampleSectors(g, offset, p, viewVec, sl.angleN, 1.0);
            occluded |= vbao_sampleSectors(g, -offset, p, viewVec, sl.angleN, -1.0);
        }
        visibility += sl.projectedLength * vbm_visibleMeasure(occluded, sl.angleN);
    }
    return visibility / float(slices);
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(vbao_evaluate(ao_gbufferPixel(e)), vbao.params.w)));
}
