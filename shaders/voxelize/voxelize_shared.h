// Constants shared by src/voxelize/*.cpp and shaders/voxelize/*.glsl: work-group sizes
// (used by both `layout(local_size...)` and the dispatch math), image units, and the
// fixed-point scales of the order-independent accumulation.
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define VOX_FN inline
#else
#define VOX_FN
#endif

VCT_BEGIN_NAMESPACE

// One invocation per triangle; triangles whose projection covers more than
// VOX_SMALL_COLUMNS voxel columns are deferred to the "big" pass, where a whole work
// group of VOX_BIG_GROUP invocations shares the columns of one triangle, so a floor
// spanning the grid does not serialize one SIMD lane for seconds.
VCT_CONST int VOX_TRI_GROUP = 64;
VCT_CONST int VOX_BIG_GROUP = 64;
VCT_CONST int VOX_SMALL_COLUMNS = 48;
VCT_CONST int VOX_GRID_GROUP = 4;   // 4x4x4 for per-voxel passes (resolve, inject, mips)

// The 18 fixed-point accumulators (r32ui 3D textures), by index: albedo r, g, b; normal x,
// y, z (two's complement sums); the sum of weights; the sum of weights of doubleSided
// materials (allocated only when the scene has one: TWO_SIDED); emission r lo, r hi, g lo,
// g hi, b lo, b hi; with vct.voxel.edges=coverage or sheet, the covered area of the voxel's
// columns and the bits of the dominant axes that cross it (EDGE_COVERAGE); with sheet, the
// span's two maxima and the bins of the voxel its surfaces reach along each axis (EDGE_SHEETS).
// GL guarantees 8 image units, so no pass binds them all as
// images: the geometry pass of voxelize.glsl binds accumulator k at image unit k (k <
// VOX_ACC_EMISSION), the emission pass binds k at image unit k - VOX_ACC_EMISSION, the
// coverage pass k at k - VOX_ACC_COVERAGE, and resolve.glsl reads those below VOX_ACC_SHEET_LO
// through texture unit k (texelFetch; at most 16 of the 16 a stage is guaranteed), writing its
// outputs to the image units below; voxelize_sheets.glsl reads the axes and the span.
VCT_CONST int VOX_ACC_ALBEDO = 0;
VCT_CONST int VOX_ACC_NORMAL = 3;
VCT_CONST int VOX_ACC_WEIGHT = 6;
VCT_CONST int VOX_ACC_TWO_SIDED = 7;
VCT_CONST int VOX_ACC_EMISSION = 8;
VCT_CONST int VOX_ACC_COVERAGE = 14;
VCT_CONST int VOX_ACC_AXES = 15;
VCT_CONST int VOX_ACC_SHEET_LO = 16;  // vct.voxel.edges=sheet: VOX_SHEET_STEPS + 1 - the span's low end
VCT_CONST int VOX_ACC_SHEET_HI = 17;  // and its high end (vox_sheetSpanFixed)
VCT_CONST int VOX_ACC_SHEET_EXTENT = 18;  // the extent bits (vox_extentBits); kept as VoxelGrid::sheetExtents
VCT_CONST int VOX_ACC_COUNT = 19;
VCT_CONST int VOX_IMAGE_RESOLVE_OPACITY = 0;
VCT_CONST int VOX_IMAGE_RESOLVE_ALBEDO = 1;
VCT_CONST int VOX_IMAGE_RESOLVE_NORMAL = 2;
VCT_CONST int VOX_IMAGE_RESOLVE_EMISSION = 3;
VCT_CONST int VOX_IMAGE_RESOLVE_TWO_SIDED = 4;
// voxelize_sheets.glsl (vct.voxel.edges=sheet): its output image, and the texture unit of the
// resolved opacity it reads (the accumulators keep theirs).
VCT_CONST int VOX_IMAGE_SHEETS = 0;
VCT_CONST int VOX_UNIT_SHEETS_OPACITY = 19;

// Storage binding of the big-triangle list: uvec4 header {listed triangles, -, -, occupied
// voxel count}, then triangle ids.
VCT_CONST int VOX_BINDING_BIGLIST = 6;

