// The cone passes' programs, each built by one key function (gl/program_cache.h) so the
// passes and the list of every variant agree.
#pragma once

#include "gl/program_cache.h"

#include <vector>

namespace vct {

// cone_ao.glsl / cone_gi.glsl over one dense grid, with or without the directional mips.
ProgramKey conePassProgramKey(bool gi, bool aniso);
// The same over a clipmap's levels (isotropic).
ProgramKey clipmapConePassProgramKey(bool gi);
// cone_bounce.glsl: the gather of one bounce, or (listPass) the list of voxels that gather.
ProgramKey coneBounceProgramKey(bool aniso, GLenum radianceFormat, bool listPass);
// cone_raymarch.glsl: the voxel_* views; channel is gpu::CONE_CHANNEL_*.
ProgramKey voxelViewProgramKey(int channel);
// bench/: the cone pass with a fetch counter, and the bare trilinear-fetch shader.
ProgramKey coneCountProgramKey(bool gi, bool aniso);
ProgramKey fetchBenchProgramKey();
// cone_march_check.glsl: the shared march's functions on a buffer of inputs (the test that
// holds the CPU tracer's march to the shaders').
ProgramKey coneMarchCheckProgramKey();

// Every variant the functions above can return.
std::vector<ProgramKey> coneProgramVariants();

}  // namespace vct
