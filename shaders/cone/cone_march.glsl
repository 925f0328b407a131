// The dense voxel grid as cone_marchVolume (cone_march_shared.h) reads it: 3D textures with
// mips, in voxel units (world / voxelSize, origin at the grid's min corner).
//
// Defines: CONE_GI (1: premultiplied radiance + alpha from grid.radiance; 0: alpha only from
// grid.opacity), CONE_ANISO (1: blend the six directional textures above level 0),
// CONE_ANISO_PACKED (AO over an AO grid: the three axes' directional opacity in one texture,
// the same both ways along an axis: VoxelGrid::anisoOpacity), CONE_DEPTH_LEVELS (the
// directional levels hold optical depth, opacity_depth.h), CONE_SHARPEN (vct.sharpen > 1: each
// axis fetched at its own coordinate, sharpened along it, and the two levels of a fractional
// lod blended by hand), CONE_SHEETS (vct.voxel.edges=sheet: the base level's opacity read from
// the sheet texels, cone_sampleSheets; GI's light that of the voxels whose sheets a step
// sees). The depth levels are a compiled variant, not a uniform branch: llvmpipe paid for the
// untaken branch's code in every sample (AO 512^2 at trace-scale=4: trace stage 90 ms with the
// branch, 62 ms without).
#include "cone/cone_common.glsl"
#include "voxelize/opacity_depth.h"

#ifdef CONE_SHEETS
// Whether voxel v lies outside the grid, where the sheet reads below find nothing.
bool cone_outsideGrid(ivec3 v) {
    return any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(u.gridResolution.xyz)));
}
layout(binding = CONE_UNIT_SHEETS) uniform sampler3D cone_sheetTexture;
// cone_sampleSheets' texel of voxel v (VoxelGrid::sheets); outside the grid none.
vec4 cone_volumeSheet(ivec3 v) {
    if (cone_outsideGrid(v)) return vec4(0.0, 0.0, 0.0, -1.0);
    return texelFetch(cone_sheetTexture, v, 0);
}
layout(binding = CONE_UNIT_SHEET_EXTENTS) uniform usampler3D cone_sheetExtentTexture;
// Its extent bits (VoxelGrid::sheetExtents); outside the grid none (the whole voxel).
uint cone_volumeSheetExtent(ivec3 v) {
    if (cone_outsideGrid(v)) return 0u;
    return texelFetch(cone_sheetExtentTexture, v, 0).r;
}
#endif

layout(binding = CONE_UNIT_OPACITY) uniform sampler3D cone_isoTexture;
#if CONE_GI
layout(binding = CONE_UNIT_NORMAL) uniform sampler3D cone_normalTexture;
#endif
#if CONE_ANISO && defined(CONE_ANISO_PACKED)
layout(binding = CONE_UNIT_ANISO) uniform sampler3D cone_anisoOpacity;  // rgb: along X, Y, Z
#elif CONE_ANISO
layout(binding = CONE_UNIT_ANISO + 0) uniform sampler3D cone_anisoPX;
layout(binding = CONE_UNIT_ANISO + 1) uniform sampler3D cone_anisoNX;
layout(binding = CONE_UNIT_ANISO + 2) uniform sampler3D cone_anisoPY;
layout(binding = CONE_UNIT_ANISO + 3) uniform sampler3D cone_anisoNY;
layout(binding = CONE_UNIT_ANISO + 4) uniform sampler3D cone_anisoPZ;
layout(binding = CONE_UNIT_ANISO + 5) uniform sampler3D cone_anisoNZ;
#endif

#ifdef CONE_SHEETS
// cone_sampleSheets' light leaving voxel v: its base-level radiance over its opacity (GI; the
// texel is premultiplied), none for AO or outside the grid. One fetch, made only for a voxel
// whose sheet a step sees.
vec3 cone_volumeSheetLight(ivec3 v) {
#if CONE_GI
    if (cone_outsideGrid(v)) return vec3(0.0);
    cone_fetches += 1.0;
    vec4 r = texelFetch(cone_isoTexture, v, 0);
    return r.rgb / max(r.a, 1.0e-4);
#else
    return vec3(0.0);
#endif
}
#endif

vec4 cone_sampleIso(vec3 tc, float lod) {
    cone_fetches += 1.0;
#if CONE_GI
    return textureLod(cone_isoTexture, tc, lod);
#else
    return vec4(0.0, 0.0, 0.0, textureLod(cone_isoTexture, tc, lod).r);
#endif
}

