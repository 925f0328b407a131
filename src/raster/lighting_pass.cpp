#include "raster/lighting_pass.h"

#include "raster/raster_programs.h"
#include "raster/raster_shared.h"

namespace vct {

GlTexture computeDirectLighting(const GBuffer& g, const GpuScene& scene, const ShadowMaps& shadows,
                                PassTimer& timer) {
    auto scope = timer.scope("direct");
    const GLuint program = cachedProgram(directLightProgramKey());
    GlTexture out = createTexture2D(GL_RGBA32F, g.width, g.height);
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "lightCount"), scene.lightCount);
    bindGBufferTextures(g);
    bindSceneBuffers(scene);
    bindShadowMaps(shadows);
    glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groupCount(g.width, gpu::RASTER_GROUP_SIZE), groupCount(g.height, gpu::RASTER_GROUP_SIZE), 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    return out;
}

CompositeOutputs composite(const GBuffer& g, const CompositeInputs& in, PassTimer& timer) {
    auto scope = timer.scope("composite");
    const GLuint program = cachedProgram(compositeProgramKey());
    static GlTexture dummy = createTexture2D(GL_RGBA32F, 1, 1);
    CompositeOutputs out;
    out.beauty = createTexture2D(GL_RGBA32F, g.width, g.height);
    out.indirect = createTexture2D(GL_RGBA32F, g.width, g.height);
    GLuint p = program;
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "useGi"), in.indirect ? 1 : 0);
    glUniform1i(glGetUniformLocation(p, "useDirect"), in.direct ? 1 : 0);
    glUniform1i(glGetUniformLocation(p, "useAo"), in.ao ? 1 : 0);
    glUniform1f(glGetUniformLocation(p, "sky"), in.sky);
    bindGBufferTextures(g);
    glBindTextureUnit(6, in.direct ? in.direct->id() : dummy.id());
    glBindTextureUnit(7, in.ao ? in.ao->id() : dummy.id());
    glBindTextureUnit(9, in.indirect ? in.indirect->id() : dummy.id());
    glBindImageTexture(0, out.beauty.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, out.indirect.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groupCount(g.width, gpu::RASTER_GROUP_SIZE), groupCount(g.height, gpu::RASTER_GROUP_SIZE), 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    return out;
}

}  // namespace vct
