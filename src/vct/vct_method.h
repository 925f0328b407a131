// Voxel cone tracing as two methods of the registry: --ao vct (world-space AO cones over the
// voxels' opacity) and --gi vct (diffuse GI cones over their radiance). Both share one
// voxelization per render (and per session, through the grid cache), on the dense GPU grid,
// a clipmap, or the sparse CPU grids (--backend vdb).
#pragma once

#include "core/method.h"

namespace vct {

const Method& vctAoMethod();
const Method& vctGiMethod();

}  // namespace vct
