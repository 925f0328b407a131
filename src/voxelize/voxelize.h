// Building the VoxelGrid of voxel_grid.h on the GPU: conservative voxelization of the scene's
// triangles, direct-light (+ optional multi-bounce) radiance injection, and mip pyramids.
//
// Typical use (GI):   grid = voxelizeScene(...); injectRadiance(grid, ...);
//                     [traceVoxelBounces(grid, ...) (cone/cone_bounce.h);] buildMips(grid, aniso, ...)
// AO only:            grid = voxelizeScene(...); buildMips(grid, aniso, ...)
//   (grid.radiance stays empty - id 0 - and buildMips builds opacity mips only; anisotropic
//   textures then carry rgb = 0 and the directional opacity in alpha.)
//
// Keys, defaults, ranges and docs: voxelSettings() (vct.voxel.precision, vct.inject.offset,
// vct.inject.dispatch-lights).
#pragma once

#include "core/gpu_scene.h"
#include "core/params.h"
#include "voxelize/voxel_settings.h"
#include "core/timing.h"
#include "voxelize/voxel_grid.h"

#include <string>
#include <vector>

namespace vct {

// Conservative voxelization of every triangle overlapping `region` (Akenine-Moller SAT per
// candidate voxel; no holes for thin, sub-voxel or axis-aligned triangles). Averages are
// order independent (integer atomics), so the same input gives the same grid bit for bit.
// Fills opacity (level 0; 1 where any triangle overlaps), albedo, normal, emission,
// occupiedVoxels and memoryBytes; `lit` (the grid will be lit by injectRadiance) also the
// two-sided texture where a material is doubleSided, which only injection reads. Without
// `attributes` and `lit` (a grid for AO, which reads opacity alone) albedo, normal and
// emission stay empty and only the weight is accumulated, one accumulator instead of seven or
// more: Sponza's AO grid at 512^3 with its directional levels holds 99 MB instead of 827 and
// voxelizes in a third of the time, the same AO bit for bit. Timer scope "voxelize".
VoxelGrid voxelizeScene(const GpuScene& scene, const Bounds3& region, int voxelRes,
                        const ParamMap& params, PassTimer& timer, bool lit = true, bool attributes = true);

// The same into a given layout (makeGridLayout; textures of `layout` are ignored): clipmap
// levels whose origins and voxel sizes must nest exactly. Timer scope `scopeName`.
VoxelGrid voxelizeGrid(const GpuScene& scene, VoxelGrid layout, const ParamMap& params, PassTimer& timer,
                       const std::string& scopeName = "voxelize", bool lit = true, bool attributes = true);

// Lights per injection dispatch: as many as the loop budget (common/loop_budget.h) holds
// lights whose shadow walks may each cross this grid (`resolution`) and `outerLevels` outer
// levels of `outerResolution` voxels, twice for `twoSided` grids; at least 1, at most
// `requested` when it is > 0 (vct.inject.dispatch-lights). More lights than this split the
// pass over dispatches that carry the irradiance summed so far.
int injectLightsPerDispatch(const glm::ivec3& resolution, int outerLevels, int outerResolution, bool twoSided,
                            int requested);

// Writes grid.radiance level 0: premultiplied (L * opacity, opacity), where L = emission +
// albedo / pi * sum of the punctual lights' irradiance on the voxel's average normal, each
// with visibility from a ray marched through the opacity grid (glTF KHR_lights_punctual
// units). Further bounces are cone/cone_bounce.h's (traceVoxelBounces). Call buildMips
// afterwards. Timer scope "inject". More lights than injectLightsPerDispatch allows take
// several dispatches, with the same sums.
//
// `outerLevels` (clipmaps, src/clipmap): voxelized coarser grids that contain this one,
// innermost first (at most 7, cubic, of this grid's resolution); shadow rays leaving this
// grid continue through them. `scopeName` replaces the timer scope's name.
void injectRadiance(VoxelGrid& grid, const GpuScene& gpuScene, const Scene& scene,
                    const ParamMap& params, PassTimer& timer,
                    const std::vector<const VoxelGrid*>& outerLevels = {},
                    const std::string& scopeName = "inject");

// Isotropic mips of opacity and (if injected) radiance: the mean of the 2x2x2 children (3
// along an axis whose size is odd, at its last voxel, so no geometry is dropped). With
// `anisotropic`, also the six directional textures of the contract; `depthLevels` stores them
// as optical depth (shaders/voxelize/opacity_depth.h; grid.depthLevels says so). Timer scope
// "mips".
void buildMips(VoxelGrid& grid, bool anisotropic, PassTimer& timer, const std::string& scopeName = "mips",
               bool depthLevels = false);

// GPU bytes of every texture held by the grid (queried from GL).
size_t voxelGridMemoryBytes(const VoxelGrid& grid);

}  // namespace vct
