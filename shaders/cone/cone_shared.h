// Constants and the uniform block shared by src/cone/*.cpp and shaders/cone/*.glsl (the
// XeGTAO.h pattern): one std140 struct with explicit vec4 packing, the work-group size used
// by both `layout(local_size...)` and the dispatch math, texture units, and the DEFAULT_*
// values of ConeSettings with the reason for each.
#pragma once
#include "common/loop_budget.h"
#include "common/shared_types.h"
#include "voxelize/voxelize_shared.h"

#ifdef __cplusplus
#define CONE_FN inline
#else
#define CONE_FN
#endif

VCT_BEGIN_NAMESPACE

// 8x8 pixels per work group: a square tile keeps neighbouring pixels' cones in the same
// voxels (texture cache on a GPU, SIMD lanes on llvmpipe).
VCT_CONST int CONE_LOCAL_SIZE = 8;

// Cones per march after splitting into lanes (src/cone/cone_set.h). A pass whose cones do not
// fit one dispatch marches them over several (CONE_LOOP_BUDGET), so this bounds cost, not the
// uniform block: 64 lanes of the 64-cone set, or 256 lanes (auto at 512^3) of the 16-cone one.
VCT_CONST int CONE_MAX_CONES = 4096;
// Cones in a set (vct.cones) before it is split into lanes: the uniform block holds their axes,
// which decide whether a lane below the surface's plane is open (src/cone/cone_set.h).
VCT_CONST int CONE_MAX_SET_CONES = 64;
// Cones in the uniform block: the slice of the set one dispatch marches. 512 vec4 = 8 KiB,
// half of the 16 KiB GL 4.5 guarantees.
VCT_CONST int CONE_BLOCK_CONES = 512;
// Loop iterations one cone pass's invocation may run (common/loop_budget.h). 16 cones x 62
// lanes of about 100 steps gave AO 0.13 off the sparse path's value when llvmpipe ended the
// loops. A pass marches as many cones per dispatch as its bound on a cone's loop iterations
// (coneLoopBound, src/cone/cone_budget.h) lets fit this budget, and carries each gather's sums
// to the next dispatch (cone_common.glsl): the same sums in the same order as one dispatch.
VCT_CONST int CONE_LOOP_BUDGET = SHADER_LOOP_BUDGET;
// vct.lanes = auto: one lane per cone at 32^3, (res / 32)^2 lanes above, so a lane's
// footprint at R spans the same number of voxels at every resolution (4.6 voxels for a
// 60-degree cone at R = 4 voxels, i.e. R = 1/8 of a 32^3 grid). vct.lanes-base moves the
// resolution of one lane per cone: 16 gives four times the lanes, each half as wide, whose
// footprint at a given distance spans half the voxels.
VCT_CONST int CONE_LANES_BASE_RES = 32;
VCT_CONST int CONE_LANES_BASE_MIN = 4;
VCT_CONST int CONE_LANES_BASE_MAX = 1024;
// Safety bound on samples per cone (apertures near 1 degree step one half voxel at a time):
// 1024 half-voxel steps cross a 512^3 grid's diagonal.
VCT_CONST int CONE_MAX_STEPS = 1024;

