// Marching one cone through a voxel volume (Crassin et al. 2011, with this project's
// sampling, compositing and plane-limit rules), written once for C++ and GLSL: the dense grid (cone_march.glsl), the clipmap
// (clipmap_march.glsl) and the sparse CPU tracer (src/vdb/sparse_cone.cpp) run this text, so
// the CPU tests exercise the shaders' code. Samples composite front to back with
// cone_composite.h. Everything works in voxel units of the volume's finest level, so the
// marching constants do not depend on the scene's scale.
//
// The volume is what differs. cone_marchVolume reads it through four calls:
//   lod(lod, x)            the level of detail the volume uses at x for footprint level lod
//                          (its coarsest level bounds it; a clipmap's levels bound it below)
//   leaving(p, d, texel)   true once a sample of edge `texel` at p, moving along d, can only
//                          see the zero border (cone_leaving in the volume's own coordinates)
//   sample(p, d, lod, dt, cap)  premultiplied (radiance, alpha) at p, footprint 2^lod voxels,
//                          for a step of dt voxels (which the sample sits in the middle of);
//                          cap = (maxDist - the sample's distance, maxDist tan(alpha)) for
//                          cone_sampleSheets' lane caps (y = 0: none)
//   facing(p, d, lod, s)   the weight of sample s's radiance for a cone along d (GI's facing
//                          rule; 1 where the volume has none)
// and, for cone_sampleSheets (vct.voxel.edges=sheet), sheet(v), the base level's sheet texel,
// sheetExtent(v), its extent bits, and sheetLight(v), the light leaving the voxel (GI; zero for
// AO).
// In C++ the volume is an object with these member functions (cone_marchVolume is a
// template); in GLSL they are the functions cone_volumeLod, cone_volumeLeaving,
// cone_volumeSample and cone_volumeFacing, declared below and defined by the includer.
// A shared caller of the march takes the volume as CONE_VOLUME_PARAM and passes it on as
// CONE_VOLUME_ARG (both empty in GLSL).
//
// Float literals carry `f` so C++ computes in float as GLSL does, and the operations keep
// the order the shaders have always had: reordering would change the rounding, and the
// dense images are checked bit for bit.
#pragma once
#include "cone/cone_composite.h"
#include "cone/cone_shared.h"

#ifdef __cplusplus
#define CONE_VOLUME_TEMPLATE template <class ConeVolume>
#define CONE_VOLUME_PARAM ConeVolume& volume,
#define CONE_VOLUME_ARG volume,
#define CONE_VOLUME_LOD(l, x) volume.lod(l, x)
#define CONE_VOLUME_LEAVING(p, d, texel) volume.leaving(p, d, texel)
#define CONE_VOLUME_SAMPLE(p, d, l, dt, cap) volume.sample(p, d, l, dt, cap)
#define CONE_VOLUME_FACING(p, d, l, s) volume.facing(p, d, l, s)
#define CONE_VOLUME_SHEET(v) volume.sheet(v)
#define CONE_VOLUME_SHEET_EXTENT(v) volume.sheetExtent(v)
#define CONE_VOLUME_SHEET_LIGHT(v) volume.sheetLight(v)
#else
#define CONE_VOLUME_TEMPLATE
#define CONE_VOLUME_PARAM
#define CONE_VOLUME_ARG
#define CONE_VOLUME_LOD(l, x) cone_volumeLod(l, x)
#define CONE_VOLUME_LEAVING(p, d, texel) cone_volumeLeaving(p, d, texel)
#define CONE_VOLUME_SAMPLE(p, d, l, dt, cap) cone_volumeSample(p, d, l, dt, cap)
#define CONE_VOLUME_FACING(p, d, l, s) cone_volumeFacing(p, d, l, s)
#define CONE_VOLUME_SHEET(v) cone_volumeSheet(v)
#define CONE_VOLUME_SHEET_EXTENT(v) cone_volumeSheetExtent(v)
#define CONE_VOLUME_SHEET_LIGHT(v) cone_volumeSheetLight(v)
#ifdef CONE_SHEETS
vec4 cone_volumeSheet(ivec3 v);
uint cone_volumeSheetExtent(ivec3 v);
vec3 cone_volumeSheetLight(ivec3 v);
#endif
float cone_volumeLod(float lod, vec3 x);
bool cone_volumeLeaving(vec3 p, vec3 d, float texel);
vec4 cone_volumeSample(vec3 p, vec3 d, float lod, float dt, vec2 cap);
float cone_volumeFacing(vec3 p, vec3 d, float lod, vec4 s);
#endif

