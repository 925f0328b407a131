// The sparse (OpenVDB, CPU) counterpart of the dense GPU voxel grid of voxelize/voxel_grid.h.
// It computes the same quantities on the same layout (makeGridLayout), so the two backends can
// be compared voxel for voxel and image for image:
//
// - level 0: opacity (1 where a triangle overlaps the voxel, conservative SAT), albedo, unit
//   normal and emission as area-weighted averages, quantized exactly as the GPU shader does
//   (12-bit albedo/normal, 2^-12 emission, integer weights in [1, 16]); integer sums make the
//   result independent of triangle order and thread count, bit for bit;
// - radiance: emission + albedo / pi * E, E from the punctual lights with visibility marched
//   through the level-0 opacity (same offsets, units and spot falloff as inject.glsl), stored
//   premultiplied (rgb * opacity; its alpha is the opacity grid of the same level);
// - levels 1..: the mean of the 2x2x2 children (3 along an axis at its last voxel when the
//   finer size is odd, as mip_common.glsl), empty children count as 0;
// - optionally the directional levels of mip_aniso.glsl (Crassin 2011): levels 1.. once per
//   direction of travel (+X, -X, +Y, -Y, +Z, -Z), the children of each line along the axis
//   composited front to back and the lines across it averaged, the first from level 0 and
//   each next from the same direction's previous level.
//
// Index space: level-k voxel (i, j, k) covers voxel units [i, i + 1] * resolution / size_k
// (size_k = max(resolution >> k, 1) per axis, as GL mip sizes); each grid's transform maps it
// to world space. Only voxels with content are active; everything else reads 0 (the GL zero
// border and empty space alike).
#pragma once

#include "core/params.h"
#include "scene/scene.h"

#include <glm/glm.hpp>
#include <openvdb/openvdb.h>

#include <array>
#include <string>
#include <vector>

namespace vct {

struct SparseVoxelStats {
    size_t activeVoxels = 0;     // level-0 occupied voxels
    size_t leafNodes = 0;        // level-0 leaf nodes (8^3 voxels each)
    size_t memoryBytes = 0;      // tree memUsage of every grid and level held
    size_t denseBytes = 0;       // same channels (float32) over the dense non-cubic grid and its mips
    size_t denseCubeBytes = 0;   // same channels over resolution^3 (the "res^3" convention)
    double voxelizeSeconds = 0.0;
    double injectSeconds = 0.0;
    double levelsSeconds = 0.0;
    double bounceSeconds = 0.0;  // vct.bounces, levels rebuilt for each bounce included
};

struct SparseVoxelScene {
    glm::ivec3 resolution{0};   // level-0 voxels per axis (makeGridLayout)
    float voxelSize = 0.f;      // world units
    glm::vec3 origin{0.f};      // world position of the grid's min corner
    int levels = 1;             // as VoxelGrid::levels: floor(log2(max resolution)) + 1
    glm::mat4 voxelFromWorld{1.f};
    glm::mat4 worldFromVoxel{1.f};
    std::string sceneName;

    openvdb::FloatGrid::Ptr opacity;    // level 0 (== opacityLevels[0])
    openvdb::Vec3SGrid::Ptr albedo;     // level 0, average linear albedo
    openvdb::Vec3SGrid::Ptr normal;     // level 0, average unit normal (0 where faces cancel)
    openvdb::Vec3SGrid::Ptr emission;   // level 0, average emitted radiance
    // Level 0, present when a material is doubleSided: the share of each voxel's weight whose
    // material is doubleSided (two-sided voxels: shaders/voxelize/voxelize_shared.h).
    openvdb::FloatGrid::Ptr twoSided;
    // Level 0, vct.voxel.edges=sheet: (lo, hi, axis) of each voxel whose surfaces share one
    // dominant axis, their span along it inside the voxel ([0, 1]); inactive elsewhere
    // (vox_sheetTexel; read with the opacity by gpu::cone_sampleSheets).
    openvdb::Vec3SGrid::Ptr sheet;
    // Level 0, with `sheet`: every occupied voxel's extent bits (vox_extentBits), where in it
    // along each axis its surfaces lie (cone_sampleSheets).
    std::shared_ptr<openvdb::UInt32Tree> sheetExtent;
    // Level 0, set by injection when the scene has two-sided voxels: `normal`, with each
    // two-sided voxel's facing normal in place of its own (the GPU rewrites its normal texture).
    openvdb::Vec3SGrid::Ptr facingNormal;
    openvdb::Vec3SGrid::Ptr radiance;   // level 0, premultiplied; null unless injected
    std::vector<openvdb::FloatGrid::Ptr> opacityLevels;    // [0, levels)
    std::vector<openvdb::Vec3SGrid::Ptr> radianceLevels;   // [0, levels) when injected, else empty
    // [0, levels) when injected: mean of the children's normals (inactive = 0), so divided by
    // the opacity level it is the occupied voxels' mean normal (GPU: the normal mips).
    std::vector<openvdb::Vec3SGrid::Ptr> normalLevels;

