// A clipmap (src/clipmap) as cone_marchVolume (cone_march_shared.h) reads it: the dense
// path's march with the level of detail also bounded below by the sample's position: a
// sample uses the finest level whose box holds it with a margin, and near that box's border
// its level of detail rises continuously to the next level (no seam). Level l at mip f stands
// for a dense grid's mip l + f; levels nest (clipmap_nest.glsl), so the switch from level l
// mip 1 to level l + 1 mip 0 changes nothing. Isotropic mips only. Positions are in level-0
// voxel units.
//
// Defines: CONE_GI (1: premultiplied radiance + alpha from the levels' radiance; 0: opacity).
#include "cone/cone_common.glsl"
#include "cone/clipmap_shared.h"

layout(std140, binding = CLIPMAP_UBO_BINDING) uniform ClipmapBlock { ClipmapUniforms cm; };

layout(binding = CLIPMAP_UNIT_LEVEL0 + 0) uniform sampler3D clip_level0;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 1) uniform sampler3D clip_level1;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 2) uniform sampler3D clip_level2;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 3) uniform sampler3D clip_level3;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 4) uniform sampler3D clip_level4;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 5) uniform sampler3D clip_level5;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 6) uniform sampler3D clip_level6;
layout(binding = CLIPMAP_UNIT_LEVEL0 + 7) uniform sampler3D clip_level7;

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
    cone_fetches += 1.0;
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

// The volume of cone_marchVolume, in level-0 voxel units: no level of detail finer than the
// position's own or coarser than the coarsest level's last mip, the coarsest level's box, and
// no facing rule.
float cone_volumeLod(float lod, vec3 x0) {
    float maxLod = float(int(cm.info.x) - 1) + cm.info.z - 1.0;
    return min(max(lod, clip_positionLod(x0)), maxLod);
}

// Leaves once the footprint is outside the coarsest level and moving away.
bool cone_volumeLeaving(vec3 p, vec3 d, float texel) {
    int n = int(cm.info.x);
    vec3 pc = clip_levelCoords(n - 1, p);
    float reach = 1.5 * texel * cm.levelFromLevel0[n - 1].w;
    return cone_leaving(pc, d, vec3(cm.info.y), reach);
}

vec4 cone_volumeSample(vec3 p, vec3 d, float lod, float dt, vec2 cap) { return clip_sample(p, lod); }

float cone_volumeFacing(vec3 p, vec3 d, float lod, vec4 s) { return 1.0; }

// As cone_gather (cone_march.glsl). The start offset is in voxels of the level the surface
// point itself falls in (continuously across the blend bands), so a point near a level
// border does not occlude itself with that coarser level's voxels.
ConeGather cone_gather(ConeGather g, vec3 pWorld, vec3 n, vec3 ng, float maxDist, float falloff, float sky) {
    vec3 p = (u.voxelFromWorld * vec4(pWorld, 1.0)).xyz;
    float offset = u.march.z * exp2(clip_positionLod(p));
    return cone_gatherVoxel(g, p, n, ng, offset, offset, maxDist, falloff, sky);
}
