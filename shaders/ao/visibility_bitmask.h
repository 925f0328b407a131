// The visibility bitmask of one GTAO slice (Therrien, Levesque and Gilet 2023), shared by
// C++ (tests) and GLSL (vbao, ssil). A slice is the half-disc of directions in the plane of
// the view vector and one screen direction, on the surface's side of its projected normal:
// angles h from the view vector (positive toward the slice's screen direction) within
// [n - pi/2, n + pi/2], n the projected normal's angle. It is cut into 32 equal sectors, bit k
// covering [n - pi/2 + k pi/32, n - pi/2 + (k+1) pi/32]; a sample occludes the sectors between
// the angles of its front and of its back (the front pushed away from the eye by an assumed
// thickness), so a thin object no longer hides everything below its horizon as in GTAO.
//
// Sectors are weighted by the measure GTAO integrates (Jimenez et al. 2016, eq. 3): over a
// slice, |sin h| cos(h - n) dh, times the projected normal's length, averaged over slices,
// is the reference's (1/pi) integral of V max(0, n.w) dw. So the visible fraction is exact
// cosine-weighted AO up to the sector quantization (a sector is 5.6 degrees), and with an
// infinite thickness the mask is GTAO's horizons.
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define VBM_FN inline
#else
#define VBM_FN
#endif

VCT_BEGIN_NAMESPACE

#ifdef __cplusplus
using glm::acos; using glm::ceil; using glm::cos; using glm::sin;  // findLSB: shared_types.h
#endif

VCT_CONST int VBM_SECTORS = 32;
VCT_CONST float VBM_PI = 3.14159265358979f;
VCT_CONST float VBM_HALF_PI = 1.57079632679490f;

// The slice's measure from the view vector (h = 0) to h, signed (negative for h < 0), so
// that the measure of [a, b] is vbm_cumulative(b) - vbm_cumulative(a). For h >= 0 it is
// GTAO's arc (cos n + 2 h sin n - cos(2 h - n)) / 4; its derivative is sin h cos(h - n).
VBM_FN float vbm_cumulative(float h, float n) {
    float arc = (cos(n) + 2.0f * h * sin(n) - cos(2.0f * h - n)) * 0.25f;
    return h < 0.0f ? -arc : arc;
}

// The angle at which sector k begins (k = 32: where the last one ends).
VBM_FN float vbm_sectorStart(int k, float n) { return n - VBM_HALF_PI + float(k) * (VBM_PI / float(VBM_SECTORS)); }

// The bits of the sectors whose centre lies in [hA, hB]. Centres rather than any overlap:
// the quantization then errs by up to half a sector either way instead of always toward
// occlusion, and an infinite thickness reproduces GTAO's horizon to within half a sector.
VBM_FN uint vbm_occludedBits(float hA, float hB, float n) {
    float scale = float(VBM_SECTORS) / VBM_PI;
    float xa = clamp((hA - n + VBM_HALF_PI) * scale, -1.0f, float(VBM_SECTORS) + 1.0f);
    float xb = clamp((hB - n + VBM_HALF_PI) * scale, -1.0f, float(VBM_SECTORS) + 1.0f);
    int first = max(int(ceil(xa - 0.5f)), 0);
    int last = min(int(floor(xb - 0.5f)), VBM_SECTORS - 1);
    if (last < first) return 0u;
    int count = last - first + 1;
    uint run = count >= VBM_SECTORS ? 0xFFFFFFFFu : ((1u << uint(count)) - 1u);
    return run << uint(first);
}

// The measure of the sectors of `mask` that are clear (visible), run by run.
VBM_FN float vbm_visibleMeasure(uint occluded, float n) {
    float sum = 0.0f;
    uint open = ~occluded;
    while (open != 0u) {
        int start = findLSB(open);
        uint shifted = open >> uint(start);
        int runLength = shifted == 0xFFFFFFFFu ? VBM_SECTORS : findLSB(~shifted);
        sum += vbm_cumulative(vbm_sectorStart(start + runLength, n), n) - vbm_cumulative(vbm_sectorStart(start, n), n);
        uint run = runLength >= VBM_SECTORS ? 0xFFFFFFFFu : ((1u << uint(runLength)) - 1u) << uint(start);
        open &= ~run;
    }
    return sum;
}

// The measure of the sectors of `bits` (those a sample newly occludes: its share of light).
VBM_FN float vbm_measure(uint bits, float n) { return vbm_visibleMeasure(~bits, n); }

VCT_END_NAMESPACE
