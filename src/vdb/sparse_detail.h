// Helpers shared by the files of src/vdb (internal).
#pragma once

#include "vdb/sparse_voxels.h"

#include <chrono>

namespace vct::vdbdetail {

// Read-only accessor, not registered with its tree (trees are not modified while read).
template <typename TreeT>
using ConstAcc = openvdb::tree::ValueAccessor<const TreeT, false>;

// Index-to-world transform of level `level`: voxel (i, j, k) is centred at
// origin + (ijk + 0.5) * voxelSize * resolution / levelSize(level).
openvdb::math::Transform::Ptr levelTransform(const SparseVoxelScene& voxels, int level);

// Calls openvdb::initialize() once per process.
void ensureOpenVdb();

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace vct::vdbdetail
