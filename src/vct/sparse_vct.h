// --backend vdb: sparse OpenVDB voxels and the CPU cone tracer (src/vdb), on the same
// G-buffer points as every other method. The dense path's region and directional levels; direct
// light only (no bounces between voxels).
#pragma once

#include "cone/cone_settings.h"
#include "core/method.h"
#include "vdb/sparse_cone.h"
#include "vdb/sparse_voxels.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vct {

// The sparse grids a session keeps, keyed as the dense ones (vct/voxel_volume.h).
struct SparseVolumeCache {
    std::map<std::string, std::shared_ptr<SparseVoxelScene>> grids;
};

// What the AO and GI cones of one render share: the grids and the G-buffer's points.
struct SparseFrame {
    std::shared_ptr<SparseVoxelScene> voxels;
    std::vector<SparsePoint> points;
};

// The render's sparse grids and points (built once per render, the grids reused across the
// session unless request.reuseSceneData is false); fills extra["voxels"].
SparseFrame& sparseFrameFor(MethodContext& ctx, SparseVolumeCache& cache, const ConeSettings& cone);

// The sparse grids and points the method built in this render (after it ran with --backend
// vdb), for tools that look inside its march (eval/convergence.h's lane trace). Throws
// InternalError when it built none.
const SparseFrame& renderedSparseFrame(MethodContext& ctx);

// The cone pass of `kind` over the sparse grids: AO into kAo, GI into kGiIndirect.
void traceSparse(MethodContext& ctx, MethodKind kind, const SparseFrame& frame, const ConeSettings& cone);

}  // namespace vct
