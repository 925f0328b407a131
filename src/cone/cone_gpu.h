// Shared plumbing of the cone passes (not a public interface): program cache, the uniform
// block, binding the grid's textures.
#pragma once

#include "cone/cone_shared.h"
#include "gl/handles.h"
#include "gl/program.h"
#include "voxelize/voxel_grid.h"

#include <string>

namespace vct::conedetail {

// Builds `name` with `defines` once per process; programs live as long as the GL context.
GLuint coneProgram(const std::string& name, const ShaderDefines& defines);

// Grid fields of the uniform block (voxelFromWorld, gridResolution).
void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid);

// Uploads `u` into a fresh uniform buffer bound at CONE_UBO_BINDING; keep it alive until
// the dispatch is issued.
GlBuffer bindConeUniforms(const gpu::ConeUniforms& u);

// Throws std::invalid_argument naming `pass` if the grid is not usable.
void checkGrid(const VoxelGrid& grid, const std::string& pass);

}  // namespace vct::conedetail