// Texture units. The G-buffer occupies units 0-5 (render/gbuffer.h); scene textures 8.
VCT_CONST int CONE_UNIT_OPACITY = 10;   // grid.opacity (AO, iso) or grid.radiance (GI, iso)
VCT_CONST int CONE_UNIT_ANISO = 11;     // 11..16: grid.anisoRadiance[+X, -X, +Y, -Y, +Z, -Z]
VCT_CONST int CONE_UNIT_COLOR = 17;     // rayMarchVoxels: albedo or radiance
VCT_CONST int CONE_UNIT_NORMAL = 18;    // GI: grid.normal (mipmapped), for the facing test
VCT_CONST int CONE_UNIT_BOUNCE_DIRECT = 19;  // cone_bounce.glsl: emission + direct light (level 0)
VCT_CONST int CONE_UNIT_BOUNCE_ALBEDO = 20;  // cone_bounce.glsl: grid.albedo
VCT_CONST int CONE_UNIT_BOUNCE_EMISSION = 21;  // cone_bounce.glsl: grid.emission (BOUNCE_EMITTED)
VCT_CONST int CONE_UNIT_SHEETS = 22;  // pixel passes with vct.voxel.edges=sheet: grid.sheets (CONE_SHEETS)
VCT_CONST int CONE_UNIT_SHEET_EXTENTS = 23;  // and grid.sheetExtents
VCT_CONST int CONE_IMAGE_OUTPUT = 0;    // image unit of the output texture
VCT_CONST int CONE_UBO_BINDING = 0;
// A gather split over dispatches: its running sums per pixel (or listed voxel), read by the
// next dispatch. Binding 5 is a scene buffer's (scene_shared.h) in the passes that read the
// scene; the cone passes read none.
VCT_CONST int CONE_BINDING_CARRY = 5;
// ConeUniforms::trace.w, split gathers: this dispatch resumes the sums a previous one carried,
// and carries its own on to a next one.
VCT_CONST int CONE_SPLIT_RESUME = 1;
VCT_CONST int CONE_SPLIT_CARRY = 2;
VCT_CONST int CONE_BINDING_COUNTS = 6;      // cone_ao/gi.glsl: per-pixel (samples, fetches)
VCT_CONST int CONE_BINDING_VOXEL_LIST = 7;  // cone_bounce.glsl: SSBO of the voxels that gather
VCT_CONST int CONE_BOUNCE_GROUP = 64;       // cone_bounce.glsl: invocations per group over the list

// Reduced-resolution cone passes (vct.trace-scale = s > 1): the trace stage marches the cones
// of one pixel per s x s block (cone_tracedPixel) into a traced image of ceil(size / s); the
// resolve stage (cone_resolve.glsl) gives every surface pixel the traced values of its nearest
// blocks weighted bilinearly and by how well each block's pixel shares its surface (normal and
// tangent plane), and lists the pixel for the own stage when none does. Engines ship VCT this
// way: the cone pass costs about 1 / s^2 of a full-resolution one, and what it gathers varies
// over distances of voxels and R, not pixels.
VCT_CONST int CONE_STAGE_TRACE = 0;
VCT_CONST int CONE_STAGE_RESOLVE = 1;
// The pixels the resolve found no block for trace their own cones in a third stage, over the
// list the resolve appended them to (cone_listPixels), not in the resolve itself: a branch
// that holds a whole cone march costs a SIMD machine in every resolve invocation, even when
// no lane takes it (llvmpipe, 512^2: the resolve took 90 ms with it, 60 ms without).
VCT_CONST int CONE_STAGE_OWN = 2;
// The pixels whose four nearest blocks share none of their surface (silhouettes, corners)
// search the sixteen nearest in a stage of their own, over the list the resolve appended
// them to, for the same reason: as a branch of the resolve, a SIMD machine ran the sixteen
// blocks' loads for every lane whenever one lane needed them (llvmpipe, Sponza AO at 512^2,
// s = 4: the cone pass took 32 ms with the branch, 25 ms with the stage; the same image).
VCT_CONST int CONE_STAGE_WIDE = 3;
// The resolve is a program of its own (CONE_RESOLVE_STAGE, coneResolveProgramKey), compiled
// without the cone march: llvmpipe paid for the march's code in every resolve invocation
// that never ran it (512^2: 60 ms in the trace stage's program, 15-22 ms in its own).
// The own and wide stages' lists: (own count, wide count, 2 pad, then a pixel's y x width + x
// per entry: the own list from entry 0, the wide list from entry width x height). Binding 7
// is also the bounce's voxel list; no program has both.
VCT_CONST int CONE_BINDING_OWN_LIST = 7;
VCT_CONST int CONE_OWN_LIST_HEADER = 4;  // uints before the pixels
VCT_CONST int CONE_IMAGE_TRACED = 1;  // image unit of the traced image in the resolve stage
// 8: a block of 64 pixels (a 512^2 image of a 60-degree view traces one pixel per 0.9
// degree). What the cones gather varies over voxels and R, and the resolve keeps the
// G-buffer's detail by surface agreement and traces the pixels no block shares, so the
// coarsest block is a cost a study measures, not a fixed image limit.
VCT_CONST int CONE_MAX_TRACE_SCALE = 8;
// Normal agreement weight max(0, n_q . n_b)^8: 0.5 at 25 degrees, so a crease's other face
// (90 degrees) gets none while a curved surface's neighbours keep most of theirs.
VCT_CONST float CONE_RESOLVE_NORMAL_POWER = 8.0;
// Tangent-plane agreement: the distance of the pixel's point from the block pixel's tangent
// plane, over their separation, weighted linearly to 0 at 0.25 (a slope of 14 degrees off the
// plane). Scale-free, so it needs no voxel size or camera: points of one smooth surface lie in
// each other's tangent planes, an edge's background does not.
VCT_CONST float CONE_RESOLVE_PLANE_SLOPE = 0.25;
// Below this total weight a pixel shares no block's surface (a thin object narrower than a
// block, a silhouette) and traces its own cones.
VCT_CONST float CONE_RESOLVE_MIN_WEIGHT = 0.05;