// Fixed point. Every (triangle, voxel) contribution has an integer weight in
// [1, VOX_WEIGHT_MAX] ~ the triangle's area in voxel faces (so a sliver does not count
// as much as a floor), and adds weight * round(value * scale):
// - albedo in [0, 1] at 12 bits: a voxel overflows only past ~65k full-weight triangles;
// - normal components in [-1, 1] at 12 bits, summed in two's complement;
// - emission per channel in a 64-bit (hi, lo) pair with carry, 2^-12 absolute resolution,
//   clamped to VOX_EMISSION_MAX: ~280k full-weight contributions before overflow.
VCT_CONST int VOX_WEIGHT_MAX = 16;
// The tested box's half-size growth in voxel units (the triangle/voxel overlap test, on the GPU
// and in the sparse voxelizer's src/vdb/triangle_box.h): 0.5 plus a margin well above float
// rounding of voxel coordinates (~1e-5 at 1024^3) and well below anything visible.
VCT_CONST float VOX_BOX_GROWTH = 1.0e-4f;
VCT_CONST float VOX_ALBEDO_SCALE = 4095.0;
VCT_CONST float VOX_NORMAL_SCALE = 4095.0;
VCT_CONST float VOX_EMISSION_SCALE = 4096.0;
VCT_CONST float VOX_EMISSION_MAX = 1.0e9;

// Edge coverage (vct.voxel.edges=coverage). An occupied voxel's opacity is 1 by default: a
// sheet's edge then stands a whole voxel past the edge wherever it falls in the voxel, and
// the sheet's boundary voxels occlude as if the sheet covered them. With edge coverage a voxel
// crossed by surfaces of one dominant axis a holds the share of its column along a that they
// cover: each triangle adds the area of its projection along its dominant axis inside the
// voxel's column square (vox_columnCoverage) to every voxel of the column it crosses, summed
// in fixed point at VOX_COVERAGE_SCALE per voxel face, and the opacity is the sum of the
// voxel's and its two neighbours' along a, at most 1, in steps of 1 / VOX_COVERAGE_STEPS
// (exact in the half-float level 0 the dense grid stores, so both backends hold the same
// values). The neighbours are there because a sheet is cut into triangles: a sloped sheet's
// two triangles over one column can cross different voxels of it, each holding its own
// triangle's part of the column, and a ray along a would pass between them; with the
// neighbours every voxel of the column holds the whole column, 1, as with occupancy. Inside a
// sheet, flat or sloped, the voxels are 1; at its rim they hold the share it covers (twice
// that where the sheet lies on the face between two voxels, both of which it crosses). A
// voxel crossed by surfaces of two or more dominant axes (a room's corner, a wall under a
// ceiling, a box's edge) keeps 1: its sheets meet inside it, and summing their shares (each
// of its own axis) would open a gap the geometry closes.
// The dense grid's sums are 32-bit: a voxel overflows past 65536 triangles that each cover its
// whole column (the sparse sums saturate there).
VCT_CONST float VOX_COVERAGE_SCALE = 65536.0f;
VCT_CONST float VOX_COVERAGE_STEPS = 1024.0f;

// Whether the surfaces crossing a voxel share one dominant axis (one bit of `axes` set), and
// that axis (axes = 1, 2 or 4).
VOX_FN bool vox_oneAxis(uint axes) { return axes != 0u && (axes & (axes - 1u)) == 0u; }
VOX_FN int vox_singleAxis(uint axes) { return axes == 1u ? 0 : (axes == 2u ? 1 : 2); }

// The part of a triangle inside one voxel column (vox_columnCut): its projected area, the lowest
// and highest height of its plane over that part, and that part's bounding rectangle in the
// column (both coordinates in [0, 1] from the column's corner).
struct VoxColumnCut {
    float area;
    float zMin;
    float zMax;
    vec2 boxLo;
    vec2 boxHi;
};

// The triangle (a, b, c), projected to 2D, clipped by the four sides of the unit square at `lo`
// (Sutherland-Hodgman): its area (the shoelace sum), its bounding rectangle, and
// (vct.voxel.edges=sheet) the lowest and highest value over the clipped part of the plane
// height z = (plane.w - plane.x u - plane.y v) / plane.z (the triangle's plane, solved for its
// dominant axis).
VOX_FN VoxColumnCut vox_columnCut(vec2 a, vec2 b, vec2 c, vec2 lo, vec4 plane) {
    vec2 poly[7];
    vec2 next[7];
    poly[0] = a - lo;
    poly[1] = b - lo;
    poly[2] = c - lo;
    int n = 3;
    for (int side = 0; side < 4; ++side) {
        int axis = side / 2;
        bool low = side % 2 == 0;  // keep p[axis] >= 0, else p[axis] <= 1
        int m = 0;
        for (int k = 0; k < n; ++k) {
            vec2 u = poly[k];
            vec2 v = poly[(k + 1) % n];
            float du = low ? u[axis] : 1.0f - u[axis];
            float dv = low ? v[axis] : 1.0f - v[axis];
            if (du >= 0.0f) next[m++] = u;
            if ((du >= 0.0f) != (dv >= 0.0f)) next[m++] = u + (du / (du - dv)) * (v - u);
        }
        n = m;
        for (int k = 0; k < n; ++k) poly[k] = next[k];
    }
    float twiceArea = 0.0f;
    VoxColumnCut cut;
    cut.zMin = 3.4e38f;
    cut.zMax = -3.4e38f;
    cut.boxLo = vec2(1.0f);
    cut.boxHi = vec2(0.0f);
    for (int k = 0; k < n; ++k) {
        vec2 u = poly[k];
        vec2 v = poly[(k + 1) % n];
        twiceArea += u.x * v.y - v.x * u.y;
        cut.boxLo = min(cut.boxLo, u);
        cut.boxHi = max(cut.boxHi, u);
        if (plane.z != 0.0f) {
            float z = (plane.w - plane.x * (u.x + lo.x) - plane.y * (u.y + lo.y)) / plane.z;
            cut.zMin = min(cut.zMin, z);
            cut.zMax = max(cut.zMax, z);
        }
    }
    cut.area = min(0.5f * max(twiceArea, -twiceArea), 1.0f);
    return cut;
}

