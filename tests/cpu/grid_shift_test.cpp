// vct.grid-shift (shiftedGridRegion, src/vct/voxel_region.h) against the grid layout both
// backends build (makeGridLayout): the same voxel size and counts, every world point's voxel
// coordinates larger by the shift, and the region still inside the grid.
#include "scene/scene.h"
#include "vct/voxel_region.h"
#include "voxelize/voxel_grid.h"

#include <gtest/gtest.h>

namespace vct {
namespace {

TEST(GridShift, TheLatticeMovesByTheShiftAndKeepsTheRegion) {
    Bounds3 b;
    b.expand(glm::vec3(-2.5f, -0.1f, -3.f));
    b.expand(glm::vec3(4.f, 1.2f, 2.25f));
    for (int res : {16, 64, 256})
        for (float f : {-0.99f, -0.25f, 0.25f, 0.5f, 0.99f}) {
            const VoxelGrid before = makeGridLayout(b, res);
            const Bounds3 moved = shiftedGridRegion(b, f, res);
            const VoxelGrid after = makeGridLayout(moved, res);
            EXPECT_FLOAT_EQ(after.voxelSize, before.voxelSize) << res << " " << f;
            EXPECT_EQ(after.resolution, before.resolution) << res << " " << f;
            for (const glm::vec3 p : {b.min, b.max, b.center(), glm::vec3(0.3f, 0.7f, -1.1f)}) {
                const glm::vec3 u0 = (p - before.origin) / before.voxelSize;
                const glm::vec3 u1 = (p - after.origin) / after.voxelSize;
                for (int a = 0; a < 3; ++a) EXPECT_NEAR(u1[a] - u0[a], f, 2e-3f) << res << " " << f << " axis " << a;
                // Inside the grid, with the corners in its outermost voxels at worst.
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GT(u1[a], 0.f) << res << " " << f;
                    EXPECT_LT(u1[a], float(after.resolution[a])) << res << " " << f;
                }
            }
        }
    // No shift, no change.
    const Bounds3 same = shiftedGridRegion(b, 0.f, 64);
    EXPECT_EQ(same.min, b.min);
    EXPECT_EQ(same.max, b.max);
}

}  // namespace
}  // namespace vct
