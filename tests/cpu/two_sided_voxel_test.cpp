// The two-sided voxel encoding of voxelize_shared.h: one radiance texel (the brighter face's)
// and a facing normal scaled by vox_twoSidedNormalScale carry the radiance leaving both faces
// of a doubleSided surface. Checked against what the encoding must reproduce through the
// cones' facing test (vox_facingWeight), which is how the march sees it.
#include "voxelize/voxelize_shared.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vct;

namespace {

const glm::vec3 kFront(0.f, 1.f, 0.f);  // the winding normal

// The radiance a cone travelling along d sees leaving the voxel whose faces emit front / back.
float seen(float front, float back, const glm::vec3& d) {
    const float k = gpu::vox_twoSidedNormalScale(front, back);
    const float stored = k >= 0.f ? front : back;
    return stored * gpu::vox_facingWeight(kFront * k, d);
}

}  // namespace

// Head on, each face shows its own radiance wherever the dimmer one is at least 1/15 of the
// brighter: the facing weight of the dimmer face is their ratio (within 1/128 of the brighter
// face where the scale's floor holds the normal's direction, as the faces become equal).
TEST(TwoSidedVoxel, HeadOnEachFaceShowsItsOwnRadiance) {
    const float floorError = 2.f * gpu::VOX_TWO_SIDED_MIN_SCALE;
    for (float front : {1.f, 3.f, 0.25f})
        for (float ratio : {1.f / 15.f, 0.1f, 0.3f, 0.5f, 0.8f, 0.99f, 1.f}) {
            const float back = front * ratio;
            const float tolerance = (ratio > 0.99f ? floorError : 1e-6f) * front;
            // A cone travelling against the front normal meets the front face.
            EXPECT_NEAR(seen(front, back, -kFront), front, 1e-6f * front) << front << " " << ratio;
            EXPECT_NEAR(seen(front, back, kFront), back, tolerance) << front << " " << ratio;
            // The normal never vanishes: the bounces gather around it.
            EXPECT_GE(std::abs(gpu::vox_twoSidedNormalScale(front, back)), gpu::VOX_TWO_SIDED_MIN_SCALE);
            if (ratio == 1.f) continue;
            // Swapped: the back is the brighter face, and the normal turns to it.
            EXPECT_LT(gpu::vox_twoSidedNormalScale(back, front), 0.f);
            EXPECT_NEAR(seen(back, front, kFront), front, 1e-6f * front) << front << " " << ratio;
            EXPECT_NEAR(seen(back, front, -kFront), back, tolerance) << front << " " << ratio;
        }
    EXPECT_GT(gpu::vox_twoSidedNormalScale(1.f, 1.f), 0.f) << "ties go to the front";
}

// Lit on one face, the voxel is a one-sided surface facing it: the unit normal, so every cone
// that meets the unlit face (dot(n, d) >= 1/2) sees nothing; lit on neither, it keeps its
// winding normal. Below a ratio of 1/15 the dimmer face shows at most its own radiance.
TEST(TwoSidedVoxel, OneLitFaceIsAOneSidedSurfaceAndDimFacesNeverShowTooMuch) {
    EXPECT_FLOAT_EQ(gpu::vox_twoSidedNormalScale(2.f, 0.f), 1.f);
    EXPECT_FLOAT_EQ(gpu::vox_twoSidedNormalScale(0.f, 2.f), -1.f);
    EXPECT_FLOAT_EQ(gpu::vox_twoSidedNormalScale(0.f, 0.f), 1.f);
    EXPECT_FLOAT_EQ(seen(0.f, 2.f, -kFront), 0.f);
    for (float c : {0.5f, 0.7f, 1.f}) {
        const glm::vec3 d = glm::normalize(kFront * c + glm::vec3(1.f, 0.f, 0.f) * std::sqrt(1.f - c * c));
        EXPECT_FLOAT_EQ(seen(2.f, 0.f, d), 0.f) << c;
    }
    for (float ratio = 0.f; ratio <= 1.f; ratio += 1.f / 256.f) {
        const float k = gpu::vox_twoSidedNormalScale(1.f, ratio);
        EXPECT_GE(k, 0.f);
        EXPECT_LE(k, 1.f);
        EXPECT_LE(seen(1.f, ratio, kFront), ratio + 1e-6f) << ratio;
    }
    // Continuous in the ratio: no jump where the two branches meet (1/15).
    const float below = gpu::vox_twoSidedNormalScale(1.f, 1.f / 15.f - 1e-4f);
    const float above = gpu::vox_twoSidedNormalScale(1.f, 1.f / 15.f + 1e-4f);
    EXPECT_NEAR(below, above, 1e-3f);
}
