// The cone passes' programs, each built by one key function (gl/program_cache.h) so the
// passes and the list of every variant agree.
#pragma once

#include "gl/program_cache.h"

#include <vector>

namespace vct {

// Which directional levels a cone pass samples (VoxelGrid): none (the isotropic mips), a lit
// grid's six RGBA textures, or an AO grid's one texture of the three axes' opacity (AO only).
enum class ConeDirectional { None, Six, Packed };

// cone_ao.glsl / cone_gi.glsl over one dense grid, with its directional levels or without;
// `depthLevels`: the directional levels hold optical depth (VoxelGrid::depthLevels);
// `sharpen`: they are read with vct.sharpen's filter (the CONE_SHARPEN variant). Both are
// ignored without directional levels; `sheets`: the base level's opacity is read from its
// sheet texels (VoxelGrid::sheets, the CONE_SHEETS variant; ignored without directional levels).
ProgramKey conePassProgramKey(bool gi, ConeDirectional directional, bool depthLevels, bool sharpen,
                              bool sheets = false);
// The same over a clipmap's levels (isotropic).
ProgramKey clipmapConePassProgramKey(bool gi);
// The resolve stage of a reduced-resolution AO or GI pass (cone_resolve.glsl): one program
// for every volume, since it marches no cones and reads none.
ProgramKey coneResolveProgramKey(bool gi);
// cone_bounce.glsl's three passes: list the voxels that gather, write the emission alone (the
// first gather's source in a scene with emitters), and the gather of one bounce
// (`depthLevels` and `sharpen` as above; the other two ignore them).
enum class BouncePass { List, Emitted, Gather };
ProgramKey coneBounceProgramKey(bool aniso, GLenum radianceFormat, BouncePass pass, bool depthLevels, bool sharpen);
// cone_raymarch.glsl: the voxel_* views; channel is gpu::CONE_CHANNEL_*.
ProgramKey voxelViewProgramKey(int channel);
// bench/: the cone pass with a fetch counter, and the bare trilinear-fetch shader.
ProgramKey coneCountProgramKey(bool gi, ConeDirectional directional, bool depthLevels, bool sharpen,
                               bool sheets = false);
ProgramKey fetchBenchProgramKey();
// cone_march_check.glsl: the shared march's functions on a buffer of inputs (the test that
// holds the CPU tracer's march to the shaders').
ProgramKey coneMarchCheckProgramKey();

// Every variant the functions above can return.
std::vector<ProgramKey> coneProgramVariants();

}  // namespace vct
