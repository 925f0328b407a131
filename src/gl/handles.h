// Move-only owners of GL object names: each deletes its object in the destructor, so no
// GL object outlives its owner (the sanitizer build checks there are no leaks at exit).
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace vct {

// False once the process-wide context is gone (static destruction at exit): an owner that
// outlives the context then has nothing left to delete and must not call GL.
bool glContextAlive();

template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : mId(id) {}
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& o) noexcept : mId(std::exchange(o.mId, 0)) {}
    GlHandle& operator=(GlHandle&& o) noexcept {
        if (this != &o) { reset(); mId = std::exchange(o.mId, 0); }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint id() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    void reset() {
        if (mId && glContextAlive()) Delete(mId);
        mId = 0;
    }

private:
    GLuint mId = 0;
};

namespace gldetail {
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
inline void deleteShader(GLuint id) { glDeleteShader(id); }
inline void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }
inline void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
}  // namespace gldetail

using GlTexture = GlHandle<gldetail::deleteTexture>;
using GlBuffer = GlHandle<gldetail::deleteBuffer>;
using GlFramebuffer = GlHandle<gldetail::deleteFramebuffer>;
using GlVertexArray = GlHandle<gldetail::deleteVertexArray>;
using GlProgram = GlHandle<gldetail::deleteProgram>;
using GlShader = GlHandle<gldetail::deleteShader>;
using GlSampler = GlHandle<gldetail::deleteSampler>;
using GlQuery = GlHandle<gldetail::deleteQuery>;

// Creation helpers (DSA, GL 4.5).
GlTexture createTexture2D(GLenum internalFormat, int width, int height, int levels = 1);
GlTexture createTexture3D(GLenum internalFormat, int w, int h, int d, int levels = 1);
GlTexture createTextureCube(GLenum internalFormat, int size);
GlBuffer createBuffer(size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
GlFramebuffer createFramebuffer();
GlVertexArray createVertexArray();

}  // namespace vct
