// The GL resources the renderer sizes from its inputs stay within what OpenGL 4.5
// guarantees at every voxel resolution it accepts: 2048 texels per 3D texture axis, 128 MiB
// per shader storage buffer binding (GL_MAX_SHADER_STORAGE_BLOCK_SIZE's minimum).
#include "cone/cone_bounce.h"
#include "core/request.h"
#include "voxelize/voxel_grid.h"

#include <gtest/gtest.h>

using namespace vct;

TEST(GlResourceBounds, GridsFitThe3DTextureSizeAtEveryAcceptedResolution) {
    const Bounds3 shapes[] = {{glm::vec3(0.f), glm::vec3(1.f)},
                              {glm::vec3(-40.f, 0.f, -40.f), glm::vec3(40.f, 0.1f, 40.f)},  // a floor
                              {glm::vec3(0.f), glm::vec3(1e-4f, 1e5f, 3.f)}};
    for (const Bounds3& b : shapes)
        for (int res : {kMinVoxelRes, 128, 513, kMaxVoxelRes}) {
            const VoxelGrid g = makeGridLayout(b, res);
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(g.resolution[a], 1);
                EXPECT_LE(g.resolution[a], 2048) << "res " << res << " axis " << a;
            }
        }
}

TEST(GlResourceBounds, BounceListsFitOneStorageBindingAtEveryAcceptedResolution) {
    const size_t bindingBytes = size_t(1) << 27;
    for (int res : {kMinVoxelRes, 64, 256, 512, kMaxVoxelRes}) {
        const glm::ivec3 r(res, res / 2 + 1, res);
        const size_t voxels = size_t(r.x) * r.y * r.z;
        for (size_t occupied : {size_t(0), voxels / 20, voxels}) {
            const std::vector<VoxelListSlab> slabs = voxelListSlabs(r, occupied);
            ASSERT_FALSE(slabs.empty());
            EXPECT_EQ(slabs.front().z0, 0);
            EXPECT_EQ(slabs.back().z1, r.z);
            size_t room = 0;
            for (size_t i = 0; i < slabs.size(); ++i) {
                if (i > 0) {
                    EXPECT_EQ(slabs[i].z0, slabs[i - 1].z1);
                }
                EXPECT_LE((1 + slabs[i].capacity) * sizeof(uint32_t), bindingBytes) << "res " << res;
                // Room for every voxel of the slab, or for every occupied voxel of the grid.
                const size_t slabVoxels = size_t(r.x) * r.y * (slabs[i].z1 - slabs[i].z0);
                EXPECT_EQ(slabs[i].capacity, std::min(slabVoxels, occupied));
                room += slabs[i].capacity;
            }
            EXPECT_GE(room, occupied);
        }
    }
    // A 256^3 grid needs one list; a full 1024^3 one splits.
    EXPECT_EQ(voxelListSlabs(glm::ivec3(256), size_t(256) * 256 * 256).size(), 1u);
    EXPECT_GT(voxelListSlabs(glm::ivec3(1024), size_t(1024) * 1024 * 1024).size(), 1u);
}
