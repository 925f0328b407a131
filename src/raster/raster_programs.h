// The rasterization and lighting passes' programs, each built by one key function
// (gl/program_cache.h) so the passes and the list of every variant agree.
#pragma once

#include "gl/program_cache.h"

#include <vector>

namespace vct {

// The G-buffer: texture sampling, the alpha test and vertex colours compiled out where the
// scene has none, albedo and emission where the render reads no material (GBuffer::materials).
ProgramKey gbufferProgramKey(bool textures, bool alphaMask, bool materials, bool vertexColors);
// The shadow maps: the alpha test where the scene has alpha-masked materials.
ProgramKey shadowProgramKey(bool alphaMask, bool textures, bool vertexColors);
ProgramKey directLightProgramKey();
ProgramKey compositeProgramKey();

std::vector<ProgramKey> rasterProgramVariants();

}  // namespace vct