VCT_BEGIN_NAMESPACE

// vct.voxel.edges=sheet: the base level read with each sheet where it lies in its voxel. A
// level-0 texel of such a grid is (opacity, lo, hi, axis): a voxel its surfaces cross along one
// dominant axis a (axis = a) holds the span [lo, hi] (in the voxel, [0, 1]) of those surfaces
// along a, and every other voxel axis = -1 (vox_sheetTexel, voxelize_shared.h). The volume reads
// the texel of voxel v through sheet(v) (C++) or cone_volumeSheet(v) (GLSL, the CONE_SHEETS
// variant), zero with axis -1 outside the grid.
//
// A box filter a voxel wide (vct.sharpen) places a sheet anywhere in its voxel: a lane that
// ends below a sheet sees it up to a voxel early, and one that passes beside its voxel sees it
// through the trilinear tent. Here a sheet voxel's opacity is seen by the sample whose step
// crosses its span: along a, the step reaches dt |d_a| / 2 either side of the sample p, so the
// voxel counts where [lo - h, hi + h] (h = dt |d_a| / 2) holds p's coordinate. Across a the
// sample is a box one voxel wide about p, and the voxel's opacity lies on its extent across a
// (the voxel's extent bits, vox_extentBits: where in the voxel its surfaces lie, to a tenth of
// a voxel), so a plate's rim is seen where it is; with the whole voxel as extent this is the
// trilinear tent, which spread a rim's share over its voxel. Consecutive steps tile the lane, so
// one crossing is seen once, the share the lane's cap crosses of it. Two voxels of one column
// along a can hold the same sheet (one lying on the face between them), so each column counts
// its larger. A voxel without a sheet (where sheets of two axes meet: a room's corner, a slab's
// rim) is read the same way as a box: a sheet spanning its extent along the lane's main axis
// (the largest |d_a|) and the whole voxel across it, crossed by the step that meets that extent
// (a slab's edge where its faces are, not a voxel early). Read instead as
// the sharpened trilinear box at every sample, it let lanes through where a wall's sheets meet
// the floor's: between the tent across the wall's sheet and the box a step later, a lane
// crossing a wall just above the floor was counted short. The share composites as a
// transmittance, written so that the march's step correction
// (alpha' = 1 - (1 - alpha)^(dt / texel)) returns it.
//
// GI's light. The sample's light is that of the voxels whose sheets (or boxes) its step sees,
// each voxel's own (the volume's sheetLight(v): its base-level radiance over its opacity),
// weighted by what the step sees of it: the trilinear sample's light, rgb / a over the eight
// voxels about the sample, blended in voxels the step does not cross (a sheet one voxel over a
// dark floor was seen at down to half its light).
//
// The lane's cap. The cone model cuts each direction of a lane at R, so a lane whose ray
// crosses a sheet near R is closed by the sheet only in the share of its directions that meet
// it before R; a march that counts the whole lane up to R and nothing past it is a ray there,
// and the lanes' rays alias with the circle of directions that meet the sheet at R (a flat
// sheet at height h: the lanes' ring at cos(theta) = h / R), an error that need not fall as the
// lanes narrow. For a lane of half-aperture alpha along d crossing, at t_c, a plane whose normal
// n makes the angle theta with d, a direction w at angle u from d towards n meets it at
// t_c cos(theta) / dot(w, n) ~ t_c (1 - u tan(theta)) to first order, so before R where
// u <= (R - t_c) / (R tan(theta)): the lane's share on the near side of a chord of its disc
// (cone_capShare). A sheet's normal is its axis a (cos(theta) = |d_a|); its crossing is its
// span's middle. With caps on (cap.y = R tan(alpha) > 0) the march reads the zone about R
// (cone_capZone) at the base level alone and carries on past R through it (a box's crossing is
// its middle along the lane's main axis).
// `lod` and `dt` are the sample's footprint level and step, `cap` as the volume's sample takes it.
// The loops are written out: llvmpipe counts every loop iteration of an invocation against the
// march's budget (coneLoopBound).
#if defined(__cplusplus) || defined(CONE_SHEETS)
// The share of a disc on the near side of a chord `along` from its centre (the disc's radius
// `across`): 1 past the rim, 0 before it; across = 0 is the ray (1 where along >= 0).
CONE_FN float cone_capShare(float along, float across) {
    if (along >= across) return 1.0f;
    if (along <= -across) return 0.0f;
    float s = along / across;
    return 0.5f + (s * sqrt(1.0f - s * s) + asin(s)) * 0.318309886f;
}
// The length of [j + s.x, j + s.y] inside the sample's box one voxel wide about x (with s =
// (0, 1), the trilinear tent's weight of voxel j).
CONE_FN float cone_acrossShare(vec2 s, float j, float x) {
    return max(min(j + s.y, x + 0.5f) - max(j + s.x, x - 0.5f), 0.0f);
}
// What a sample at p (a step of 2 halfStep along d) sees of voxel `cell` along axis a. A sheet of
// axis a whose span [k + lo, k + hi] the step meets: its opacity spread over its extent across a
// (vox_extentSpan of its extent bits `e`; at most 1 there) times the share of the sample's box
// that extent covers. A box (no sheet) where a is the lane's main axis (`mainAxis`) and the step
// meets its extent along a: its opacity times the tent across a, the whole voxel (read by its
// extent across, a lane whose box straddles a concave edge, a room's corner, passes the part
// outside it). With caps on, times the lane's share (cone_capShare of (R - t_c) cos(theta) over
// R tan(alpha) sin(theta)). Else 0.
CONE_FN float cone_sheetSeen(vec4 v, uint e, int a, vec3 cell, vec3 p, vec3 d, float halfStep, vec2 cap, bool mainAxis) {
    bool box = v.w < 0.0f && v.x > 0.0f && mainAxis;
    vec2 span = box ? vox_extentSpan(e, a) : vec2(v.y, v.z);
    float k = cell[a], x = p[a], h = halfStep * abs(d[a]);
    if (!((box || (v.w >= 0.0f && int(v.w) == a)) && x + h >= k + span.x && x - h <= k + span.y)) return 0.0f;
    int b = (a + 1) % 3, c = (a + 2) % 3;
    vec2 sb = box ? vec2(0.0f, 1.0f) : vox_extentSpan(e, b), sc = box ? vec2(0.0f, 1.0f) : vox_extentSpan(e, c);
    float seen = min(v.x / ((sb.y - sb.x) * (sc.y - sc.x)), 1.0f) * cone_acrossShare(sb, cell[b], p[b]) *
                 cone_acrossShare(sc, cell[c], p[c]);
    if (!(cap.y > 0.0f)) return seen;
    float along = cap.x * abs(d[a]) - (k + 0.5f * (span.x + span.y) - x) * sign(d[a]);
    return seen * cone_capShare(along, cap.y * sqrt(max(1.0f - d[a] * d[a], 0.0f)));
}
// One column along axis a: its voxels at `cell` and one further along a, counted once (the
// larger), as (seen l, seen) with l the light leaving the voxel seen (sheetLight, read only
// where the step sees one).
CONE_VOLUME_TEMPLATE
CONE_FN vec4 cone_sheetColumn(CONE_VOLUME_PARAM vec4 v0, uint e0, vec4 v1, uint e1, int a, vec3 cell, vec3 p, vec3 d,
                              float halfStep, vec2 cap, bool mainAxis) {
    vec3 next = cell;
    next[a] += 1.0f;
    float s0 = cone_sheetSeen(v0, e0, a, cell, p, d, halfStep, cap, mainAxis);
    float s1 = cone_sheetSeen(v1, e1, a, next, p, d, halfStep, cap, mainAxis);
    float seen = max(s0, s1);
    if (!(seen > 0.0f)) return vec4(0.0f);
    return vec4(CONE_VOLUME_SHEET_LIGHT(ivec3(s0 >= s1 ? cell : next)) * seen, seen);
}

