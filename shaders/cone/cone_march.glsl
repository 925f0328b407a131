// Marching one cone through the voxel grid (Crassin et al. 2011, with the rules of BRIEF
// section 3). Everything here works in voxel units (world / voxelSize, origin at the grid's
// min corner), so the marching constants do not depend on the scene's scale.
//
// Defines: CONE_GI (1: premultiplied radiance + alpha from grid.radiance; 0: alpha only from
// grid.opacity), CONE_ANISO (1: blend the six directional textures above level 0).
#include "cone/cone_shared.h"

layout(std140, binding = CONE_UBO_BINDING) uniform ConeBlock { ConeUniforms u; };

// G-buffer units of render/gbuffer.h (GBufferUnit).
layout(binding = 0) uniform sampler2D gbufPosition;
layout(binding = 1) uniform sampler2D gbufNormal;
layout(binding = 2) uniform sampler2D gbufGeomNormal;
layout(binding = 3) uniform sampler2D gbufAlbedo;

layout(binding = CONE_UNIT_OPACITY) uniform sampler3D cone_isoTexture;
#if CONE_GI
layout(binding = CONE_UNIT_NORMAL) uniform sampler3D cone_normalTexture;
#endif
#if CONE_ANISO
layout(binding = CONE_UNIT_ANISO + 0) uniform sampler3D cone_anisoPX;
layout(binding = CONE_UNIT_ANISO + 1) uniform sampler3D cone_anisoNX;
layout(binding = CONE_UNIT_ANISO + 2) uniform sampler3D cone_anisoPY;
layout(binding = CONE_UNIT_ANISO + 3) uniform sampler3D cone_anisoNY;
layout(binding = CONE_UNIT_ANISO + 4) uniform sampler3D cone_anisoPZ;
layout(binding = CONE_UNIT_ANISO + 5) uniform sampler3D cone_anisoNZ;
#endif