// AO mappings (ConeSettings::aoMapping).
VCT_CONST int CONE_AO_LINEAR = 0;    // A = 1 - sum_c w_c alpha_c: estimates the reference's A_R
VCT_CONST int CONE_AO_FALLOFF = 1;   // each sample's occlusion weighted by 1 / (1 + lambda t)

// rayMarchVoxels channels.
VCT_CONST int CONE_CHANNEL_OPACITY = 0;
VCT_CONST int CONE_CHANNEL_ALBEDO = 1;
VCT_CONST int CONE_CHANNEL_RADIANCE = 2;

// Defaults (ConeSettings; ranges in src/cone/cone_settings.h).
// 6 cones: Villegas 2016's set, cheapest set that covers the hemisphere with 60 deg cones.
VCT_CONST int CONE_DEFAULT_COUNT = 6;
VCT_CONST float CONE_DEFAULT_APERTURE_6 = 60.0;   // degrees: the 6 cones tile the hemisphere
VCT_CONST float CONE_DEFAULT_APERTURE_16 = 50.0;  // degrees: compix / WickedEngine's 16-cone set
// The finer spiral sets keep the 16-cone set's overlap: N cones of solid angle 1.5 * 2 pi / N,
// i.e. cos(aperture / 2) = 1 - 1.5 / N, so the cone set refines toward the cosine integral
// (each cone's weight 1 / N, its cap shrinking with N).
VCT_CONST float CONE_DEFAULT_APERTURE_32 = 35.0;
VCT_CONST float CONE_DEFAULT_APERTURE_64 = 25.0;
// beta = 0.5: two samples per footprint diameter, so a one-voxel wall is always sampled
// within its trilinear support; 1.0 halves the cost and starts to skip thin walls.
VCT_CONST float CONE_DEFAULT_STEP = 0.5;
// 1.5 voxels: a conservatively voxelized surface marks voxels up to one voxel above the
// shading point (centres up to 0.5 above); trilinear support is one texel, so a level-0
// sample at 1.5 voxels gives those voxels weight exactly 0 (no self-occlusion).
VCT_CONST float CONE_DEFAULT_OFFSET = 1.5;
// 0.99: past it the remaining 1% changes the result by less than 16-bit precision matters.
VCT_CONST float CONE_DEFAULT_MAX_ALPHA = 0.99;
// Plane limit: a sample at height h above the shading point's tangent plane uses texels of
// at most h / 1.5 voxels (the same 1.5-texel reach as the offset above), so coarse mips
// never blend the surface's own voxels into its cones (flat floors stay open, AO = 1).
VCT_CONST float CONE_PLANE_LIMIT_RATIO = 1.5;
// Crassin 2011's AO falloff 1 / (1 + lambda t), with lambda = 4 / R: weight 0.2 at t = R.
VCT_CONST float CONE_FALLOFF_LAMBDA_R = 4.0;
// vct.sharpen: 1 keeps plain trilinear filtering of the directional levels. The value that
// removes a sheet's leak is 4: at the default step (two samples a texel) a crossing cone always
// samples the opaque 3/4 of a texel it leaves, where 2 leaves half a texel to miss.
VCT_CONST float CONE_DEFAULT_SHARPEN = 1.0;
VCT_CONST float CONE_SHARPEN_MAX = 16.0;
// vct.level-bias: a footprint of diameter D samples level log2(D) + b (Crassin 2011: b = 0). A
// trilinear sample's tent is two texels wide, twice the footprint at b = 0, so a narrow lane sees
// what lies up to a footprint beside its cap; b = -1 makes the tent the footprint's width, at up
// to twice the samples (a step is beta texels). Narrow lanes gain; the default wide cones do not
// (their footprint's own error is the larger). Below -2 a step is a quarter of the footprint or
// less and nothing more is seen; above 1 a sample blurs across four footprints.
VCT_CONST float CONE_DEFAULT_LEVEL_BIAS = 0.0;
VCT_CONST float CONE_LEVEL_BIAS_MIN = -2.0;
VCT_CONST float CONE_LEVEL_BIAS_MAX = 1.0;

