// Marching one cone through a clipmap (src/clipmap): the dense path's march (cone_march.glsl,
// BRIEF section 3) with the level of detail also bounded below by the sample's position: a
// sample uses the finest level whose box holds it with a margin, and near that box's border
// its level of detail rises continuously to the next level (no seam). Level l at mip f stands
// for a dense grid's mip l + f; levels nest (clipmap_nest.glsl), so the switch from level l
// mip 1 to level l + 1 mip 0 changes nothing. Isotropic mips only. Positions are in level-0
// voxel units.
//
// Defines: CONE_GI (1: premultiplied radiance + alpha from the levels' radiance; 0: opacity).
#include "cone/cone_shared.h"
#include "cone/clipmap_shared.h"

layout(std140, binding = CONE_UBO_BINDING) uniform ConeBlock { ConeUniforms u; };
layout(std140, binding = CLIPMAP_UBO_BINDING) uniform ClipmapBlock { ClipmapUniforms cm; };

layout(binding = 0) uniform sampler2D gbufPosition;
layout(binding = 1) uniform sampler2D gbufNormal;
layout(binding = 2) uniform sampler2D gbufGeomNormal;
layout(binding = 3) uniform sampler2D gbufAlbedo;

layout(binding = CLIPMAP_UNIT_LEVEL0 + 0) uniform sampler3D clip_level0;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 1) uniform sampler3D clip_level1;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 2) uniform sampler3D clip_level2;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 3) uniform sampler3D clip_level3;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 4) uniform sampler3D clip_level4;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 5) uniform sampler3D clip_level5;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 6) uniform sampler3D clip_level6;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 7) uniform sampler3D clip_level7;

mat3 cone_frame(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

vec3 clip_levelCoords(int level, vec3 x0) {
    vec4 m = cm.levelFromLevel0[level];
    return x0 * m.w + m.xyz;
}

// Level of detail (level-0 units) that the position x0 allows: l inside level l's interior,
// rising to l + 1 across the blend band at its border; the coarsest level everywhere else.
float clip_positionLod(vec3 x0) {
    int n = int(cm.info.x);
    float halfRes = 0.5 * cm.info.y;
    float margin = cm.band.x, blend = cm.band.y;
    for (int l = 0; l < n - 1; ++l) {
        vec3 q = abs(clip_levelCoords(l, x0) - halfRes);
        float m = max(q.x, max(q.y, q.z));
        if (m < halfRes - margin) return float(l) + clamp((m - (halfRes - margin - blend)) / blend, 0.0, 1.0);
    }
    return float(n - 1);
}

// (premultiplied radiance, alpha) of level `level` at its texture coordinate tc, mip `mip`.
vec4 clip_fetch(int level, vec3 tc, float mip) {
    vec4 s;
    switch (level) {
    case 0: s = textureLod(clip_level0, tc, mip); break;
    case 1: s = textureLod(clip_level1, tc, mip); break;
    case 2: s = textureLod(clip_level2, tc, mip); break;
    case 3: s = textureLod(clip_level3, tc, mip); break;
    case 4: s = textureLod(clip_level4, tc, mip); break;
    case 5: s = textureLod(clip_level5, tc, mip); break;
    case 6: s = textureLod(clip_level6, tc, mip); break;
    default: s = textureLod(clip_level7, tc, mip); break;
    }
#if CONE_GI
    return s;
#else
    return vec4(0.0, 0.0, 0.0, s.r);
#endif
}

// The clipmap at level-0 position x0 with footprint 2^lod level-0 voxels (lod >= the
// position's own lod): level floor(lod), mip lod - level (the coarsest level takes the rest).
vec4 clip_sample(vec3 x0, float lod) {
    int n = int(cm.info.x);
    int level = min(int(floor(lod)), n - 1);
    float mip = min(lod - float(level), cm.info.z - 1.0);
    return clip_fetch(level, clip_levelCoords(level, x0) / cm.info.y, mip);
}

struct ConeResult {
    vec3 radiance;
    float alpha;
};

// As cone_march (cone_march.glsl), in level-0 voxel units.
ConeResult clip_march(vec3 origin, vec3 d, float h0, float rise, float maxDist, float falloff) {
    float tanHalf = u.march.x;
    float beta = u.march.y;
    float maxAlpha = u.march.w;
    float planeRatio = u.limits.w;
    int n = int(cm.info.x);
    float maxLod = float(n - 1) + cm.info.z - 1.0;
    float res = cm.info.y;
    float coarseScale = cm.levelFromLevel0[n - 1].w;

    ConeResult r;
    r.radiance = vec3(0.0);
    r.alpha = 0.0;
    float t = 0.0;
    for (int i = 0; i < CONE_MAX_STEPS; ++i) {
        if (t >= maxDist || r.alpha >= maxAlpha) break;
        float lod = log2(max(1.0, 2.0 * t * tanHalf));
        if (planeRatio > 0.0) {
            float h = h0 + t * rise;
            lod = min(lod, floor(log2(max(1.0, h / planeRatio))));
        }
        lod = min(max(lod, clip_positionLod(origin + d * t)), maxLod);
        float dt = min(beta * exp2(lod), maxDist - t);
        vec3 p = origin + d * (t + 0.5 * dt);
        // The sample point may sit slightly further out than the step's start.
        lod = min(max(lod, clip_positionLod(p)), maxLod);
        float texel = exp2(lod);

        // Leave once the footprint is outside the coarsest level and moving away.
        vec3 pc = clip_levelCoords(n - 1, p);
        float reach = 1.5 * texel * coarseScale;
        bvec3 below = lessThan(pc, vec3(-reach));
        bvec3 above = greaterThan(pc, vec3(res + reach));
        if (any(bvec3(below.x && d.x <= 0.0, below.y && d.y <= 0.0, below.z && d.z <= 0.0)) ||
            any(bvec3(above.x && d.x >= 0.0, above.y && d.y >= 0.0, above.z && d.z >= 0.0)))
            break;

        vec4 s = clip_sample(p, lod);
        float a = clamp(s.a, 0.0, 1.0);
        float k = dt / texel;
        float aStep = 1.0 - exp2(k * log2(max(1.0 - a, 1e-7)));
        vec3 c = a > 1e-6 ? s.rgb * (aStep / a) : s.rgb * k;
        float w = falloff > 0.0 ? 1.0 / (1.0 + falloff * (t + 0.5 * dt)) : 1.0;
        r.radiance += (1.0 - r.alpha) * c;
        r.alpha += (1.0 - r.alpha) * aStep * w;
        t += dt;
    }
    if (r.alpha >= maxAlpha) {
        r.radiance /= r.alpha;
        r.alpha = 1.0;
    }
    return r;
}

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

struct ConeGather {
    vec3 radiance;
    float occlusion;
};

// As cone_gather (cone_march.glsl). The start offset is in voxels of the level the surface
// point itself falls in (continuously across the blend bands), so a point near a level
// border does not occlude itself with that coarser level's voxels.
ConeGather cone_gather(vec3 pWorld, vec3 n, vec3 ng, float maxDist, float falloff, float sky) {
    vec3 p = (u.voxelFromWorld * vec4(pWorld, 1.0)).xyz;
    mat3 frame = cone_frame(n);
    float offset = u.march.z * exp2(clip_positionLod(p));
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
        ConeResult r = clip_march(origin, d, offset, rise, maxDist, falloff);
        g.radiance += cone.w * (r.radiance + (1.0 - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
    }
    return g;
}