VOX_FN float vox_columnCoverage(vec2 a, vec2 b, vec2 c, vec2 lo) { return vox_columnCut(a, b, c, lo, vec4(0.0f)).area; }

// vct.voxel.edges=sheet: where in its voxel a sheet lies. Each triangle that covers part of a
// voxel's column adds the span of its plane over that part (vox_columnCut), relative
// to voxel k along the axis and clamped to it, in steps of 1 / VOX_SHEET_STEPS rounded
// outwards; the voxel keeps the lowest and the highest (two atomic maxima: VOX_SHEET_STEPS + 1 -
// lo, hi; zero-initialised accumulators read as no span). Exact in half floats.
VCT_CONST float VOX_SHEET_STEPS = 1024.0f;
VOX_FN uvec2 vox_sheetSpanFixed(vec2 zSpan, float k) {
    float lo = clamp(zSpan.x - k, 0.0f, 1.0f), hi = clamp(zSpan.y - k, 0.0f, 1.0f);
    return uvec2(uint(VOX_SHEET_STEPS + 1.0f - floor(lo * VOX_SHEET_STEPS)), uint(ceil(hi * VOX_SHEET_STEPS)));
}
// The base level's sheet texel (cone_sampleSheets): (opacity, lo, hi, axis) where the voxel's
// surfaces share one dominant axis and left a span, else (opacity, 0, 0, -1).
VOX_FN vec4 vox_sheetTexel(float opacity, uint axes, uint loInv, uint hi) {
    float lo = (VOX_SHEET_STEPS + 1.0f - float(loInv)) / VOX_SHEET_STEPS;
    float top = float(hi) / VOX_SHEET_STEPS;
    bool sheet = vox_oneAxis(axes) && loInv > 0u && lo <= top;
    return sheet ? vec4(opacity, lo, top, float(vox_singleAxis(axes))) : vec4(opacity, 0.0f, 0.0f, -1.0f);
}

// vct.voxel.edges=sheet: where in its voxel a sheet or a box lies across. Each triangle that
// covers part of a voxel's column sets, per axis, the bins of the voxel (VOX_EXTENT_BINS of
// them) its part reaches: across its dominant axis the bounding rectangle of its part of the
// column (vox_columnCut), along it its plane's span relative to the voxel, both rounded outwards.
// The voxel keeps their union (one atomic or: bits [VOX_EXTENT_BINS a, VOX_EXTENT_BINS (a + 1))
// for axis a), so its extent along each axis holds every surface in it: a plate's rim or a
// slab's corner where it lies in its voxel, not across the whole voxel (cone_sampleSheets).
// VOX_EXTENT_BINS: 10, fixed: three fields of 10 bits fill the one 32-bit word an atomic or
// takes; a tenth of a voxel is far below the lanes' footprints (one to several voxels at the
// base level), and the rounding outwards keeps every surface inside its extent.
VCT_CONST int VOX_EXTENT_BINS = 10;
VOX_FN uint vox_extentBits(float lo, float hi, int axis) {
    int first = clamp(int(floor(clamp(lo, 0.0f, 1.0f) * float(VOX_EXTENT_BINS))), 0, VOX_EXTENT_BINS - 1);
    int last = clamp(int(ceil(clamp(hi, 0.0f, 1.0f) * float(VOX_EXTENT_BINS))) - 1, first, VOX_EXTENT_BINS - 1);
    uint bits = ((2u << uint(last)) - 1u) & ~((1u << uint(first)) - 1u);
    return bits << uint(VOX_EXTENT_BINS * axis);
}
// One triangle's extent bits in voxel k along its dominant axis `axis`: `across`, the bits of its
// part of the column across the axis, and its plane's span `zSpan` relative to the voxel.
VOX_FN uint vox_triangleExtentBits(uint across, vec2 zSpan, float k, int axis) {
    return across | vox_extentBits(zSpan.x - k, zSpan.y - k, axis);
}
// The extent [lo, hi] (in the voxel, [0, 1]) along `axis` of a voxel's extent bits; the whole
// voxel where no bin is set (outside the grid, or a test volume that records none).
VOX_FN vec2 vox_extentSpan(uint bits, int axis) {
    uint b = (bits >> uint(VOX_EXTENT_BINS * axis)) & ((1u << uint(VOX_EXTENT_BINS)) - 1u);
    if (b == 0u) return vec2(0.0f, 1.0f);
    return vec2(float(findLSB(b)), float(findMSB(b) + 1)) * (1.0f / float(VOX_EXTENT_BINS));
}