// vct.sharpen's filter along one axis: the coordinate, in texels of one level (centres at
// i + 1/2), at which linear filtering gives texel i + 1 the weight clamp((f - 1/2) s + 1/2, 0, 1)
// instead of f, the fraction of the way from centre i to centre i + 1. A directional level is
// crossed along its own axis, and there a one-texel sheet filtered linearly is a tent two texels
// wide whose opacity, composited with the step correction, passes exp(-2) = 13.5% of a cone that
// crosses an opaque texel, at every level and resolution: an error that finer voxels never
// reduce. Sharpened by s the tent becomes a box of 1 - 1/s texels with ramps of 1/s, which a
// crossing cone cannot pass, while the two axes across the level keep their linear weights (a
// sheet's edge stays where its coverage puts it). s = 1 is the identity; the weights still sum
// to 1, so a uniform medium is unchanged.
CONE_FN float cone_sharpenTexel(float x, float s) {
    float i = floor(x - 0.5f);
    float f = clamp((x - 0.5f - i - 0.5f) * s + 0.5f, 0.0f, 1.0f);
    return i + 0.5f + f;
}

struct ConeUniforms {
    mat4 voxelFromWorld;   // world -> voxel units [0, resolution]
    mat4 worldFromView;    // rayMarchVoxels: camera frame
    vec4 gridResolution;   // xyz voxels per axis, w = mip levels
    vec4 march;            // x = tan(aperture / 2) 2^(vct.level-bias), y = step factor beta, z = offset (voxels),
                           // w = max alpha
    vec4 limits;           // x = max distance (voxels), y = sky radiance, z = falloff lambda (1/voxels),
                           // w = plane-limit ratio (0 = off)
    vec4 camera;           // x = tan(yfov / 2) * aspect, y = tan(yfov / 2), z = ray step (voxels),
                           // w = vct.sharpen (read by the CONE_SHARPEN variant; optical-depth levels
                           // are the CONE_DEPTH_LEVELS variant)
    ivec4 config;          // x = cones in this dispatch (cones[0, x)), y = AO mapping, z = mip level (rayMarch), w = channel (rayMarch)
    ivec4 image;           // x = width, y = height, z = cone jitter (1: rotate per pixel), w = its seed
    ivec4 trace;           // pixel passes: x = trace scale (vct.trace-scale), y = stage (CONE_STAGE_*),
                           // z = the own stage's first list entry (dispatches of at most 65535 groups),
                           // w = split gathers (CONE_SPLIT_RESUME | CONE_SPLIT_CARRY; 0 = whole)
    ivec4 lanes;           // x = lanes per cone of the set, y = the set-wide index of cones[0] (this slice's first),
                           // z = flags (CONE_LANES_AIM | CONE_LANES_MIRROR), w = vct.end-taper (1: cone_endRatio)
    vec4 caps;             // x = tan of a lane's half-aperture where a pixel pass reads sheets and marches lanes
                           // (ConeMarch::capTan, set by bindConePass: laneCapTangent; 0 = no caps), yzw = 0
    vec4 coneAxes[CONE_MAX_SET_CONES];  // the set's cones before the lanes (xyz = direction, tangent frame)
    vec4 cones[CONE_BLOCK_CONES];  // xyz = direction in the tangent frame (z = normal), w = weight
};

