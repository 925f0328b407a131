// Sparse memory grows with surface area, not volume: Sponza at 256 and 512 voxels. Skipped when
// the scene is absent ($VCT_SHARED_SCENES, else VCT_SOURCE_DIR "/../shared/scenes").
#include "scene/gltf_loader.h"
#include "vdb/sparse_voxels.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace vct {
namespace {

TEST(VdbMemory, SponzaGrowsWithSurfaceArea) {
    const char* env = std::getenv("VCT_SHARED_SCENES");
    const std::string path = std::string(env ? env : VCT_SOURCE_DIR "/../shared/scenes") + "/mcguire_sponza.glb";
    if (!std::ifstream(path).good()) GTEST_SKIP() << path << " not found";
    Scene scene = loadScene(path);
    ParamMap params;
    params.set("vct.bounces", "0");  // the grids held do not depend on the bounces
    SparseVoxelScene v256 = buildSparseVoxels(scene, 256, true, 1.f, params);
    const SparseVoxelStats s256 = v256.stats;
    v256 = SparseVoxelScene{};
    SparseVoxelScene v512 = buildSparseVoxels(scene, 512, true, 1.f, params);
    const SparseVoxelStats& s = v512.stats;
    std::printf("[vdb_memory] Sponza 512: %zu active voxels, sparse %.1f MiB, dense res^3 %.1f MiB (%.1f%%), "
                "dense %dx%dx%d %.1f MiB (%.1f%%); 256 -> 512 memory x%.2f, active x%.2f\n",
                s.activeVoxels, s.memoryBytes / 1048576.0, s.denseCubeBytes / 1048576.0,
                100.0 * s.memoryBytes / s.denseCubeBytes, v512.resolution.x, v512.resolution.y, v512.resolution.z,
                s.denseBytes / 1048576.0, 100.0 * s.memoryBytes / s.denseBytes,
                double(s.memoryBytes) / s256.memoryBytes, double(s.activeVoxels) / s256.activeVoxels);
    // The convention: dense = res^3 x bytes per voxel of the same channels.
    EXPECT_LT(double(s.memoryBytes), 0.15 * double(s.denseCubeBytes));
    // Surfaces: doubling the resolution multiplies voxels by ~4, a dense grid by 8.
    EXPECT_LT(double(s.activeVoxels) / s256.activeVoxels, 5.0);
    EXPECT_LT(double(s.memoryBytes) / s256.memoryBytes, 6.0);
}

}  // namespace
}  // namespace vct