CONE_VOLUME_TEMPLATE
CONE_FN vec4 cone_sampleSheets(CONE_VOLUME_PARAM vec3 p, vec3 d, float lod, float dt, vec2 cap) {
    vec3 c0 = floor(p - vec3(0.5f));
    ivec3 i0 = ivec3(c0);
    vec4 t0 = CONE_VOLUME_SHEET(i0);
    vec4 t1 = CONE_VOLUME_SHEET(i0 + ivec3(1, 0, 0));
    vec4 t2 = CONE_VOLUME_SHEET(i0 + ivec3(0, 1, 0));
    vec4 t3 = CONE_VOLUME_SHEET(i0 + ivec3(1, 1, 0));
    vec4 t4 = CONE_VOLUME_SHEET(i0 + ivec3(0, 0, 1));
    vec4 t5 = CONE_VOLUME_SHEET(i0 + ivec3(1, 0, 1));
    vec4 t6 = CONE_VOLUME_SHEET(i0 + ivec3(0, 1, 1));
    vec4 t7 = CONE_VOLUME_SHEET(i0 + ivec3(1, 1, 1));
    uint e0 = CONE_VOLUME_SHEET_EXTENT(i0);
    uint e1 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(1, 0, 0));
    uint e2 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(0, 1, 0));
    uint e3 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(1, 1, 0));
    uint e4 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(0, 0, 1));
    uint e5 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(1, 0, 1));
    uint e6 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(0, 1, 1));
    uint e7 = CONE_VOLUME_SHEET_EXTENT(i0 + ivec3(1, 1, 1));
    // Per axis, the four columns across it; boxes on the lane's main axis alone.
    vec3 ad = abs(d);
    bool mx = ad.x >= ad.y && ad.x >= ad.z, my = !mx && ad.y >= ad.z, mz = !mx && !my;
    vec3 cx = c0 + vec3(1.0f, 0.0f, 0.0f), cy = c0 + vec3(0.0f, 1.0f, 0.0f), cz = c0 + vec3(0.0f, 0.0f, 1.0f);
    vec3 cyz = c0 + vec3(0.0f, 1.0f, 1.0f), cxz = c0 + vec3(1.0f, 0.0f, 1.0f), cxy = c0 + vec3(1.0f, 1.0f, 0.0f);
    float hs = 0.5f * dt;
    vec4 seen = cone_sheetColumn(CONE_VOLUME_ARG t0, e0, t1, e1, 0, c0, p, d, hs, cap, mx) +
                cone_sheetColumn(CONE_VOLUME_ARG t2, e2, t3, e3, 0, cy, p, d, hs, cap, mx) +
                cone_sheetColumn(CONE_VOLUME_ARG t4, e4, t5, e5, 0, cz, p, d, hs, cap, mx) +
                cone_sheetColumn(CONE_VOLUME_ARG t6, e6, t7, e7, 0, cyz, p, d, hs, cap, mx) +
                cone_sheetColumn(CONE_VOLUME_ARG t0, e0, t2, e2, 1, c0, p, d, hs, cap, my) +
                cone_sheetColumn(CONE_VOLUME_ARG t1, e1, t3, e3, 1, cx, p, d, hs, cap, my) +
                cone_sheetColumn(CONE_VOLUME_ARG t4, e4, t6, e6, 1, cz, p, d, hs, cap, my) +
                cone_sheetColumn(CONE_VOLUME_ARG t5, e5, t7, e7, 1, cxz, p, d, hs, cap, my) +
                cone_sheetColumn(CONE_VOLUME_ARG t0, e0, t4, e4, 2, c0, p, d, hs, cap, mz) +
                cone_sheetColumn(CONE_VOLUME_ARG t1, e1, t5, e5, 2, cx, p, d, hs, cap, mz) +
                cone_sheetColumn(CONE_VOLUME_ARG t2, e2, t6, e6, 2, cy, p, d, hs, cap, mz) +
                cone_sheetColumn(CONE_VOLUME_ARG t3, e3, t7, e7, 2, cxy, p, d, hs, cap, mz);
    float blocked = seen.w;
    float texel = exp2(max(lod, 0.0f));
    float sheetLogT = log2(max(1.0f - min(blocked, 1.0f), 1.0e-7f)) * (texel / dt);
    float alpha = 1.0f - exp2(sheetLogT);
    // The light of what the step sees, each voxel's own weighted by what it sees of it.
    return vec4(vec3(seen) * (alpha / max(blocked, 1.0e-7f)), alpha);
}