// How a gather takes a lane, from `rise` = dot(lane, ng) and `axisRise` = dot(its cone's axis,
// ng) (ng the geometric normal): a cone whose axis is below the surface's plane is closed,
// every lane of it; a lane below the plane of a cone above it is open, not marched (a cone
// never sees the surface it starts from, and the cone model counts those directions open:
// src/cone/cone_set.h), or with vct.below-plane=mirror marched reflected across the plane
// (cone_mirrored); the others are marched. One lane a cone is the cone itself
// (axisRise = rise).
VCT_CONST int CONE_LANE_CLOSED = 0;
VCT_CONST int CONE_LANE_OPEN = 1;
VCT_CONST int CONE_LANE_MARCHED = 2;
CONE_FN int cone_laneState(float rise, float axisRise) {
    if (axisRise <= 0.0f) return CONE_LANE_CLOSED;
    return rise > 0.0f ? CONE_LANE_MARCHED : CONE_LANE_OPEN;
}
// vct.aim: the direction a marched cone takes from its start, `offset` voxels up the geometric
// normal ng, so that it meets its own ray from the shading point at `maxDist` (voxels) instead
// of running parallel to it `offset` voxels higher. The cone model's cones start at the shading
// point; the offset is there only to clear the surface's own voxels, and a cone that keeps it
// to the end sees an occluder `offset` voxels closer than it is: under a sheet at height h a
// cone whose ray ends just below the sheet at R ends inside it. That is a band of directions
// offset / R wide in dot(d, ng), first order in the voxel but with a constant the size of the
// offset. Aimed, the displacement falls linearly from `offset` at the start to 0 at maxDist. A
// direction whose ray at maxDist is less than `offset` above the tangent plane would aim
// downwards and is kept level (its component along ng removed), offset voxels above the plane.
// d unit, dot(d, ng) > 0 (a marched cone), maxDist > 0.
CONE_FN vec3 cone_aimedSpan(vec3 d, vec3 ng, float offset, float maxDist) {
    vec3 a = d * maxDist - ng * offset;
    return a - ng * min(dot(a, ng), 0.0f);
}
CONE_FN vec3 cone_aimedDirection(vec3 d, vec3 ng, float offset, float maxDist) {
    vec3 a = cone_aimedSpan(d, ng, offset, maxDist);
    return dot(a, a) > 0.0f ? normalize(a) : d;
}
// How far an aimed cone marches: to the point it is aimed at, |d maxDist - ng offset| (about
// maxDist - offset dot(d, ng)), not maxDist, which would carry it that far past its ray's end
// and let it see occluders up to `offset` voxels beyond maxDist.
CONE_FN float cone_aimedReach(vec3 d, vec3 ng, float offset, float maxDist) {
    return length(cone_aimedSpan(d, ng, offset, maxDist));
}
// vct.below-plane=mirror: a direction below the geometric plane reflected above it. The Vogel
// sets' outer caps reach below the plane (2.2% of the 16-cone set's weight); counted open, that
// weight reads as light in a room that is closed above the plane, an error of the set that does
// not fall with the voxels. Reflected, the weight stays on the hemisphere and each cap's lower
// edge is sampled twice, so the set's estimate of a closed room is 0 and of an open one 1.
CONE_FN vec3 cone_mirrored(vec3 d, vec3 ng) { return d - 2.0f * min(dot(d, ng), 0.0f) * ng; }
// ConeUniforms::lanes.z: the march's flags.
VCT_CONST int CONE_LANES_AIM = 1;     // vct.aim: cone_aimedDirection
VCT_CONST int CONE_LANES_MIRROR = 2;  // vct.below-plane=mirror: cone_mirrored
// vct.end-taper: a march's sample sits half a step (beta texels) past where its level was chosen
// and a trilinear sample sees one texel past its centre, so a texel of (maxDist - t) / (1 + beta / 2)
// voxels chosen at t reaches no further than maxDist.
CONE_FN float cone_endRatio(float stepFactor) { return 1.0f + 0.5f * stepFactor; }
// vct.voxel.edges=sheet: the zone about maxDist in which a march reads sheets with its lane's
// cap (cone_sampleSheets, cone_march_shared.h), maxDist tan(alpha) CONE_CAP_ZONE voxels either
// side (alpha the lane's half-aperture; tanAlpha = 0: none). A sheet crossed at t_c is met before
// maxDist by the share of the lane at s = (maxDist - t_c) / (maxDist tan(alpha) tan(theta)),
// theta the angle between the lane and the sheet's normal, which is 0 from s = -1: the zone
// holds every sheet's whole cap up to tan(theta) = CONE_CAP_ZONE. Default 2 (63 degrees): a lane
// crossing a sheet more obliquely with its ray past the zone's end is cut there, at most a fifth
// of its share up to 76 degrees. Range [1, 8]: 4 (76 degrees) gave the same mean voxel error over
// the closed-form cases within 3% for twice the zone's steps (+21% samples against +11%).
VCT_CONST float CONE_CAP_ZONE = 2.0f;
CONE_FN float cone_capZone(float maxDist, float tanAlpha) { return maxDist * tanAlpha * CONE_CAP_ZONE; }
// GI over sheets (vct.voxel.edges=sheet): how far up its geometric normal a pixel's lanes start,
// in voxels, where no box is there (cone_sheetStartOffset, cone_march_shared.h). Half a voxel
// clears the surface's own sheet, which a step sees only by crossing it. Range (0, vct.offset]:
// the offset's 1.5 (the trilinear base's reach) put the lanes level with an emitter 1.5
// voxels up, whose sheet no step then crosses, and moved each lane 1.5 voxels sideways of the
// cone model's; 0.5 took the 12 open emitting cases' mean voxel error at 64^3 from 0.069 to 0.023.
VCT_CONST float CONE_SHEET_START = 0.5f;
// The sheet texels cone_sheetStartOffset reads about a pixel's start (3 x 3 x 3), counted once a
// pixel in both backends' fetches (cone/cone_cost.h).
VCT_CONST float CONE_SHEET_START_FETCHES = 27.0f;
// The set's cone of lane `lane` (set-wide index; lanes of a cone are consecutive).
CONE_FN int cone_laneCone(int lane, int lanesPerCone) { return lane / max(lanesPerCone, 1); }

