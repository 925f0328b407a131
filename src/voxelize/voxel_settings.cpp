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
                  "voxels along the normal where shadow rays of injection start");
    return table;
}

}  // namespace vct
