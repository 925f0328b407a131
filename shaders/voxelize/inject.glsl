// Direct light into the voxels: L = emission + albedo / pi * sum_lights E, with E the
// irradiance of each KHR_lights_punctual light on the voxel's average normal and its
// visibility from a voxel walk (Amanatides-Woo) through the level-0 opacity. Radiance is a
// per-area quantity, so nothing here scales with the voxel size: the result does not
// change with the grid resolution. Output premultiplied: (L * opacity, opacity).
// TWO_SIDED: two-sided voxels (voxelize_shared.h) are lit on each face and write their facing
// normal, level 0 of the normal texture, which the mips then filter.
// LIGHT_BATCHES: one dispatch of several that each sum lights [uLightFirst, uLightEnd) onto the
// irradiance the previous ones left in ioIrradiance (and ioIrradianceBack for the back faces of
// two-sided voxels); the last (uLastBatch) writes the radiance. An invocation's shadow walks
// cost up to a grid diagonal each, and llvmpipe ends its loops after 65535 iterations
// (common/loop_budget.h), so injectRadiance gives each dispatch as many lights as that budget
// holds: the same sums in the same order as one dispatch.
#include "common/scene.glsl"
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(binding = 0) uniform sampler3D uOpacity;
layout(binding = 1) uniform sampler3D uAlbedo;
layout(binding = 2) uniform sampler3D uNormal;
layout(binding = 3) uniform sampler3D uEmission;
layout(RADIANCE_FORMAT, binding = 0) uniform writeonly image3D outRadiance;
#ifdef TWO_SIDED
layout(binding = 4) uniform sampler3D uTwoSided;  // xyz = winding normal, w = doubleSided share
layout(rgba16f, binding = 1) uniform writeonly image3D outNormal;
#endif
#ifdef LIGHT_BATCHES
layout(rgba32f, binding = 2) uniform image3D ioIrradiance;
#ifdef TWO_SIDED
layout(rgba32f, binding = 3) uniform image3D ioIrradianceBack;
#endif
uniform bool uLastBatch;
#endif

uniform ivec3 uResolution;
uniform vec3 uGridOrigin;
uniform float uVoxelSize;
uniform int uLightFirst;  // the lights this dispatch sums: [uLightFirst, uLightEnd)
uniform int uLightEnd;
uniform float uShadowOffset;  // voxels along the normal before the shadow ray starts

const float PI = 3.14159265358979;
const float RADIANCE_MAX = RADIANCE_FORMAT_MAX;

// Transmittance from `o` (voxel units of `opacity`, `res` voxels per axis) along unit `d` up
// to distance tMax, compositing the opacity of every voxel the segment crosses; stops once it
// is ~opaque.
float inject_march(sampler3D opacity, ivec3 res, vec3 o, vec3 d, float tMax) {
    // Clip to the grid box: outside it there is nothing to block.
    vec3 invD;
    for (int a = 0; a < 3; ++a) invD[a] = d[a] != 0.0 ? 1.0 / d[a] : 1.0e30;
    vec3 t0 = (vec3(0.0) - o) * invD, t1 = (vec3(res) - o) * invD;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    float tEnter = max(0.0, max(tNear.x, max(tNear.y, tNear.z)));
    float tExit = min(tMax, min(tFar.x, min(tFar.y, tFar.z)));
    if (!(tEnter < tExit)) return 1.0;
    vec3 p = o + d * tEnter;
    ivec3 cell = clamp(ivec3(floor(p)), ivec3(0), res - 1);
    ivec3 stepDir = ivec3(sign(d));
    vec3 tDelta = abs(invD);
    vec3 tNext = vec3(tExit + 1.0);
    for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0) tNext[a] = tEnter + ((float(cell[a]) + (d[a] > 0.0 ? 1.0 : 0.0)) - p[a]) * invD[a];
    float transmittance = 1.0;
    int maxSteps = res.x + res.y + res.z + 3;
    for (int i = 0; i < maxSteps; ++i) {
        transmittance *= 1.0 - texelFetch(opacity, cell, 0).r;
        if (transmittance < 0.01) return 0.0;
        float tn = min(tNext.x, min(tNext.y, tNext.z));
        if (tn >= tExit) break;
        int a = tNext.x == tn ? 0 : (tNext.y == tn ? 1 : 2);
        cell[a] += stepDir[a];
        tNext[a] += tDelta[a];
        if (cell[a] < 0 || cell[a] >= res[a]) break;
    }
    return transmittance;
}

