// The visibility bitmask of one slice (shaders/ao/visibility_bitmask.h, compiled here as C++
// exactly as vbao.glsl and ssil.glsl compile it): the sectors' measures add up to GTAO's
// unoccluded slice, an occluded range sets the sectors whose centres it covers, and an
// infinitely thick sample reproduces GTAO's horizon within half a sector.
#include "ao/visibility_bitmask.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace vct::gpu;

// GTAO's closed form for one side (Jimenez et al. 2016, eq. 7), as gtao.glsl's gtao_arc.
double gtaoArc(double h, double n) { return (std::cos(n) + 2.0 * h * std::sin(n) - std::cos(2.0 * h - n)) * 0.25; }

const double kNormals[] = {-1.5, -1.0, -0.4, 0.0, 0.3, 0.9, 1.4};

TEST(VisibilityBitmask, ClearSliceIsGtaosUnoccludedSlice) {
    for (double n : kNormals) {
        const double expected = gtaoArc(n + M_PI / 2, n) + gtaoArc(n - M_PI / 2, n);
        EXPECT_NEAR(vbm_visibleMeasure(0u, float(n)), expected, 1e-5) << "n " << n;
    }
    // A slice through the normal (n = 0) carries half of the cosine-weighted hemisphere on
    // each side: the whole slice measures 1.
    EXPECT_NEAR(vbm_visibleMeasure(0u, 0.f), 1.0, 1e-6);
    EXPECT_EQ(vbm_visibleMeasure(0xFFFFFFFFu, 0.4f), 0.f);
}

TEST(VisibilityBitmask, SectorMeasuresAddUp) {
    for (double n : kNormals) {
        double sum = 0.0;
        for (int k = 0; k < VBM_SECTORS; ++k) {
            const float m = vbm_measure(1u << k, float(n));
            EXPECT_GE(m, 0.f) << "sector " << k << " n " << n;
            sum += m;
        }
        EXPECT_NEAR(sum, vbm_visibleMeasure(0u, float(n)), 1e-5) << "n " << n;
        // Any mask splits the slice into its set and its clear sectors.
        const uint mask = 0x0F0F3C81u;
        EXPECT_NEAR(vbm_measure(mask, float(n)) + vbm_visibleMeasure(mask, float(n)), sum, 1e-5) << "n " << n;
    }
}

TEST(VisibilityBitmask, RangeSetsTheSectorsWhoseCentresItCovers) {
    const float n = 0.3f, w = float(M_PI) / VBM_SECTORS;
    auto centre = [&](int k) { return vbm_sectorStart(k, n) + 0.5f * w; };
    EXPECT_EQ(vbm_occludedBits(centre(5) - 0.1f * w, centre(5) + 0.1f * w, n), 1u << 5);
    EXPECT_EQ(vbm_occludedBits(centre(5) + 0.1f * w, centre(5) + 0.8f * w, n), 0u);  // no centre inside
    EXPECT_EQ(vbm_occludedBits(centre(3) - 0.1f * w, centre(6) + 0.1f * w, n), 0xFu << 3);
    EXPECT_EQ(vbm_occludedBits(-10.f, 10.f, n), 0xFFFFFFFFu);                         // clamped to the slice
    EXPECT_EQ(vbm_occludedBits(centre(30), 10.f, n), 3u << 30);
    EXPECT_EQ(vbm_occludedBits(1.f, 0.5f, n), 0u);                                    // empty range
}

TEST(VisibilityBitmask, InfiniteThicknessIsGtaosHorizon) {
    // One horizon per side, everything below it occluded (a sample of infinite thickness
    // occludes from its front to the far end of the slice): the clear measure is GTAO's
    // arc(h0) + arc(h1) up to half a sector's measure on each side.
    const float w = float(M_PI) / VBM_SECTORS;
    for (double n : kNormals) {
        double worst = 0.0;
        for (int i = 0; i <= 100; ++i)
            for (int j = 0; j <= 10; ++j) {
                const double h1 = n + (-0.5 + i / 100.0) * M_PI, h0 = n + (-0.5 + j / 20.0) * M_PI;
                if (h1 < 0.0 || h0 > 0.0) continue;  // h1 on the positive side, h0 on the negative one
                const uint mask = vbm_occludedBits(float(h1), 10.f, float(n)) | vbm_occludedBits(-10.f, float(h0), float(n));
                const double gtao = gtaoArc(h1, n) + gtaoArc(h0, n);
                worst = std::max(worst, std::abs(double(vbm_visibleMeasure(mask, float(n))) - gtao));
            }
        // The density sin h cos(h - n) = (sin(2h - n) + sin n) / 2 is at most 1, so half a
        // sector on each side measures at most w / 2, both sides w.
        std::printf("[bitmask] n %+.1f: worst |bitmask - GTAO| %.4f (bound %.4f)\n", n, worst, double(w));
        EXPECT_LE(worst, w) << "n " << n;
    }
}

}  // namespace