// Weights of the three directional textures a cone of unit direction d blends: d^2 sums to
// |d|^2 = 1, so a uniform medium keeps its opacity (abs(d) sums to up to sqrt(3) and
// over-brightens). Shared so the CPU test checks the shader's function.
CONE_FN vec3 cone_anisoWeights(vec3 d) { return d * d; }

// Blends the three directional samples (premultiplied radiance, alpha) with weights w that
// sum to 1. Opacity blends as optical depth: T = T_x^w.x T_y^w.y T_z^w.z, the transmittance
// of a path that crosses each axis's layers in proportion to its weight. A linear blend of
// alpha would let a wall that is opaque along its normal (alpha_x = 1 at every level, the
// point of the directional mips) turn transparent for oblique cones as the level rises
// (alpha -> w.x + (1 - w.x) 2^-level), so leaking would grow with the grid resolution.
// Radiance keeps the linear blend's ratio to opacity (the blended colour of what is hit).
CONE_FN vec4 cone_blendDirectional(vec3 w, vec4 x, vec4 y, vec4 z) {
    vec3 alpha = clamp(vec3(x.w, y.w, z.w), vec3(0.0), vec3(1.0));
    vec3 logT = log2(max(vec3(1.0) - alpha, vec3(1.0e-7)));
    float a = 1.0f - exp2(dot(w, logT));
    float aLinear = dot(w, alpha);
    vec3 c = w.x * vec3(x) + w.y * vec3(y) + w.z * vec3(z);
    return vec4(aLinear > 1.0e-6f ? c * (a / aLinear) : c, a);
}

// vct.jitter: the angle in [0, 2 pi) by which pixel (x, y) (GL's, bottom row 0) turns the cone
// set about its normal, from a PCG hash (O'Neill) of the pixel and the seed. A fixed set draws
// the same few directions at every pixel, so a wall's occluders show as streaks along them; a
// turn per pixel spreads the set over the azimuth and the streaks become noise a filter or
// temporal accumulation can average (a new seed per frame gives a new pattern). Shared so the
// cone-model reference turns its cones as the cone passes do.
CONE_FN uint cone_pcg(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
CONE_FN float cone_jitterAngle(uint x, uint y, uint seed) {
    uint h = cone_pcg(x ^ cone_pcg(y ^ cone_pcg(seed)));
    return 6.28318530717958647692f * float(h >> 8u) * (1.0f / 16777216.0f);
}

VCT_END_NAMESPACE