#ifdef OUTER_LEVELS
// Clipmap levels (src/clipmap): the coarser levels around this one, innermost first. A shadow
// ray that leaves this level's box continues in each coarser level from where it left the
// previous one, so occluders outside the box still cast shadows.
uniform sampler3D uOuterOpacity[OUTER_LEVELS];
uniform vec4 uOuterGrid[OUTER_LEVELS];  // xyz = origin (world), w = voxel size
uniform int uOuterResolution;           // voxels per axis (cubic levels)
uniform int uOuterCount;

// Distance along d from o (inside the box [lo, hi]) to where it leaves the box.
float inject_exitDistance(vec3 o, vec3 d, vec3 lo, vec3 hi) {
    float t = 3.4e38;
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0.0) t = min(t, (hi[a] - o[a]) / d[a]);
        else if (d[a] < 0.0) t = min(t, (lo[a] - o[a]) / d[a]);
    }
    return max(t, 0.0);
}
#endif

// Transmittance from voxel-space `o` along `d` over tMax voxels: this grid, then the outer levels.
float inject_visibility(vec3 o, vec3 d, float tMax) {
    float v = inject_march(uOpacity, uResolution, o, d, tMax);
#ifdef OUTER_LEVELS
    vec3 oWorld = uGridOrigin + o * uVoxelSize;
    float tMaxWorld = tMax * uVoxelSize;
    vec3 lo = uGridOrigin, hi = uGridOrigin + vec3(uResolution) * uVoxelSize;
    for (int k = 0; k < uOuterCount && v >= 0.01; ++k) {
        float tExit = inject_exitDistance(oWorld, d, lo, hi);
        if (tExit >= tMaxWorld) break;
        vec4 g = uOuterGrid[k];
        vec3 start = (oWorld + d * tExit - g.xyz) / g.w;
        v *= inject_march(uOuterOpacity[k], ivec3(uOuterResolution), start, d, (tMaxWorld - tExit) / g.w);
        lo = g.xyz;
        hi = g.xyz + vec3(uOuterResolution) * g.w;
    }
#endif
    return v;
}

// Irradiance (W/m^2 per channel, here lux-like photometric units as given) from light i on
// a surface at `pWorld` with unit normal n (zero: a voxel whose faces point both ways,
// lit as if facing the light, at half weight since half its area faces away).
vec3 inject_lightIrradiance(int i, vec3 pWorld, vec3 pVoxel, vec3 n) {
    GpuLight light = sceneLights[i];
    int type = int(light.color.w + 0.5);
    vec3 toLight;
    float distance;  // world
    vec3 intensity = light.color.rgb;
    if (type == LIGHT_DIRECTIONAL) {
        toLight = -normalize(light.direction.xyz);
        distance = 3.4e38;
    } else {
        vec3 dl = light.position.xyz - pWorld;
        distance = length(dl);
        if (distance <= 0.0) return vec3(0.0);
        toLight = dl / distance;
        // E = I cos / d^2, with the distance kept above half a voxel so a light inside a
        // voxel does not blow up to Inf.
        intensity /= max(distance * distance, 0.25 * uVoxelSize * uVoxelSize);
        if (type == LIGHT_SPOT) {
            // glTF KHR_lights_punctual smooth falloff between the outer and inner cones.
            float cd = dot(normalize(light.direction.xyz), -toLight);
            float scale = 1.0 / max(0.001, light.spot.y - light.spot.x);
            float att = clamp((cd - light.spot.x) * scale, 0.0, 1.0);
            intensity *= att * att;
        }
    }
    bool twoSided = dot(n, n) < 0.5;
    float cosine = twoSided ? 0.5 : dot(n, toLight);
    if (cosine <= 0.0 || all(equal(intensity, vec3(0.0)))) return vec3(0.0);
    vec3 start = pVoxel + (twoSided ? toLight : n) * uShadowOffset;
    float tMax = distance / uVoxelSize - length(start - pVoxel);
    if (tMax <= 0.0) return intensity * cosine;
    return intensity * cosine * inject_visibility(start, toLight, tMax);
}

