// gtao: per pixel, `slices` view-aligned slices through the view vector; in each, search
// the horizon on both sides (`steps` samples per side), clamp the horizons to the projected
// normal angle n +- pi/2 and integrate the cosine-weighted visible arc in closed form
// (Jimenez et al. 2016, Algorithm 1; line numbers below are the paper's). Structure and
// heuristics follow XeGTAO's XeGTAO_MainPass; differences: our view space is right-handed
// with GL's y-up pixels, samples off screen or on sky do not raise the horizon, and
// XeGTAO's small-radius fade hack is left out.
#include "ao/ao_common.glsl"
#include "ao/gtao_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform GtaoBlock { GtaoUniforms gtao; };
layout(binding = AO_UNIT_ALBEDO) uniform sampler2D aoGAlbedo;
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

// Horizon cosine on one side after one sample at pixel offset `offset` (falloff-weighted
// toward the low horizon, as XeGTAO). Returns `current` when the sample is unusable.
float gtao_sampleHorizonCos(ivec2 g, ivec2 offset, vec3 p, vec3 viewVec, float lowCos, float current) {
    ivec2 q = g + offset;
    vec3 s;
    if (offset == ivec2(0) || !ao_onScreen(q) || !ao_fetchViewPosition(q, s)) return current;
    vec3 delta = s - p;
    float dist = length(delta);
    float falloffBase = length(vec3(delta.xy, delta.z * (1.0 + gtao.shaping.x)));
    float weight = clamp(falloffBase * gtao.falloff.y + gtao.falloff.z, 0.0, 1.0);
    float shc = dot(delta / max(dist, 1e-30), viewVec);
    return max(current, mix(lowCos, shc, weight));
}

// Cosine-weighted visible arc of one side, horizon angle h, projected normal angle n.
float gtao_arc(float h, float n, float cosN) { return (cosN + 2.0 * h * sin(n) - cos(2.0 * h - n)) * 0.25; }

// Jimenez et al.'s fit of multi-bounce AO for albedo rho (their eq. 10).
float gtao_multiBounce(float visibility, float rho) {
    float a = 2.0404 * rho - 0.3324;
    float b = -4.7951 * rho + 0.6417;
    float c = 2.7552 * rho + 0.6903;
    return max(visibility, ((visibility * a + b) * visibility + c) * visibility);
}

float gtao_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    p *= 0.99999;  // XeGTAO: nudge toward the eye so the pixel's own plane never occludes it
    vec3 viewVec = normalize(-p);

    float screenRadius = gtao.falloff.x * ao_pixelsPerUnit(-p.z);
    float minS = GTAO_MIN_STEP_PIXELS / max(screenRadius, 1e-30);
    vec2 noise = ao_pixelNoise(g, 3u);
    int slices = gtao.config.x, steps = gtao.config.y;

    float visibility = 0.0;
    for (int slice = 0; slice < slices; ++slice) {
        float phi = (float(slice) + noise.x) / float(slices) * AO_PI;         // lines 5-6
        AoSlice sl = ao_slice(phi, screenRadius, n, viewVec);                 // lines 7-15
        vec2 omega = sl.omega;
        float projectedLength = sl.projectedLength, cosN = sl.cosN, angleN = sl.angleN;

        float lowCos0 = cos(angleN + AO_HALF_PI), lowCos1 = cos(angleN - AO_HALF_PI);
        float horizonCos0 = lowCos0, horizonCos1 = lowCos1;                    // lines 17-18
        for (int step = 0; step < steps; ++step) {
            // R1 quasi-random offset per step (XeGTAO), on top of the per-pixel noise.
            float stepNoise = fract(noise.y + float(slice + step * steps) * 0.6180339887498948);
            float s = pow((float(step) + stepNoise) / float(steps), gtao.falloff.w) + minS;  // line 20
            ivec2 offset = ivec2(round(s * omega));  // snapped to texel centres, as XeGTAO
            horizonCos0 = gtao_sampleHorizonCos(g, offset, p, viewVec, lowCos0, horizonCos0);
            horizonCos1 = gtao_sampleHorizonCos(g, -offset, p, viewVec, lowCos1, horizonCos1);
        }
        projectedLength = mix(projectedLength, 1.0, GTAO_PROJECTED_NORMAL_FUDGE);
        float h0 = -acos(clamp(horizonCos1, -1.0, 1.0));                        // line 27
        float h1 = acos(clamp(horizonCos0, -1.0, 1.0));
        h0 = angleN + clamp(h0 - angleN, -AO_HALF_PI, AO_HALF_PI);
        h1 = angleN + clamp(h1 - angleN, -AO_HALF_PI, AO_HALF_PI);
        visibility += projectedLength * (gtao_arc(h0, angleN, cosN) + gtao_arc(h1, angleN, cosN));
    }
    visibility = pow(max(visibility / float(slices), 0.0), gtao.shaping.y);
    if (gtao.config.z != 0) {
        vec3 albedo = texelFetch(aoGAlbedo, g, 0).rgb;
        visibility = gtao_multiBounce(visibility, dot(albedo, vec3(0.2126, 0.7152, 0.0722)));
    }
    return visibility;
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(gtao_evaluate(ao_gbufferPixel(e)), gtao.shaping.z)));
}