// GI over sheets: the offset of a pixel's lanes' start up ng from voxel-space point p:
// CONE_SHEET_START (at most `offset`) where no other surface is near, else `offset`, which the
// trilinear base has always needed to clear a surface's voxels. Near is a box (a voxel without a
// sheet, where sheets of two axes meet: a wall's foot) or a sheet across another axis than ng's
// in the 3 x 3 x 3 voxels about that start: a box's extent is met by every lane's first step
// there, the lanes that head away from its surfaces too, and the light of a wall's foot is
// that voxel's, the dark floor's with the wall's.
CONE_VOLUME_TEMPLATE
CONE_FN float cone_sheetStartOffset(CONE_VOLUME_PARAM vec3 p, vec3 ng, float offset) {
    float lifted = min(offset, CONE_SHEET_START);
    ivec3 c = ivec3(floor(p + ng * lifted));
    vec3 an = abs(ng);
    int axis = an.x >= an.y && an.x >= an.z ? 0 : an.y >= an.z ? 1 : 2;
    bool near = false;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                vec4 s = CONE_VOLUME_SHEET(c + ivec3(x, y, z));
                near = near || (s.x > 0.0f && int(s.w) != axis);
            }
    return near ? offset : lifted;
}
#endif

// The settings a march reads besides its volume (ConeUniforms::march and ::limits).
struct ConeMarch {
    float tanHalfAperture;  // tan(aperture / 2), times 2^(vct.level-bias): the level of the footprint at t is
                            // log2(2 t tanHalfAperture)
    float stepFactor;       // beta: each step is beta footprints long
    float maxAlpha;         // the cone closes at this opacity (cone_close)
    float planeRatio;       // plane limit: texels of at most h / ratio voxels at height h; 0 = off
    vec3 levelBase;         // voxels per axis of level 0, for the plane limit's texel size (0: 2^lod)
    float endRatio;         // vct.end-taper: texels of at most (maxDist - t) / endRatio voxels; 0 = off
    float capTan;           // vct.voxel.edges=sheet: tan of a lane's half-aperture, for its cap
                            // (cone_sampleSheets); 0 = off
};

