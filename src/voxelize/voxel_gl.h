// Small GL helpers shared by the voxelization, injection and mip passes (internal).
#pragma once

#include "gl/handles.h"

#include <glm/glm.hpp>

#include <string>

namespace vct {

// Runs the bound compute program over a grid of `size` voxels in VOX_GRID_GROUP^3 work groups,
// then makes its image writes visible to the next pass's image loads and texture fetches.
void dispatchGrid(const glm::ivec3& size);

// Binds `level` of a 3D texture (all layers) to an image unit.
inline void bindImage3D(GLuint unit, GLuint texture, int level, GLenum access, GLenum format) {
    glBindImageTexture(unit, texture, level, GL_TRUE, 0, access, format);
}

void setUniform(GLuint program, const char* name, int v);
void setUniform(GLuint program, const char* name, float v);
void setUniform(GLuint program, const char* name, const glm::ivec3& v);
void setUniform(GLuint program, const char* name, const glm::vec3& v);

// Internal format of level 0 of a texture.
GLenum textureInternalFormat(GLuint texture);
// Mip levels of an immutable texture (1 for a single level, 0 for no texture).
int textureLevelCount(const GlTexture& t);
// The GLSL image format qualifier of an internal format ("rgba16f", ...).
std::string glslImageFormat(GLenum internalFormat);
// Largest finite value storable in the format ("65504.0" for half floats).
std::string formatMaxLiteral(GLenum internalFormat);

}  // namespace vct