#if CONE_ANISO && defined(CONE_SHARPEN)
// vct.sharpen (u.camera.w): tc moved along `axis`, on a level `size` texels long on that axis,
// so that linear filtering gives cone_sharpenTexel's weights there.
vec3 cone_sharpenAlong(vec3 tc, int axis, float size) {
    tc[axis] = cone_sharpenTexel(tc[axis] * size, u.camera.w) / size;
    return tc;
}

// Axis `axis` of the directional levels at texture level `level` (pyramid level + 1), sharpened
// along that axis; the level's texels follow GL's mip sizes.
vec4 cone_fetchSharpened(int axis, bool positive, vec3 tc, float level) {
    tc = cone_sharpenAlong(tc, axis, max(floor(u.gridResolution[axis] * exp2(-(level + 1.0))), 1.0));
    cone_fetches += 1.0;
#ifdef CONE_ANISO_PACKED
    return vec4(0.0, 0.0, 0.0, textureLod(cone_anisoOpacity, tc, level)[axis]);
#else
    if (axis == 0) return positive ? textureLod(cone_anisoPX, tc, level) : textureLod(cone_anisoNX, tc, level);
    if (axis == 1) return positive ? textureLod(cone_anisoPY, tc, level) : textureLod(cone_anisoNY, tc, level);
    return positive ? textureLod(cone_anisoPZ, tc, level) : textureLod(cone_anisoNZ, tc, level);
#endif
}

// One axis at fractional level `lod`: each of the two levels at its own sharpened coordinate,
// blended as trilinear filtering blends them (the sparse backend's order).
vec4 cone_sampleAxisSharpened(int axis, bool positive, vec3 tc, float lod) {
    float l0 = floor(lod);
    vec4 s = cone_fetchSharpened(axis, positive, tc, l0);
    if (lod > l0) s = mix(s, cone_fetchSharpened(axis, positive, tc, l0 + 1.0), lod - l0);
    return s;
}
#endif

#if CONE_ANISO && defined(CONE_SHARPEN)
// The base level as a cone travelling along d crosses it. The base is isotropic, so it is
// fetched once per axis, each fetch sharpened along its own axis, and the three blend as the
// directional levels' axes do: a one-voxel sheet is a box along its normal to the axis that
// crosses it, where one linear fetch would be a tent that lets a narrow cone (a footprint below
// a voxel) through. Three fetches written out: a loop would count against llvmpipe's
// per-invocation iteration limit that coneLoopBound budgets.
vec4 cone_sampleBaseSharpened(vec3 tc, vec3 d) {
    vec4 x = cone_sampleIso(cone_sharpenAlong(tc, 0, u.gridResolution.x), 0.0);
    vec4 y = cone_sampleIso(cone_sharpenAlong(tc, 1, u.gridResolution.y), 0.0);
    vec4 z = cone_sampleIso(cone_sharpenAlong(tc, 2, u.gridResolution.z), 0.0);
    return cone_blendDirectional(cone_anisoWeights(d), x, y, z);
}
#endif

#if CONE_ANISO
// The base level at a sample of direction d, voxel-space p, footprint 2^lod, step dt: the sheet
// texels and their extent bits (CONE_SHEETS: sixteen fetches; GI's light one more a voxel seen),
// sharpened (vct.sharpen) or one linear fetch.
vec4 cone_sampleBase(vec3 p, vec3 tc, vec3 d, float lod, float dt, vec2 cap) {
#if defined(CONE_SHEETS)
    cone_fetches += 16.0;
    return cone_sampleSheets(p, d, lod, dt, cap);
#elif defined(CONE_SHARPEN)
    return cone_sampleBaseSharpened(tc, d);
#else
    return cone_sampleIso(tc, 0.0);
#endif
}

