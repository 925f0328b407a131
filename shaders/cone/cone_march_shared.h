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
//   sample(p, d, lod, dt)  premultiplied (radiance, alpha) at p, footprint 2^lod voxels, for a
//                          step of dt voxels (which the sample sits in the middle of)
//   facing(p, d, lod, s)   the weight of sample s's radiance for a cone along d (GI's facing
//                          rule; 1 where the volume has none)
// and, for cone_sampleSheets (vct.voxel.edges=sheet), sheet(v), the base level's sheet texel.
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
#define CONE_VOLUME_SAMPLE(p, d, l, dt) volume.sample(p, d, l, dt)
#define CONE_VOLUME_FACING(p, d, l, s) volume.facing(p, d, l, s)
#define CONE_VOLUME_SHEET(v) volume.sheet(v)
#else
#define CONE_VOLUME_TEMPLATE
#define CONE_VOLUME_PARAM
#define CONE_VOLUME_ARG
#define CONE_VOLUME_LOD(l, x) cone_volumeLod(l, x)
#define CONE_VOLUME_LEAVING(p, d, texel) cone_volumeLeaving(p, d, texel)
#define CONE_VOLUME_SAMPLE(p, d, l, dt) cone_volumeSample(p, d, l, dt)
#define CONE_VOLUME_FACING(p, d, l, s) cone_volumeFacing(p, d, l, s)
#define CONE_VOLUME_SHEET(v) cone_volumeSheet(v)
#ifdef CONE_SHEETS
vec4 cone_volumeSheet(ivec3 v);
#endif
float cone_volumeLod(float lod, vec3 x);
bool cone_volumeLeaving(vec3 p, vec3 d, float texel);
vec4 cone_volumeSample(vec3 p, vec3 d, float lod, float dt);
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
// voxel counts where [lo - h, hi + h] (h = dt |d_a| / 2) holds p's coordinate, with the linear
// tent across a (the share of the lane its column covers). Consecutive steps tile the lane, so
// one crossing is seen once, the share the lane's cap crosses of it. Two voxels of one column
// along a can hold the same sheet (one lying on the face between them), so each column counts
// its larger. Voxels without a sheet keep the sharpened fetches of the plain base level
// (cone_sharpenTexel along each axis, blended by cone_blendDirectional). The sheets' share
// composites with the rest as transmittances, and is written so that the march's step
// correction (alpha' = 1 - (1 - alpha)^(dt / texel)) returns it.
// `dt` is the sample's step, `texel` its texel edge, `s` vct.sharpen (1: linear).
// The loops are written out: llvmpipe counts every loop iteration of an invocation against the
// march's budget (coneLoopBound).
#if defined(__cplusplus) || defined(CONE_SHEETS)
// Opacity of a texel without a sheet, 0 for a sheet's.
CONE_FN float cone_plainOpacity(vec4 v) { return v.w < 0.0f ? v.x : 0.0f; }
// Trilinear over the eight corners (corner c = x + 2 y + 4 z; lo = corners 0..3, hi = 4..7).
CONE_FN float cone_trilinear8(vec4 lo, vec4 hi, vec3 w) {
    vec2 a = mix(vec2(lo.x, lo.z), vec2(lo.y, lo.w), w.x);
    vec2 b = mix(vec2(hi.x, hi.z), vec2(hi.y, hi.w), w.x);
    return mix(mix(a.x, a.y, w.y), mix(b.x, b.y, w.y), w.z);
}
// The opacity texel v of voxel k along axis a holds, if its sheet is of axis a and its span
// [k + lo, k + hi] meets the step's [x - h, x + h]; else 0.
CONE_FN float cone_sheetCrossed(vec4 v, int a, float k, float x, float h) {
    return (v.w >= 0.0f && int(v.w) == a && x + h >= k + v.y && x - h <= k + v.z) ? v.x : 0.0f;
}
// One column along axis a: its two voxels k and k + 1, counted once (the larger), weighted by
// the tent across a.
CONE_FN float cone_sheetColumn(vec4 v0, vec4 v1, int a, float k, float x, float h, float w) {
    return w * max(cone_sheetCrossed(v0, a, k, x, h), cone_sheetCrossed(v1, a, k + 1.0f, x, h));
}