// The longest edge, in level-0 voxels, of a texel of level `level` (the volume's GL mip sizes:
// each axis halved rounding down, never below 1). On an axis that is not a multiple of
// 2^level a texel spans size / floor(size / 2^level) voxels, more than 2^level: a grid 127
// voxels tall has 3 texels of 42.3 at level 5, not 32, and the base level's voxels reach up
// to 1.5 of those. A zero base means texels of exactly 2^level.
CONE_FN float cone_texelExtent(vec3 base, float level) {
    if (!(base.x > 0.0f)) return exp2(level);
    vec3 size = max(floor(base * exp2(-level)), vec3(1.0f));
    vec3 e = base / size;
    return max(e.x, max(e.y, e.z));
}

// The footprint's level of detail at distance t: diameter 2 t tan(aperture / 2), at least one
// voxel; with the plane limit, whole levels whose texels (cone_texelExtent) are at most h / ratio
// voxels at height h = h0 + t rise above the tangent plane (a fractional level would blend in
// the next, coarser one).
CONE_FN float cone_footprintLod(ConeMarch m, float t, float h0, float rise) {
    float lod = log2(max(1.0f, 2.0f * t * m.tanHalfAperture));
    if (m.planeRatio > 0.0f) {
        float reach = max(1.0f, (h0 + t * rise) / m.planeRatio);
        float cap = floor(log2(reach));
        // The texels a level really has, which exceed 2^level on an axis that is not a
        // power-of-two multiple (a fitted grid's short axis).
        while (cap > 0.0f && cone_texelExtent(m.levelBase, cap) > reach) cap -= 1.0f;
        lod = min(lod, cap);
    }
    return lod;
}