// Directional level `lod` (= pyramid level lod + 1) as seen by a cone travelling along d.
vec4 cone_sampleAniso(vec3 tc, vec3 d, float lod) {
    vec3 w = cone_anisoWeights(d);
#if defined(CONE_SHARPEN)
    vec4 x = cone_sampleAxisSharpened(0, d.x >= 0.0, tc, lod);
    vec4 y = cone_sampleAxisSharpened(1, d.y >= 0.0, tc, lod);
    vec4 z = cone_sampleAxisSharpened(2, d.z >= 0.0, tc, lod);
#elif defined(CONE_ANISO_PACKED)
    // The three axes in one fetch (an RGBA fetch costs about what a single-channel one does).
    cone_fetches += 1.0;
    vec3 axes = textureLod(cone_anisoOpacity, tc, lod).rgb;
    vec4 x = vec4(0.0, 0.0, 0.0, axes.x);
    vec4 y = vec4(0.0, 0.0, 0.0, axes.y);
    vec4 z = vec4(0.0, 0.0, 0.0, axes.z);
#else
    cone_fetches += 3.0;
    vec4 x = d.x >= 0.0 ? textureLod(cone_anisoPX, tc, lod) : textureLod(cone_anisoNX, tc, lod);
    vec4 y = d.y >= 0.0 ? textureLod(cone_anisoPY, tc, lod) : textureLod(cone_anisoNY, tc, lod);
    vec4 z = d.z >= 0.0 ? textureLod(cone_anisoPZ, tc, lod) : textureLod(cone_anisoNZ, tc, lod);
#endif
#ifdef CONE_DEPTH_LEVELS
    // Optical-depth levels: filtered as depth, composited as opacity.
    x = vox_alphaFromDepth(x);
    y = vox_alphaFromDepth(y);
    z = vox_alphaFromDepth(z);
#endif
    return cone_blendDirectional(w, x, y, z);
}
#endif

// Premultiplied (radiance, alpha) of the grid at voxel-space point p, footprint 2^lod voxels,
// step dt, lane cap `cap` (cone_sampleSheets).
vec4 cone_sampleGrid(vec3 p, vec3 d, float lod, float dt, vec2 cap) {
    vec3 tc = p / u.gridResolution.xyz;
#if CONE_ANISO
    vec4 directional = cone_sampleAniso(tc, d, max(lod - 1.0, 0.0));
    // Between the base level and the first directional level: blend as trilinear
    // filtering blends two mip levels. (One directional fetch on both paths: on SIMD
    // hardware and llvmpipe a divergent branch would run both.)
    if (lod < 1.0) {
#ifdef CONE_DEPTH_LEVELS
        // With optical-depth levels the two levels blend as depth (the base level's 0 / 1
        // voxels filter to VOX_DEPTH_MAX times their opacity).
        directional = vox_alphaFromDepth(mix(vox_depthFromCoverage(cone_sampleBase(p, tc, d, lod, dt, cap)),
                                             vox_depthFromAlpha(directional), lod));
#else
        directional = mix(cone_sampleBase(p, tc, d, lod, dt, cap), directional, lod);
#endif
    }
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
    cone_fetches += 1.0;
    vec4 n = textureLod(cone_normalTexture, p / u.gridResolution.xyz, lod);
    return vox_facingWeight(n.xyz / max(n.w, 1e-4), d);
}
#endif

// The volume of cone_marchVolume: the grid's mips up to the coarsest, its box, and (GI) the
// facing rule.
float cone_volumeLod(float lod, vec3 x) { return min(lod, u.gridResolution.w - 1.0); }

bool cone_volumeLeaving(vec3 p, vec3 d, float texel) {
    return cone_leaving(p, d, u.gridResolution.xyz, 1.5 * texel);
}

vec4 cone_volumeSample(vec3 p, vec3 d, float lod, float dt, vec2 cap) { return cone_sampleGrid(p, d, lod, dt, cap); }

float cone_volumeFacing(vec3 p, vec3 d, float lod, vec4 s) {
#if CONE_GI
    return cone_facing(p, d, lod);
#else
    return 1.0;
#endif
}

ConeGather cone_gather(ConeGather g, vec3 pWorld, vec3 n, vec3 ng, float maxDist, float falloff, float sky) {
    // voxelFromWorld is a uniform scale plus a translation: directions keep their length.
    vec3 p = (u.voxelFromWorld * vec4(pWorld, 1.0)).xyz;
#if defined(CONE_SHEETS) && CONE_GI
    if ((u.trace.w & CONE_SPLIT_RESUME) == 0) cone_fetches += CONE_SHEET_START_FETCHES;  // once a pixel, as the sparse gather counts
    float offset = cone_sheetStartOffset(p, ng, u.march.z);
#else
    float offset = u.march.z;
#endif
    return cone_gatherVoxel(g, p, n, ng, offset, offset, maxDist, falloff, sky);
}
