// The programs of voxelization, injection, mips and clipmap nesting, each built by one key
// function (gl/program_cache.h) so the passes and the list of every variant agree.
#pragma once

#include "gl/program_cache.h"

#include <vector>

namespace vct {

// The voxelizer's accumulation passes, each its own source binding its own images.
enum class VoxelizePass {
    Geometry,  // voxelize.glsl: albedo, normal, weight (and the doubleSided weight)
    Emission,  // voxelize_emission.glsl: the emission sums
    Coverage,  // voxelize_coverage.glsl: the columns' covered areas and axes (vct.voxel.edges=coverage)
};
// One accumulation pass, small or big-triangle; the geometry pass sums the doubleSided weight
// when `twoSided`, and only the weight when `opacityOnly` (an AO grid).
// `sheets`: the coverage pass also keeps each voxel's sheet span (vct.voxel.edges=sheet).
ProgramKey voxelizeProgramKey(VoxelizePass pass, bool bigPass, bool twoSided, bool opacityOnly = false,
                              bool sheets = false);
// voxelize_sheets.glsl: level 0's sheet texels (vct.voxel.edges=sheet).
ProgramKey sheetsProgramKey();
// resolve.glsl: reads the emission accumulators when the scene has emission; writes emission
// in `emissionFormat` (GL_RGBA16F or GL_RGBA32F); `twoSided`: the two-sided texture too;
// `opacityOnly`: opacity alone (an AO grid); `edgeCoverage`: opacity from the coverage pass.
ProgramKey resolveProgramKey(bool hasEmission, GLenum emissionFormat, bool twoSided, bool opacityOnly = false,
                             bool edgeCoverage = false);
// inject.glsl: radiance in `radianceFormat`; `outerLevels` clipmap levels continue shadow rays;
// `twoSided`: two-sided voxels lit on each face (voxelize_shared.h); `lightBatches`: one of
// several dispatches that each sum a slice of the lights (injectLightsPerDispatch).
ProgramKey injectProgramKey(GLenum radianceFormat, int outerLevels, bool twoSided, bool lightBatches);
// mip_iso.glsl: opacity, and radiance (radianceFormat != 0) and normals when the grid has them.
ProgramKey isotropicMipProgramKey(GLenum radianceFormat, bool normals);
// mip_aniso.glsl: one directional level from `srcFormat` (GL_R16F: the opacity base level);
// `packedOpacity`: an AO grid's levels, the three axes' opacity in one (VoxelGrid::anisoOpacity).
ProgramKey anisotropicMipProgramKey(GLenum srcFormat, GLenum dstFormat, bool packedOpacity);
// clipmap_nest.glsl: a finer level's means into the coarser level's voxels they fill, in `dstFormat`.
ProgramKey clipmapNestProgramKey(GLenum dstFormat);

// Every variant the functions above can return for the formats the grids use.
std::vector<ProgramKey> voxelProgramVariants();

}  // namespace vct
