// Writing the sparse voxels to an OpenVDB file and reading them back.
//
// Grids: "opacity", "albedo", "normal", "emission", "radiance" (when injected) at level 0, and
// "opacity_L<k>", "radiance_L<k>" for the coarser levels; each grid's transform maps its index
// space to world space (see sparse_voxels.h). File metadata: "scene" (name), "voxel_size",
// "origin", "resolution", "levels", "bounds_min" / "bounds_max" (world box of the grid),
// "generator". Written to "<path>.tmp" and renamed, so a reader never sees half a file.
#pragma once

#include "vdb/sparse_voxels.h"

#include <string>

namespace vct {

void writeVdb(const SparseVoxelScene& voxels, const std::string& path, const std::string& sceneName);

// Reads every grid written by writeVdb (throws std::runtime_error naming the file or the
// missing grid/metadata). Stats: memory and active counts recomputed, times 0.
SparseVoxelScene readVdb(const std::string& path);

}  // namespace vct
