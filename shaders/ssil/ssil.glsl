// ssil: one bounce of diffuse light gathered from the lit G-buffer (direct light of the
// punctual lights + emission) with VBAO's visibility bitmasks (Therrien, Levesque and Gilet
// 2023). Per slice, samples are taken from p outward on both sides; each claims the sectors
// it occludes that no nearer sample has (ao/visibility_bitmask.h), and brings its radiance
// times their cosine-weighted measure, so the nearest surface in a direction is the one seen
// there, as a ray would find. The sectors left clear see the sky. Indirect radiance, as VCT's
// GI: albedo x (gathered radiance + sky x clear fraction), with the 1/pi of the Lambertian
// BRDF already in the measure (its total over the hemisphere is 1). Sky pixels read 0.
#include "ao/ao_common.glsl"
#include "ao/visibility_bitmask.h"
#include "ssil/ssil_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform SsilBlock { SsilUniforms ssil; };
layout(binding = AO_UNIT_ALBEDO) uniform sampler2D ssilAlbedo;
layout(binding = SSIL_UNIT_EMISSION) uniform sampler2D ssilEmission;
layout(binding = SSIL_UNIT_DIRECT) uniform sampler2D ssilDirect;
layout(rgba32f, binding = SSIL_IMAGE_OUTPUT) uniform writeonly image2D ssilOut;

// The radiance a sample's surface sends toward p: what the camera sees there (Lambertian, so
// the same in every direction of its front side), or nothing when p is behind it.
vec3 ssil_sampleRadiance(ivec2 q, vec3 s, vec3 p) {
    if (dot(ao_fetchViewNormal(q, s), p - s) <= 0.0) return vec3(0.0);
    vec3 l = texelFetch(ssilEmission, q, 0).rgb;
    if (ssil.config.z != 0) l += texelFetch(ssilDirect, q, 0).rgb;
    return max(l, vec3(0.0));
}

// One sample at pixel offset `offset`, `side` +1 along the slice's screen direction: claims
// the sectors it occludes that are still clear, and adds its light over them.
void ssil_sample(ivec2 g, ivec2 offset, vec3 p, vec3 viewVec, float angleN, float side, float thickness,
                 inout uint occluded, inout vec3 gathered) {
    ivec2 q = g + offset;
    vec3 s;
    if (offset == ivec2(0) || !ao_onScreen(q) || !ao_fetchViewPosition(q, s)) return;
    vec3 delta = s - p;
    float dist = length(delta);
    if (!(dist > 0.0)) return;
    float scale = 1.0 / max(dist, thickness);  // finite at every scale, as vbao.glsl
    vec3 back = delta * scale - viewVec * (thickness * scale);
    float hFront = acos(clamp(dot(delta, viewVec) / dist, -1.0, 1.0));
    float hBack = acos(clamp(dot(back, viewVec) / max(length(back), 1e-30), -1.0, 1.0));
    uint bits = side > 0.0 ? vbm_occludedBits(hFront, hBack, angleN) : vbm_occludedBits(-hBack, -hFront, angleN);
    uint claimed = bits & ~occluded;
    if (claimed == 0u) return;
    gathered += ssil_sampleRadiance(q, s, p) * vbm_measure(claimed, angleN);
    occluded |= claimed;
}

vec3 ssil_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return vec3(0.0);
    vec3 n = ao_fetchViewNormal(g, p);
    vec3 albedo = max(texelFetch(ssilAlbedo, g, 0).rgb, vec3(0.0));
    p *= 0.99999;  // as GTAO: the pixel's own plane never occludes it
    vec3 viewVec = normalize(-p);
    float thickness = ssil.params.y * (-p.z);
    float screenRadius = ssil.params.x;
    float minS = SSIL_MIN_STEP_PIXELS / max(screenRadius, 1e-30);
    vec2 noise = ao_pixelNoise(g, 5u);
    int slices = ssil.config.x, steps = ssil.config.y;

    vec3 radiance = vec3(0.0);
    for (int slice = 0; slice < slices; ++slice) {
        // The slice and its projected normal, as GTAO (Jimenez et al. 2016, Algorithm 1, lines 5-15).
        float phi = (float(slice) + noise.x) / float(slices) * AO_PI;
        AoSlice sl = ao_slice(phi, screenRadius, n, viewVec);

        uint occluded = 0u;
        vec3 gathered = vec3(0.0);
        for (int step = 0; step < steps; ++step) {  // near to far: the nearest sample claims a sector
            float stepNoise = fract(noise.y + float(slice + step * steps) * 0.6180339887498948);
            float s = pow((float(step) + stepNoise) / float(steps), ssil.params.z) + minS;
            ivec2 offset = ivec2(round(s * sl.omega));
            ssil_sample(g, offset, p, viewVec, sl.angleN, 1.0, thickness, occluded, gathered);
            ssil_sample(g, -offset, p, viewVec, sl.angleN, -1.0, thickness, occluded, gathered);
        }
        radiance += sl.projectedLength * (gathered + ssil.params.w * vbm_visibleMeasure(occluded, sl.angleN));
    }
    return albedo * radiance / float(slices);
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    vec3 l = ssil_evaluate(e);
    bool finite = !any(isnan(l)) && !any(isinf(l));
    imageStore(ssilOut, e, vec4(finite ? l : vec3(0.0), 1.0));
}