// True once the footprint at p (volume coordinates, box [0, size]; one texel of trilinear
// reach past half a texel: `reach`) is outside the volume and moving away along d: the zero
// border means only sky remains.
CONE_FN bool cone_leaving(vec3 p, vec3 d, vec3 size, float reach) {
    bvec3 below = lessThan(p, vec3(-reach));
    bvec3 above = greaterThan(p, size + reach);
    return any(bvec3(below.x && d.x <= 0.0f, below.y && d.y <= 0.0f, below.z && d.z <= 0.0f)) ||
           any(bvec3(above.x && d.x >= 0.0f, above.y && d.y >= 0.0f, above.z && d.z >= 0.0f));
}

// Marches from `origin` (voxel units) along unit `d`. `h0` is the origin's height above the
// shading point's tangent plane and `rise` = dot(d, geometric normal), both for the plane
// limit; `maxDist` (voxels) limits the distance (R for AO); `falloff` is lambda (AO only).
// The step's length follows the footprint at its start; the sample sits at its middle,
// where the volume may ask for a coarser level (a clipmap near a level's border).
CONE_VOLUME_TEMPLATE
CONE_FN ConeResult cone_marchVolume(CONE_VOLUME_PARAM ConeMarch m, vec3 origin, vec3 d, float h0, float rise,
                                    float maxDist, float falloff) {
    ConeResult r;
    r.radiance = vec3(0.0f);
    r.alpha = 0.0f;
    r.samples = 0.0f;
    float t = 0.0f;
    // Lane caps (cone_sampleSheets): the zone about maxDist at the base level, to its far end.
    float zone = cone_capZone(maxDist, m.capTan);
    float end = maxDist + zone;
    for (int i = 0; i < CONE_MAX_STEPS; ++i) {
        if (t >= end || r.alpha >= m.maxAlpha) break;
        float lod = cone_footprintLod(m, t, h0, rise);
        // vct.end-taper: whole levels whose texel, sampled half a step on, reaches no further
        // than maxDist (a trilinear sample sees one texel past its centre).
        if (m.endRatio > 0.0f) lod = min(lod, floor(log2(max(1.0f, (maxDist - t) / m.endRatio))));
        if (zone > 0.0f && t >= maxDist - zone) lod = 0.0f;
        lod = CONE_VOLUME_LOD(lod, origin + d * t);
        // A step ends at maxDist, and (caps) the next ones at the zone's end.
        float dt = min(m.stepFactor * exp2(lod), (t < maxDist ? maxDist : end) - t);
        vec3 p = origin + d * (t + 0.5f * dt);
        lod = CONE_VOLUME_LOD(lod, p);
        float texel = exp2(lod);

        if (CONE_VOLUME_LEAVING(p, d, texel)) break;

        vec4 s = CONE_VOLUME_SAMPLE(p, d, lod, dt, vec2(maxDist - (t + 0.5f * dt), maxDist * m.capTan));
        r.samples += 1.0f;
        s = vec4(vec3(s) * CONE_VOLUME_FACING(p, d, lod, s), s.a);
        cone_composite(r, s, dt, texel, t + 0.5f * dt, falloff);
        t += dt;
    }
    cone_close(r, m.maxAlpha);
    return r;
}

VCT_END_NAMESPACE
