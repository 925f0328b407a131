// The passes of voxel cone tracing and the resources between them: voxelize -> (inject and
// bounces) -> mips -> cone_ao / cone_gi, and the voxel_* views of the grid.
#pragma once

#include "core/pass.h"

#include <string>

namespace vct {

// The name of both VCT methods (--ao vct, --gi vct).
inline constexpr const char* kVctMethodName = "vct";

inline constexpr PassId kPassVoxelize{"voxelize"};
inline constexpr PassId kPassInject{"inject"};
inline constexpr PassId kPassMips{"mips"};
inline constexpr PassId kPassConeAo{"cone_ao"};
inline constexpr PassId kPassConeGi{"cone_gi"};
inline constexpr PassId kPassVoxelView{"voxel_view"};

inline constexpr ResourceId kVoxels{"voxels"};
inline constexpr ResourceId kVoxelRadiance{"radiance"};
inline constexpr ResourceId kVoxelMips{"voxel_mips"};
inline constexpr ResourceId kVoxelView{"voxel_view"};

}  // namespace vct
