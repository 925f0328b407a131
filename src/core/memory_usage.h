// What a run costs in memory, as the operating system counts it: the process's peak resident
// set. It holds every allocation, not only the voxels' own count (SparseVoxelStats::memoryBytes,
// VoxelGrid::memoryBytes): scene, BVH, temporaries of a build, and the GL driver's; on llvmpipe
// the "GPU" textures are process memory too, on a discrete GPU they are not.
#pragma once

#include <cstddef>

namespace vct {

// The process's peak resident memory so far, in bytes (never falls); 0 where the platform does
// not report it.
size_t peakResidentBytes();

}  // namespace vct
