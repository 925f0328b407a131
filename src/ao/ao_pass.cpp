#include "ao/ao_pass.h"

#include "ao/ao_random.h"

#include <stdexcept>

namespace vct {

static_assert(gpu::AO_UNIT_POSITION == kUnitPosition && gpu::AO_UNIT_NORMAL == kUnitNormal &&
                  gpu::AO_UNIT_ALBEDO == kUnitAlbedo,
              "AO shaders must read the G-buffer at the units of render/gbuffer.h");
static_assert(sizeof(gpu::AoViewUniforms) == 64 + 4 * 16, "AoViewUniforms must match std140");

gpu::AoViewUniforms makeAoViewUniforms(const View& view, int fullWidth, int fullHeight, int evalWidth,
                                       int evalHeight, int scale, float radius, uint64_t seed) {
    gpu::AoViewUniforms u{};
    u.viewFromWorld = view.viewFromWorld;
    // clipFromView is a symmetric pinhole: ndc = P[i][i] * xy / -z, pixel = (ndc + 1) / 2 * size.
    u.pixelFromView = glm::vec4(0.5f * fullWidth * view.clipFromView[0][0],
                                0.5f * fullHeight * view.clipFromView[1][1], 0.5f * fullWidth,
                                0.5f * fullHeight);
    u.size = glm::ivec4(evalWidth, evalHeight, fullWidth, fullHeight);
    u.radius = glm::vec4(radius, radius * radius, 0.f, 0.f);
    SplitMix64 rng(seed ^ 0x5A0C0DEull);
    u.noise = glm::uvec4(uint32_t(rng.next() >> 32), uint32_t(scale), 0u, 0u);
    return u;
}

AoPassContext makeAoPassContext(const GBuffer& gbuffer, const View& view, float radius, int scale, uint64_t seed) {
    AoPassContext ctx;
    ctx.gbuffer = &gbuffer;
    ctx.scale = scale;
    ctx.evalWidth = (gbuffer.width + scale - 1) / scale;
    ctx.evalHeight = (gbuffer.height + scale - 1) / scale;
    ctx.radius = radius;
    ctx.seed = seed;
    gpu::AoViewUniforms u = makeAoViewUniforms(view, gbuffer.width, gbuffer.height, ctx.evalWidth,
                                               ctx.evalHeight, scale, radius, seed);
    ctx.viewUniforms = createBuffer(sizeof(u), &u, 0);
    return ctx;
}

void bindAoPassInputs(const AoPassContext& ctx) {
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::AO_BINDING_VIEW, ctx.viewUniforms.id());
    glBindTextureUnit(gpu::AO_UNIT_POSITION, ctx.gbuffer->position.id());
    glBindTextureUnit(gpu::AO_UNIT_NORMAL, ctx.gbuffer->normal.id());
    glBindTextureUnit(gpu::AO_UNIT_ALBEDO, ctx.gbuffer->albedo.id());
}

GlTexture createAoTexture(int width, int height) { return createTexture2D(GL_R32F, width, height); }

void dispatchAoPass(GLuint program, const GlTexture& output, int width, int height) {
    glUseProgram(program);
    glBindImageTexture(gpu::AO_IMAGE_OUTPUT, output.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(groupCount(width, gpu::AO_LOCAL_SIZE_X), groupCount(height, gpu::AO_LOCAL_SIZE_Y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace vct
