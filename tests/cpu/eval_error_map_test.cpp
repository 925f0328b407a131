// False-colour error maps: sign-to-hue mapping, saturation, masking, legend.
#include <gtest/gtest.h>

#include <limits>

#include "core/errors.h"
#include "eval/error_map.h"

namespace vct {
namespace {

TEST(EvalErrorMap, SignSelectsHue) {
    Image ref(4, 1, 1, 0.5f), est = ref;
    est.at(1, 0) = 0.6f;   // +0.1: too bright
    est.at(2, 0) = 0.4f;   // -0.1: too dark
    est.at(3, 0) = 0.55f;  // +0.05: half saturated
    Image map = falseColorError(est, ref, 0.1);
    ASSERT_EQ(map.channels, 3);
    for (int c = 0; c < 3; ++c) EXPECT_GT(map.at(0, 0, c), 0.99f) << "zero error should be white";
    EXPECT_GT(map.at(1, 0, 0), map.at(1, 0, 1) + 0.5f);  // red dominant
    EXPECT_GT(map.at(1, 0, 0), map.at(1, 0, 2) + 0.5f);
    EXPECT_GT(map.at(2, 0, 2), map.at(2, 0, 0) + 0.4f);  // blue dominant
    EXPECT_GT(map.at(2, 0, 2), map.at(2, 0, 1) + 0.4f);
    // Half the error is halfway between white and saturated red (linear ramp).
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(map.at(3, 0, c), 0.5f * (1.f + map.at(1, 0, c)), 1e-5f);
}

TEST(EvalErrorMap, SaturatesAtScale) {
    Image ref(2, 1, 1, 0.f), est(2, 1, 1, 0.f);
    est.at(0, 0) = 0.2f;
    est.at(1, 0) = 5.f;
    Image map = falseColorError(est, ref, 0.2);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(map.at(0, 0, c), map.at(1, 0, c));
}

TEST(EvalErrorMap, MaskedPixelsAreGrey) {
    Image ref(3, 1, 1, 0.f), est(3, 1, 1, 0.3f), mask(3, 1, 1, 1.f);
    mask.at(1, 0) = 0.f;
    Image map = falseColorError(est, ref, 0.1, &mask);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(map.at(1, 0, c), kMaskedGrey);
    EXPECT_GT(map.at(0, 0, 0), map.at(0, 0, 2));
}

TEST(EvalErrorMap, LegendRunsBlueWhiteRed) {
    Image legend = falseColorLegend(101, 8, 0.05);
    ASSERT_EQ(legend.width, 101);
    ASSERT_EQ(legend.height, 8);
    EXPECT_GT(legend.at(0, 4, 2), legend.at(0, 4, 0) + 0.4f);      // left: blue
    EXPECT_GT(legend.at(100, 4, 0), legend.at(100, 4, 2) + 0.4f);  // right: red
    for (int c = 0; c < 3; ++c) EXPECT_GT(legend.at(50, 0, c), 0.99f);  // centre column: white
    for (int c = 0; c < 3; ++c) EXPECT_EQ(legend.at(10, 0, c), legend.at(10, 7, c));  // constant columns
    EXPECT_THROW(falseColorLegend(0, 8, 0.05), InternalError);
    EXPECT_THROW(falseColorLegend(8, 8, 0.0), InternalError);
}

TEST(EvalErrorMap, RejectsBadInput) {
    Image ref(2, 2, 1, 0.f), est = ref;
    EXPECT_THROW(falseColorError(est, ref, -1.0), InternalError);
    est.at(1, 1) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(falseColorError(est, ref, 0.1), InternalError);
}

}  // namespace
}  // namespace vct
