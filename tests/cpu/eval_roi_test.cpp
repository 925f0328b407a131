// ROI masks: exactly the pixels whose with/without difference exceeds k combined standard errors.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "eval/metrics.h"
#include "eval/roi.h"

namespace vct {
namespace {

TEST(EvalRoi, SelectsPixelsBeyondKSigma) {
    const int w = 8, h = 4;
    Image without(w, h, 1, 0.5f), with = without, se1(w, h, 1, 0.01f), se2(w, h, 1, 0.01f);
    // Combined sigma = 0.01 sqrt(2) = 0.014142; 3 sigma = 0.042426.
    with.at(0, 0) = 0.5f - 0.05f;   // 3.54 sigma: selected
    with.at(1, 0) = 0.5f + 0.04f;   // 2.83 sigma: not
    with.at(2, 1) = 0.5f + 0.045f;  // 3.18 sigma: selected
    with.at(3, 2) = 0.5f - 0.041f;  // 2.90 sigma: not
    // Different sigmas per pixel: se 0.03 and 0.04 combine to 0.05, 3 sigma = 0.15.
    se1.at(4, 3) = 0.03f, se2.at(4, 3) = 0.04f, with.at(4, 3) = 0.5f + 0.14f;  // not
    se1.at(5, 3) = 0.03f, se2.at(5, 3) = 0.04f, with.at(5, 3) = 0.5f + 0.16f;  // selected
    // Noise-free pixels: the absolute floor rejects rounding-level differences only.
    se1.at(6, 3) = se2.at(6, 3) = 0.f, with.at(6, 3) = 0.5f + 1e-7f;  // 1 ulp-ish: not
    se1.at(7, 3) = se2.at(7, 3) = 0.f, with.at(7, 3) = 0.5f + 1e-4f;  // selected

    Image roi = deriveRoiMask(with, without, se1, se2, 3.0);
    ASSERT_EQ(roi.channels, 1);
    const int selected[][2] = {{0, 0}, {2, 1}, {5, 3}, {7, 3}};
    Image expected(w, h, 1, 0.f);
    for (auto& p : selected) expected.at(p[0], p[1]) = 1.f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            EXPECT_EQ(roi.at(x, y), expected.at(x, y)) << "pixel (" << x << ", " << y << ")";
    EXPECT_EQ(countMask(roi), 4u);

    // k = 2 also takes the 2.83, 2.90 and 2.8 sigma pixels.
    EXPECT_EQ(countMask(deriveRoiMask(with, without, se1, se2, 2.0)), 7u);
    // The mask plugs into the metrics: mean |difference| over the ROI.
    ErrorMetrics m = computeErrorMetrics(with, without, &roi);
    EXPECT_EQ(m.pixelCount, 4u);
    EXPECT_NEAR(m.mae, (0.05 + 0.045 + 0.16 + 1e-4) / 4, 1e-6);
}

TEST(EvalRoi, RejectsBadInput) {
    Image a(4, 4, 1, 0.5f), s(4, 4, 1, 0.01f);
    Image negative = s;
    negative.at(2, 2) = -0.01f;
    EXPECT_THROW(deriveRoiMask(a, a, negative, s), InternalError);
    EXPECT_THROW(deriveRoiMask(a, Image(4, 5, 1, 0.5f), s, s), InternalError);
    EXPECT_THROW(deriveRoiMask(a, a, s, s, -1.0), InternalError);
    Image nan = a;
    nan.at(1, 1) = std::nanf("");
    EXPECT_THROW(deriveRoiMask(nan, a, s, s), InternalError);
    EXPECT_EQ(countMask(deriveRoiMask(a, a, s, s)), 0u);
}

}  // namespace
}  // namespace vct
