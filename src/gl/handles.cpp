#include "gl/handles.h"

#include "gl/program_limits.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vct {

GlTexture createTexture2D(GLenum internalFormat, int width, int height, int levels) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, levels, internalFormat, width, height);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return GlTexture(id);
}

GlTexture createTexture3D(GLenum internalFormat, int w, int h, int d, int levels) {
    // A clear refusal instead of GL_INVALID_VALUE: GL guarantees 2048 texels per axis.
    static const int maxSize = deviceLimits().max3DTextureSize;
    if (std::max(w, std::max(h, d)) > maxSize)
        throw std::runtime_error("3D texture " + std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(d) +
                                 " exceeds this GL's GL_MAX_3D_TEXTURE_SIZE of " + std::to_string(maxSize));
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    glTextureStorage3D(id, levels, internalFormat, w, h, d);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_BORDER);
    const float zero[4] = {0, 0, 0, 0};
    glTextureParameterfv(id, GL_TEXTURE_BORDER_COLOR, zero);
    return GlTexture(id);
}

GlTexture createTextureCube(GLenum internalFormat, int size) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
    glTextureStorage2D(id, 1, internalFormat, size, size);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    return GlTexture(id);
}

GlBuffer createBuffer(size_t bytes, const void* data, GLbitfield flags) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes == 0 ? 4 : bytes), data, flags);
    return GlBuffer(id);
}

GlFramebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return GlFramebuffer(id);
}

GlVertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return GlVertexArray(id);
}

}  // namespace vct
