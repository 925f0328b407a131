#include "voxelize/voxel_gl.h"

#include "core/errors.h"
#include "gl/program.h"
#include "voxelize/voxelize.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <stdexcept>

namespace vct {

void dispatchGrid(const glm::ivec3& size) {
    const int g = gpu::VOX_GRID_GROUP;
    glDispatchCompute(groupCount(size.x, g), groupCount(size.y, g), groupCount(size.z, g));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void setUniform(GLuint program, const char* name, int v) {
    glProgramUniform1i(program, glGetUniformLocation(program, name), v);
}
void setUniform(GLuint program, const char* name, float v) {
    glProgramUniform1f(program, glGetUniformLocation(program, name), v);
}
void setUniform(GLuint program, const char* name, const glm::ivec3& v) {
    glProgramUniform3i(program, glGetUniformLocation(program, name), v.x, v.y, v.z);
}
void setUniform(GLuint program, const char* name, const glm::vec3& v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), v.x, v.y, v.z);
}

int textureLevelCount(const GlTexture& t) {
    if (!t) return 0;
    GLint levels = 0;
    glGetTextureParameteriv(t.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    return std::max(1, int(levels));
}

GLenum textureInternalFormat(GLuint texture) {
    GLint f = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    return static_cast<GLenum>(f);
}

std::string glslImageFormat(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_R16F: return "r16f";
    case GL_R32F: return "r32f";
    case GL_RGBA16F: return "rgba16f";
    case GL_RGBA32F: return "rgba32f";
    case GL_R32UI: return "r32ui";
    default: throw InternalError("voxel grid", "unsupported texture format " + std::to_string(internalFormat));
    }
}

std::string formatMaxLiteral(GLenum internalFormat) {
    return (internalFormat == GL_R16F || internalFormat == GL_RGBA16F) ? "65504.0" : "3.0e38";
}

namespace {

size_t bytesPerTexel(GLenum f) {
    switch (f) {
    case GL_R16F: return 2;
    case GL_R32F: case GL_R32UI: return 4;
    case GL_RGBA16F: return 8;
    case GL_RGBA32F: return 16;
    default: return 0;
    }
}

size_t textureBytes(const GlTexture& t) {
    if (!t) return 0;
    const int levels = textureLevelCount(t);
    size_t texel = bytesPerTexel(textureInternalFormat(t.id())), total = 0;
    for (int l = 0; l < levels; ++l) {
        GLint w = 0, h = 0, d = 0;
        glGetTextureLevelParameteriv(t.id(), l, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(t.id(), l, GL_TEXTURE_HEIGHT, &h);
        glGetTextureLevelParameteriv(t.id(), l, GL_TEXTURE_DEPTH, &d);
        total += size_t(w) * size_t(h) * size_t(d) * texel;
    }
    return total;
}

}  // namespace

size_t voxelGridMemoryBytes(const VoxelGrid& g) {
    size_t total = textureBytes(g.opacity) + textureBytes(g.albedo) + textureBytes(g.normal) +
                   textureBytes(g.emission) + textureBytes(g.radiance) + textureBytes(g.twoSided) +
                   textureBytes(g.sheets) + textureBytes(g.sheetExtents);
    for (const GlTexture& t : g.anisoRadiance) total += textureBytes(t);
    total += textureBytes(g.anisoOpacity);
    return total;
}

}  // namespace vct
