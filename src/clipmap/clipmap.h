// Clipmap cascades for voxel cone tracing: `levelCount` nested cubic grids of one resolution,
// level l with voxels 2^l times level 0's, all centred (to a voxel) on a focus point near the
// camera, the coarsest one covering the whole region. Each level is voxelized and injected on
// its own (VoxelGrid of src/voxelize, with its own isotropic mips); then, finest first, the
// mean of level l's eight voxels under each voxel of level l + 1 that they fill replaces that
// voxel (clipmap_nest.glsl: level l's mip 1 where the two lattices pair up), so a
// cone sees one consistent pyramid: a dense grid at level 0's resolution near the focus,
// coarser further out. Radiance stays per-area (no voxel-size factor), and the nesting makes
// a level switch change nothing, so brightness does not depend on the number of levels.
//
// Parameters (ParamMap): vct.clipmap.levels  0..8, default 0 (off: one dense grid).
// Anisotropic mips are not built for clipmaps: their directional base would have to nest as
// well; cones over a clipmap use isotropic mips (also 5-10x faster on llvmpipe).
#pragma once

#include "cone/cone_settings.h"
#include "cone/cone_trace.h"
#include "core/gbuffer.h"
#include "core/gpu_scene.h"
#include "core/params.h"
#include "core/timing.h"
#include "core/view.h"
#include "voxelize/voxel_grid.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vct {

// Where the levels lie. Level l's origin is a whole number of its own voxels from `anchor`,
// so every level's voxels lie on one lattice fixed to the region: eight voxels of level l
// fill each voxel of level l + 1 exactly, wherever the two origins stand.
struct ClipmapLayout {
    int levelCount = 0;
    int resolution = 0;          // voxels per axis of every level (a multiple of 4)
    float baseVoxelSize = 0.f;   // level 0's voxel edge, world units
    glm::vec3 anchor{0.f};       // world point from which origins are counted
    std::vector<glm::ivec3> originIndex;  // level l's min corner, in level-0 voxels from anchor
    glm::vec3 focus{0.f};        // the point the levels are centred on
    Bounds3 region;              // what the coarsest level must cover

    float voxelSize(int level) const { return baseVoxelSize * float(1 << level); }
    glm::vec3 origin(int level) const { return anchor + glm::vec3(originIndex[size_t(level)]) * baseVoxelSize; }
    Bounds3 bounds(int level) const;
};

// Levels of `resolution` (rounded up to a multiple of 4, clamped to [32, 512]) on a lattice
// that depends on `region` alone (voxel sizes and anchor): the coarsest level covers the region
// from its centre, each finer one centres on `focus` (moved into `region` first) in steps of one
// of its voxels, clamped inside the next coarser level. A focus that moves less than half a voxel
// of a level keeps that level's voxels; a step moves them by one voxel, never resamples them.
// levelCount in [1, 8].
ClipmapLayout computeClipmapLayout(const Bounds3& region, const glm::vec3& focus, int levelCount, int resolution);

// The point a camera's cascades centre on: a quarter of level 0's span ahead of the eye along
// the view direction. The view sees only what lies in front of it, so a level centred on the
// eye would spend half its voxels behind the camera.
glm::vec3 clipmapFocus(const Bounds3& region, const Camera& camera, int levelCount, int resolution);

struct Clipmap {
    ClipmapLayout layout;
    std::vector<VoxelGrid> levels;  // finest first; isotropic mips; radiance when injected
    std::vector<double> levelMs;    // wall time of each level's voxelize + inject + nest + mips
    size_t memoryBytes = 0;
};

// Voxelizes every level, injects radiance when `inject` (shadow rays leaving a level continue
// through the coarser ones), nests and builds mips. Timer scopes voxelize_lN, inject_lN,
// mips_lN (nesting counts with the mips). Without `attributes` and `inject` (AO) the levels
// hold opacity alone (voxelizeScene).
Clipmap buildClipmap(const GpuScene& gpuScene, const Scene& scene, const ClipmapLayout& layout, bool inject,
                     const ParamMap& params, PassTimer& timer, bool attributes = true);

// Cone traced AO / indirect diffuse over a clipmap: the contracts of coneTraceAO and
// coneTraceGI (cone/cone_trace.h), isotropic mips whatever settings.anisotropic says.
// Timer scopes "cone_ao" / "cone_gi".
GlTexture coneTraceClipmapAO(const Clipmap& clipmap, const GBuffer& gbuffer, const View& view, float radius,
                             const ConeSettings& settings, PassTimer& timer, ConeCost* cost = nullptr);
GlTexture coneTraceClipmapGI(const Clipmap& clipmap, const GBuffer& gbuffer, const View& view, float sky,
                             const ConeSettings& settings, PassTimer& timer, ConeCost* cost = nullptr);

// For --stats: per level extent, voxel size, origin, memory and time; totals.
nlohmann::json clipmapStats(const Clipmap& clipmap);

}  // namespace vct