// Tangent frame around unit n without a branch on the pole (Duff et al. 2017).
mat3 cone_frame(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

vec4 cone_sampleIso(vec3 tc, float lod) {
#if CONE_GI
    return textureLod(cone_isoTexture, tc, lod);
#else
    return vec4(0.0, 0.0, 0.0, textureLod(cone_isoTexture, tc, lod).r);
#endif
}

#if CONE_ANISO
// Directional level `lod` (= pyramid level lod + 1) as seen by a cone travelling along d.
vec4 cone_sampleAniso(vec3 tc, vec3 d, float lod) {
    vec3 w = cone_anisoWeights(d);
    vec4 x = d.x >= 0.0 ? textureLod(cone_anisoPX, tc, lod) : textureLod(cone_anisoNX, tc, lod);
    vec4 y = d.y >= 0.0 ? textureLod(cone_anisoPY, tc, lod) : textureLod(cone_anisoNY, tc, lod);
    vec4 z = d.z >= 0.0 ? textureLod(cone_anisoPZ, tc, lod) : textureLod(cone_anisoNZ, tc, lod);
    return cone_blendDirectional(w, x, y, z);
}
#endif

// Premultiplied (radiance, alpha) of the grid at voxel-space point p, footprint 2^lod voxels.
vec4 cone_sampleGrid(vec3 p, vec3 d, float lod) {
    vec3 tc = p / u.gridResolution.xyz;
#if CONE_ANISO
    vec4 directional = cone_sampleAniso(tc, d, max(lod - 1.0, 0.0));
    // Between the base level and the first directional level: blend as trilinear
    // filtering blends two mip levels. (One directional fetch on both paths: on SIMD
    // hardware and llvmpipe a divergent branch would run both.)
    if (lod < 1.0) directional = mix(cone_sampleIso(tc, 0.0), directional, lod);
    return directional;
#else
    return cone_sampleIso(tc, lod);
#endif
}

#if CONE_GI
// vox_facingWeight (voxelize_shared.h) of the sample's voxels: their mean normal at the
// sample's level (normal mips are coverage-weighted, a = coverage). Without it a cone that
// meets a surface's back gathers the light of its front, at every level, and the
// directional mips cannot tell: a horizontal emitter is as bright to a cone crossing it at
// 60 degrees from above as from below.
float cone_facing(vec3 p, vec3 d, float lod) {
    vec4 n = textureLod(cone_normalTexture, p / u.gridResolution.xyz, lod);
    return vox_facingWeight(n.xyz / max(n.w, 1e-4), d);
}
#endif

struct ConeResult {
    vec3 radiance;   // premultiplied radiance gathered front to back
    float alpha;     // accumulated opacity; 1 = the cone saw no sky
};

// Marches from `origin` (voxel units) along unit `d`. `h0` is the origin's height above the
// shading point's tangent plane and `rise` = dot(d, geometric normal), both for the plane
// limit; `maxDist` (voxels) limits the distance (R for AO); `falloff` is lambda (AO only).
ConeResult cone_march(vec3 origin, vec3 d, float h0, float rise, float maxDist, float falloff) {
    float tanHalf = u.march.x;
    float beta = u.march.y;
    float maxAlpha = u.march.w;
    float planeRatio = u.limits.w;
    float maxLod = u.gridResolution.w - 1.0;
    vec3 res = u.gridResolution.xyz;

    ConeResult r;
    r.radiance = vec3(0.0);
    r.alpha = 0.0;
    float t = 0.0;
    for (int i = 0; i < CONE_MAX_STEPS; ++i) {
        if (t >= maxDist || r.alpha >= maxAlpha) break;
        // Footprint: diameter 2 t tan(aperture / 2), at least one voxel.
        float lod = log2(max(1.0, 2.0 * t * tanHalf));
        if (planeRatio > 0.0) {
            // Whole levels only: a fractional level would blend in the next, coarser one.
            float h = h0 + t * rise;
            lod = min(lod, floor(log2(max(1.0, h / planeRatio))));
        }
        lod = min(lod, maxLod);
        float texel = exp2(lod);
        float dt = min(beta * texel, maxDist - t);
        vec3 p = origin + d * (t + 0.5 * dt);

        // Leave once the footprint (one texel of trilinear reach past half a texel) is outside
        // the grid and moving away: the zero border means only sky remains.
        float reach = 1.5 * texel;
        bvec3 below = lessThan(p, vec3(-reach));
        bvec3 above = greaterThan(p, res + reach);
        if (any(bvec3(below.x && d.x <= 0.0, below.y && d.y <= 0.0, below.z && d.z <= 0.0)) ||
            any(bvec3(above.x && d.x >= 0.0, above.y && d.y >= 0.0, above.z && d.z >= 0.0)))
            break;

        vec4 s = cone_sampleGrid(p, d, lod);
#if CONE_GI
        s.rgb *= cone_facing(p, d, lod);
#endif
        // Opacity of a step dt through a texel of edge `texel`: alpha' = 1 - (1 - alpha)^(dt / texel).
        float a = clamp(s.a, 0.0, 1.0);
        float k = dt / texel;
        float aStep = 1.0 - exp2(k * log2(max(1.0 - a, 1e-7)));
        // Premultiplied radiance scales with the corrected opacity (its ratio to alpha is the
        // radiance itself); a transparent sample with radiance would be emission of a medium.
        vec3 c = a > 1e-6 ? s.rgb * (aStep / a) : s.rgb * k;
        float w = falloff > 0.0 ? 1.0 / (1.0 + falloff * (t + 0.5 * dt)) : 1.0;
        r.radiance += (1.0 - r.alpha) * c;
        r.alpha += (1.0 - r.alpha) * aStep * w;
        t += dt;
    }
    // A saturated cone counts as closed: renormalize what it saw rather than letting the
    // last 1 - maxAlpha see the sky (that would leak sky light into closed rooms).
    if (r.alpha >= maxAlpha) {
        r.radiance /= r.alpha;
        r.alpha = 1.0;
    }
    return r;
}

// Reads the G-buffer texel; false for sky or unusable normals.
bool cone_surface(ivec2 pix, out vec3 pWorld, out vec3 n, out vec3 ng) {
    vec4 pos = texelFetch(gbufPosition, pix, 0);
    n = texelFetch(gbufNormal, pix, 0).xyz;
    ng = texelFetch(gbufGeomNormal, pix, 0).xyz;
    pWorld = pos.xyz;
    if (!(pos.w > 0.0)) return false;
    if (any(isnan(pos.xyz)) || any(isinf(pos.xyz))) return false;
    float ln = dot(n, n), lg = dot(ng, ng);
    if (!(lg > 1e-12) || isnan(lg) || isinf(lg)) return false;
    ng *= inversesqrt(lg);
    n = (ln > 1e-12 && !isnan(ln) && !isinf(ln)) ? n * inversesqrt(ln) : ng;
    return true;
}

// The cone set around shading normal n: sum_c w_c * (cone result) integrates the cosine lobe.
// Cones whose axis is below the geometric plane are closed (BRIEF section 1: directions below
// the geometric normal count as occluded).
struct ConeGather {
    vec3 radiance;    // sum_c w_c * (radiance_c + (1 - alpha_c) * sky)
    float occlusion;  // sum_c w_c * alpha_c
};

// The gather from voxel-space point p (the surface point, or a voxel centre for bounces);
// the cones start `offset` voxels along ng, and `h0` is that start's height above the
// tangent plane for the plane limit.
ConeGather cone_gatherVoxel(vec3 p, vec3 n, vec3 ng, float offset, float h0, float maxDist, float falloff,
                            float sky) {
    mat3 frame = cone_frame(n);
    vec3 origin = p + ng * offset;
    ConeGather g;
    g.radiance = vec3(0.0);
    g.occlusion = 0.0;
    for (int c = 0; c < u.config.x; ++c) {
        vec4 cone = u.cones[c];
        vec3 d = normalize(frame * cone.xyz);
        float rise = dot(d, ng);
        if (rise <= 0.0) {
            g.occlusion += cone.w;
            continue;
        }
        ConeResult r = cone_march(origin, d, h0, rise, maxDist, falloff);
        g.radiance += cone.w * (r.radiance + (1.0 - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
    }
    return g;
}

ConeGather cone_gather(vec3 pWorld, vec3 n, vec3 ng, float maxDist, float falloff, float sky) {
    // voxelFromWorld is a uniform scale plus a translation: directions keep their length.
    vec3 p = (u.voxelFromWorld * vec4(pWorld, 1.0)).xyz;
    return cone_gatherVoxel(p, n, ng, u.march.z, u.march.z, maxDist, falloff, sky);
}