// One triangle's covered area in fixed point.
VOX_FN uint vox_coverageFixed(float area) { return uint(floor(area * VOX_COVERAGE_SCALE + 0.5f)); }


// A voxel's opacity from its axis bits and the coverage sums of the voxel (`here`) and of its
// two neighbours along its axis (0 where unoccupied); 0 when no triangle crossed it.
VOX_FN float vox_edgeOpacity(uint axes, uint below, uint here, uint above) {
    if (axes == 0u) return 0.0f;
    if (!vox_oneAxis(axes)) return 1.0f;  // two or more dominant axes
    float sum = min(float(below), VOX_COVERAGE_SCALE) + min(float(here), VOX_COVERAGE_SCALE) +
                min(float(above), VOX_COVERAGE_SCALE);
    float share = min(sum, VOX_COVERAGE_SCALE) * (VOX_COVERAGE_STEPS / VOX_COVERAGE_SCALE);
    return floor(share + 0.5f) / VOX_COVERAGE_STEPS;
}

// Share of a voxel sample's radiance (premultiplied or not) that leaves towards a cone
// travelling along unit d, given n, the mean normal of the sample's occupied voxels (the
// filtered normal texture's xyz / a): radiance leaves a surface from its front, so voxels
// seen from behind (dot(n, d) >= 1/2) pass none of it, though they still occlude. The mean
// is shorter where voxels disagree (both faces of a thin wall, a corner), so mixed and
// two-sided voxels pass their radiance. Without this an emitter or a lit wall shines
// through its back: a bright rim on a ceiling 2 cm above a light panel once voxels are
// finer than the gap, and a floor lit by the back of a panel facing away from it.
VOX_FN float vox_facingWeight(vec3 n, vec3 d) { return clamp(1.0f - 2.0f * dot(n, d), 0.0f, 1.0f); }

// Two-sided voxels. A glTF doubleSided material reflects and emits from both faces. A voxel
// at least VOX_TWO_SIDED_SHARE of whose accumulation weight is doubleSided is lit on both
// faces by injection, each face with its own cosine and shadow ray, which gives the radiance
// leaving its front (the side of its winding normal n) and its back. One radiance texel and
// the facing test carry both: the texel holds the brighter face's radiance, and the voxel's
// facing normal (the normal texture the cones' facing test and the bounces read) is
// vox_twoSidedNormalScale(front, back) * n. Its magnitude k makes a cone that meets the dimmer
// face head on see the brighter radiance times 1 - 2 k, which is the dimmer face's own where
// r = dim / bright >= 1/15 (k = (1 - r) / 2), and rises to the unit normal of a one-sided
// surface facing the lit side as r -> 0 (k = 1 - 8 r: a face lit at under 1/15 of the other
// shows 0). Lit on one face only, a two-sided voxel is exactly a one-sided surface facing the
// light; lit on neither, it keeps its winding normal, as a one-sided surface. Its sign picks
// the brighter face (ties: the front), and k never falls below VOX_TWO_SIDED_MIN_SCALE, so the
// facing normal always points somewhere: the bounces gather around it, on the brighter face
// (a face as bright as the other shows 1 - 1/128 of it). `front` and `back` are the faces'
// max components.
VCT_CONST float VOX_TWO_SIDED_SHARE = 0.5f;
VCT_CONST float VOX_TWO_SIDED_MIN_SCALE = 1.0f / 256.0f;
VOX_FN float vox_twoSidedNormalScale(float front, float back) {
    float bright = max(front, back);
    if (!(bright > 0.0f)) return 1.0f;
    float r = min(front, back) / bright;
    float k = max(max(0.5f * (1.0f - r), 1.0f - 8.0f * r), VOX_TWO_SIDED_MIN_SCALE);
    return front >= back ? k : -k;
}
// The same for the faces' radiances, compared by their max components (what both backends'
// injection passes).
VOX_FN float vox_twoSidedNormalScale(vec3 front, vec3 back) {
    return vox_twoSidedNormalScale(max(front.x, max(front.y, front.z)), max(back.x, max(back.y, back.z)));
}

VCT_END_NAMESPACE
