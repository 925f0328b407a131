#include "raster/gbuffer_pass.h"

#include "raster/raster_programs.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>

namespace vct {

GBuffer renderGBuffer(const GpuScene& scene, const View& view, PassTimer& timer, bool materials) {
    auto scope = timer.scope("gbuffer");
    // One program per shader variant: features the scene does not use are compiled out.
    const GLuint program = cachedProgram(gbufferProgramKey(rasterFeaturesOf(scene), materials));

    GBuffer g;
    g.width = view.width;
    g.height = view.height;
    g.position = createTexture2D(GL_RGBA32F, g.width, g.height);
    // Unit normals need no 32-bit floats (core/gbuffer.h).
    g.normal = createTexture2D(GL_RGBA16F, g.width, g.height);
    g.geomNormal = createTexture2D(GL_RGBA16F, g.width, g.height);
    if (materials) {
        g.albedo = createTexture2D(GL_RGBA32F, g.width, g.height);
        g.emission = createTexture2D(GL_RGBA32F, g.width, g.height);
    }
    g.depth = createTexture2D(GL_DEPTH_COMPONENT32F, g.width, g.height);
    g.fbo = createFramebuffer();
    GLuint fbo = g.fbo.id();
    const GLuint colors[5] = {g.position.id(), g.normal.id(), g.geomNormal.id(), g.albedo.id(), g.emission.id()};
    const int attachments = materials ? 5 : 3;
    GLenum drawBuffers[5];
    for (int i = 0; i < attachments; ++i) {
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + i, colors[i], 0);
        drawBuffers[i] = GL_COLOR_ATTACHMENT0 + i;
    }
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, g.depth.id(), 0);
    glNamedFramebufferDrawBuffers(fbo, attachments, drawBuffers);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("gbuffer: framebuffer incomplete");

    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < attachments; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
    const float farDepth = 0.f;  // reversed-Z: 0 is infinitely far
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);

    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, g.width, g.height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDisable(GL_CULL_FACE);
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "clipFromWorld"), 1, GL_FALSE,
                       glm::value_ptr(view.clipFromWorld));
    glUniformMatrix4fv(glGetUniformLocation(program, "viewFromWorld"), 1, GL_FALSE,
                       glm::value_ptr(view.viewFromWorld));
    glUniform3fv(glGetUniformLocation(program, "eyeWorld"), 1, glm::value_ptr(view.camera.eye));
    bindSceneBuffers(scene);
    glBindVertexArray(scene.vao.id());
    glDrawElements(GL_TRIANGLES, 3 * scene.triangleCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    return g;
}

}  // namespace vct
