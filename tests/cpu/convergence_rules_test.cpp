// The rules the convergence tables apply (eval/convergence.h) and the schedule that refines
// the cone set with the voxels: each rule on error sequences whose verdict follows from its
// definition by hand, at and around its thresholds.
#include "core/errors.h"
#include "eval/convergence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vct {
namespace {

TEST(ConvergenceRules, VoxelErrorMustFallByHalfAgainPerDoublingAndEndAtMostTwoHundredths) {
    EXPECT_TRUE(voxelErrorConverges({0.12, 0.08, 0.04, 0.02}));     // 1.5x, 2x, 2x; 0.02 at the end
    EXPECT_FALSE(voxelErrorConverges({0.12, 0.09, 0.04, 0.02}));    // 1.33x on the first doubling
    EXPECT_FALSE(voxelErrorConverges({0.24, 0.12, 0.06, 0.03}));    // falls 2x but ends above 0.02
    EXPECT_FALSE(voxelErrorConverges({0.05, 0.1, 0.03, 0.015}));    // grows once
    // Below 0.01 a step only has to stay below 0.01, whatever the previous one was.
    EXPECT_TRUE(voxelErrorConverges({0.05, 0.009, 0.0095, 0.0099}));
    EXPECT_FALSE(voxelErrorConverges({0.05, 0.009, 0.0101, 0.005}));  // 0.0101: neither 1.5x nor below
    EXPECT_TRUE(voxelErrorConverges({0.015}));                        // one step: the end rule alone
    EXPECT_FALSE(voxelErrorConverges({}));
    EXPECT_FALSE(voxelErrorConverges({0.1, 0.05, std::nan("")}));
}

TEST(ConvergenceRules, TotalErrorMustNeverGrowAndEndAtMostFiveHundredths) {
    EXPECT_TRUE(totalErrorRefines({0.09, 0.05, 0.05}));   // equal steps do not grow
    EXPECT_FALSE(totalErrorRefines({0.03, 0.031, 0.02}));  // grows once, however little
    EXPECT_FALSE(totalErrorRefines({0.2, 0.1, 0.051}));    // never grows but ends above 0.05
    EXPECT_TRUE(totalErrorRefines({0.04}));
    EXPECT_FALSE(totalErrorRefines({}));
}

TEST(ConeSchedule, ParsesResolutionsConesAndOptionalLanes) {
    const std::vector<ConeScheduleStep> s = parseConeSchedule("64:6,128:16,256:64:64");
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].voxelRes, 64);
    EXPECT_EQ(s[0].cones, 6);
    EXPECT_EQ(s[0].lanes, 0);  // auto
    EXPECT_EQ(s[1].voxelRes, 128);
    EXPECT_EQ(s[1].cones, 16);
    EXPECT_EQ(s[2].voxelRes, 256);
    EXPECT_EQ(s[2].cones, 64);
    EXPECT_EQ(s[2].lanes, 64);
}

TEST(ConeSchedule, BadStepsAreNamed) {
    auto message = [](const std::string& text) {
        try {
            parseConeSchedule(text);
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("64:6,128:x").find("step 2 '128:x'"), std::string::npos) << message("64:6,128:x");
    EXPECT_NE(message("64").find("RES:CONES"), std::string::npos);
    EXPECT_NE(message("64:6:4:2").find("step 1"), std::string::npos);
    EXPECT_NE(message("128:16,64:6").find("increase"), std::string::npos);
    EXPECT_NE(message("64:-6").find("'-6'"), std::string::npos);
    EXPECT_NE(message("64:6.5").find("'6.5'"), std::string::npos);
    EXPECT_NE(message("").find("no steps"), std::string::npos);
    EXPECT_NE(message("64:6,,128:16").find("step 2"), std::string::npos);
}

}  // namespace
}  // namespace vct