CONE_VOLUME_TEMPLATE
CONE_FN float cone_sampleSheets(CONE_VOLUME_PARAM vec3 p, vec3 d, float dt, float texel, float s) {
    vec3 x = p - vec3(0.5f);
    vec3 c0 = floor(x);
    ivec3 i0 = ivec3(c0);
    vec3 f = x - c0;
    vec4 t0 = CONE_VOLUME_SHEET(i0);
    vec4 t1 = CONE_VOLUME_SHEET(i0 + ivec3(1, 0, 0));
    vec4 t2 = CONE_VOLUME_SHEET(i0 + ivec3(0, 1, 0));
    vec4 t3 = CONE_VOLUME_SHEET(i0 + ivec3(1, 1, 0));
    vec4 t4 = CONE_VOLUME_SHEET(i0 + ivec3(0, 0, 1));
    vec4 t5 = CONE_VOLUME_SHEET(i0 + ivec3(1, 0, 1));
    vec4 t6 = CONE_VOLUME_SHEET(i0 + ivec3(0, 1, 1));
    vec4 t7 = CONE_VOLUME_SHEET(i0 + ivec3(1, 1, 1));
    // The voxels without a sheet: one sharpened trilinear sum per axis, blended as optical depth.
    vec4 lo = vec4(cone_plainOpacity(t0), cone_plainOpacity(t1), cone_plainOpacity(t2), cone_plainOpacity(t3));
    vec4 hi = vec4(cone_plainOpacity(t4), cone_plainOpacity(t5), cone_plainOpacity(t6), cone_plainOpacity(t7));
    vec3 g = clamp((f - vec3(0.5f)) * s + vec3(0.5f), vec3(0.0f), vec3(1.0f));
    vec3 axisAlpha = vec3(cone_trilinear8(lo, hi, vec3(g.x, f.y, f.z)), cone_trilinear8(lo, hi, vec3(f.x, g.y, f.z)),
                          cone_trilinear8(lo, hi, vec3(f.x, f.y, g.z)));
    float plainLogT = cone_blendedLogTransmittance(cone_anisoWeights(d), axisAlpha);
    // The sheets: per axis, the four columns across it.
    vec3 h = 0.5f * dt * abs(d);
    vec3 e = vec3(1.0f) - f;
    float blocked = cone_sheetColumn(t0, t1, 0, c0.x, p.x, h.x, e.y * e.z) +
                    cone_sheetColumn(t2, t3, 0, c0.x, p.x, h.x, f.y * e.z) +
                    cone_sheetColumn(t4, t5, 0, c0.x, p.x, h.x, e.y * f.z) +
                    cone_sheetColumn(t6, t7, 0, c0.x, p.x, h.x, f.y * f.z) +
                    cone_sheetColumn(t0, t2, 1, c0.y, p.y, h.y, e.x * e.z) +
                    cone_sheetColumn(t1, t3, 1, c0.y, p.y, h.y, f.x * e.z) +
                    cone_sheetColumn(t4, t6, 1, c0.y, p.y, h.y, e.x * f.z) +
                    cone_sheetColumn(t5, t7, 1, c0.y, p.y, h.y, f.x * f.z) +
                    cone_sheetColumn(t0, t4, 2, c0.z, p.z, h.z, e.x * e.y) +
                    cone_sheetColumn(t1, t5, 2, c0.z, p.z, h.z, f.x * e.y) +
                    cone_sheetColumn(t2, t6, 2, c0.z, p.z, h.z, e.x * f.y) +
                    cone_sheetColumn(t3, t7, 2, c0.z, p.z, h.z, f.x * f.y);
    float sheetLogT = log2(max(1.0f - min(blocked, 1.0f), 1.0e-7f)) * (texel / dt);
    return 1.0f - exp2(plainLogT + sheetLogT);
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
    for (int i = 0; i < CONE_MAX_STEPS; ++i) {
        if (t >= maxDist || r.alpha >= m.maxAlpha) break;
        float lod = cone_footprintLod(m, t, h0, rise);
        // vct.end-taper: whole levels whose texel, sampled half a step on, reaches no further
        // than maxDist (a trilinear sample sees one texel past its centre).
        if (m.endRatio > 0.0f) lod = min(lod, floor(log2(max(1.0f, (maxDist - t) / m.endRatio))));
        lod = CONE_VOLUME_LOD(lod, origin + d * t);
        float dt = min(m.stepFactor * exp2(lod), maxDist - t);
        vec3 p = origin + d * (t + 0.5f * dt);
        lod = CONE_VOLUME_LOD(lod, p);
        float texel = exp2(lod);

        if (CONE_VOLUME_LEAVING(p, d, texel)) break;

        vec4 s = CONE_VOLUME_SAMPLE(p, d, lod, dt);
        r.samples += 1.0f;
        s = vec4(vec3(s) * CONE_VOLUME_FACING(p, d, lod, s), s.a);
        cone_composite(r, s, dt, texel, t + 0.5f * dt, falloff);
        t += dt;
    }
    cone_close(r, m.maxAlpha);
    return r;
}

VCT_END_NAMESPACE
