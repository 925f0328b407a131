#include "voxelize/voxel_settings.h"

namespace vct {

const SettingsTable<VoxelSettings>& voxelSettings() {
    static const auto table =
        SettingsTable<VoxelSettings>()
            .choice("vct.voxel.precision", &VoxelSettings::precision,
                    {{"auto", VoxelPrecision::Auto}, {"half", VoxelPrecision::Half}, {"float", VoxelPrecision::Float}},
                    "storage of emission/radiance: half (RGBA16F, clamps at 65504), float (RGBA32F), auto = float "
                    "when emission or lights exceed the half range")
            .real("vct.inject.offset", &VoxelSettings::injectOffset, 0.f, 16.f,
                  "voxels along the normal where shadow rays of injection start")
            .integer("vct.inject.dispatch-lights", &VoxelSettings::dispatchLights, 0, 1 << 20,
                     "at most this many lights per injection dispatch; 0 = as many as fit the loop budget a driver "
                     "allows one invocation (llvmpipe ends an invocation's loops after 65535 iterations, and each "
                     "light's shadow walk can cross the grid). The dispatches carry their sums, so the radiance is "
                     "the same for any value (dense grid)");
    return table;
}

}  // namespace vct