// Irradiance of this dispatch's lights on a face with normal n, summed onto E.
vec3 inject_sumLights(vec3 E, vec3 pWorld, vec3 pVoxel, vec3 n) {
    for (int i = uLightFirst; i < uLightEnd; ++i) E += inject_lightIrradiance(i, pWorld, pVoxel, n);
    return E;
}

// What the previous dispatches summed (zero for the first), and whether this dispatch only
// carries its sum to the next one.
#ifdef LIGHT_BATCHES
#define INJECT_PREVIOUS(image, v) (uLightFirst > 0 ? imageLoad(image, v).rgb : vec3(0.0))
#define INJECT_CARRY(image, v, E) if (!uLastBatch) imageStore(image, v, vec4(E, 0.0));
#define INJECT_IS_LAST uLastBatch
#else
#define INJECT_PREVIOUS(image, v) vec3(0.0)
#define INJECT_CARRY(image, v, E)
#define INJECT_IS_LAST true
#endif

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uResolution))) return;
    float alpha = texelFetch(uOpacity, v, 0).r;
    if (alpha <= 0.0) {
        if (INJECT_IS_LAST) imageStore(outRadiance, v, vec4(0.0));
        return;
    }
    vec3 albedo = texelFetch(uAlbedo, v, 0).rgb;
    vec3 L = texelFetch(uEmission, v, 0).rgb;
    vec3 pVoxel = vec3(v) + 0.5;
    vec3 pWorld = uGridOrigin + pVoxel * uVoxelSize;
#ifdef TWO_SIDED
    // Read from the texture resolve wrote, never from the normal this pass rewrites, so every
    // injection gives the same result whatever the lights were before.
    vec4 twoSided = texelFetch(uTwoSided, v, 0);
    if (twoSided.w >= VOX_TWO_SIDED_SHARE && dot(twoSided.xyz, twoSided.xyz) > 0.25) {
        vec3 front = normalize(twoSided.xyz);
        vec3 Ef = inject_sumLights(INJECT_PREVIOUS(ioIrradiance, v), pWorld, pVoxel, front);
        vec3 Eb = inject_sumLights(INJECT_PREVIOUS(ioIrradianceBack, v), pWorld, pVoxel, -front);
        INJECT_CARRY(ioIrradiance, v, Ef)
        INJECT_CARRY(ioIrradianceBack, v, Eb)
        if (!INJECT_IS_LAST) return;
        vec3 Lf = min(L + albedo / PI * Ef, vec3(RADIANCE_MAX)), Lb = min(L + albedo / PI * Eb, vec3(RADIANCE_MAX));
        float k = vox_twoSidedNormalScale(Lf, Lb);
        imageStore(outNormal, v, vec4(front * k, 1.0));
        imageStore(outRadiance, v, vec4((k >= 0.0 ? Lf : Lb) * alpha, alpha));
        return;
    }
#endif
    vec3 n = texelFetch(uNormal, v, 0).xyz;
    vec3 E = inject_sumLights(INJECT_PREVIOUS(ioIrradiance, v), pWorld, pVoxel, n);
    INJECT_CARRY(ioIrradiance, v, E)
    if (!INJECT_IS_LAST) return;
    L += albedo / PI * E;
    L = min(L, vec3(RADIANCE_MAX));
    imageStore(outRadiance, v, vec4(L * alpha, alpha));
}