    // The directional levels (mip_aniso.glsl), empty unless built: directional[d][k] is
    // pyramid level k + 1 as seen by a cone travelling along direction d (+X, -X, +Y, -Y, +Z,
    // -Z, the GPU's anisoRadiance order); radiance premultiplied, held when injected.
    struct DirectionalLevel {
        openvdb::FloatGrid::Ptr opacity;
        openvdb::Vec3SGrid::Ptr radiance;  // null unless injected
    };
    std::array<std::vector<DirectionalLevel>, 6> directional;
    // The directional levels hold optical depth (opacity tau, radiance * tau):
    // shaders/voxelize/opacity_depth.h, vct.opacity=depth.
    bool depthLevels = false;

    SparseVoxelStats stats;

    bool injected() const { return bool(radiance); }
    // The normals the facing test and the bounces read at level 0.
    const openvdb::Vec3SGrid::Ptr& facing() const { return facingNormal ? facingNormal : normal; }
    bool anisotropic() const { return !directional[0].empty(); }
    // Voxels per axis of level k (GL mip sizes).
    glm::ivec3 levelSize(int level) const { return glm::max(resolution >> level, glm::ivec3(1)); }
};

// Voxelizes `scene` (grid fitted to scene.bounds with `voxelRes` voxels along the longest axis,
// [4, 1024]), optionally injects direct light + emission, and builds the levels. TBB parallel;
// the result is bit-identical for any thread count. ParamMap keys (shared with the GPU path):
//   vct.inject.offset    0..16 voxels, default 2: where shadow marches start along the normal.
//   vct.bounces, vct.bounce.sky, vct.bounce.emitters: the diffuse bounces between voxels (traceSparseBounces),
//                        traced with the cone settings of `params`, as the GPU path's.
//   vct.voxel.precision: read for parity with the GPU path; the sparse grids always hold
//                        float32.
SparseVoxelScene buildSparseVoxels(const Scene& scene, int voxelRes, bool inject, float sky,
                                   const ParamMap& params);

// What the GPU path chooses per render and the sparse one follows: the grid's world box (the
// dense path's region, voxelRes voxels along its longest axis) and the directional levels.
struct SparseBuildOptions {
    Bounds3 region;            // empty: the scene's bounds
    bool anisotropic = false;  // also build the directional levels (the GPU path's vct.aniso)
    bool depthLevels = false;  // hold them as optical depth (vct.opacity=depth)
    // false (AO, not injected): level 0 holds opacity alone, voxelized without albedo, normal
    // or emission (the dense path's grid without attributes, voxelize.h)
    bool attributes = true;
};
SparseVoxelScene buildSparseVoxels(const Scene& scene, int voxelRes, bool inject, float sky,
                                   const ParamMap& params, const SparseBuildOptions& options);

// The steps of buildSparseVoxels, for tests and tools.
SparseVoxelScene voxelizeSparse(const Scene& scene, int voxelRes);
// Over `region` instead of the scene's bounds: triangles outside it are left out. `lit` (the
// voxels will be injected): also the two-sided share where a material is doubleSided, which
// only injection reads (voxelizeGrid's `lit`). `attributes` false and not `lit` (AO): opacity
// alone, no albedo, normal or emission grids, and no per-voxel sums while voxelizing (the
// same opacity: level 0 is 1 on every occupied voxel). `edgeCoverage` (vct.voxel.edges=coverage):
// level 0 holds the share of each voxel's column its sheets cover (vox_edgeOpacity); `sheets`
// (vct.voxel.edges=sheet): that, and `sheet`, where in its voxel each sheet lies.
SparseVoxelScene voxelizeSparse(const Scene& scene, const Bounds3& region, int voxelRes, bool lit = true,
                                bool attributes = true, bool edgeCoverage = false, bool sheets = false);
void injectSparseRadiance(SparseVoxelScene& voxels, const Scene& scene, float shadowOffsetVoxels);
void buildSparseLevels(SparseVoxelScene& voxels, bool anisotropic = false, bool depthLevels = false);
// Recomputes stats.memoryBytes / denseBytes / activeVoxels from the grids held.
void updateSparseMemoryStats(SparseVoxelScene& voxels);

}  // namespace vct
