// Plumbing shared by the screen-space AO passes: the per-view uniform block, the list of
// their programs, R32F textures and the dispatch of one 2D compute pass.
#pragma once

#include "ao/ao_shared.h"
#include "gl/handles.h"
#include "gl/program_cache.h"
#include "core/gbuffer.h"
#include "core/view.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

// What every pass of one evaluation reads. Evaluation happens at `evalWidth x evalHeight`,
// one evaluation pixel per `scale x scale` G-buffer pixels (scale 1 or 2).
struct AoPassContext {
    const GBuffer* gbuffer = nullptr;
    int evalWidth = 0;
    int evalHeight = 0;
    int scale = 1;
    float radius = 0.f;   // R, world units
    uint64_t seed = 0;
    GlBuffer viewUniforms;  // gpu::AoViewUniforms, bound at AO_BINDING_VIEW by bindAoPassInputs
};

gpu::AoViewUniforms makeAoViewUniforms(const View& view, int fullWidth, int fullHeight, int evalWidth,
                                       int evalHeight, int scale, float radius, uint64_t seed);
AoPassContext makeAoPassContext(const GBuffer& gbuffer, const View& view, float radius, int scale, uint64_t seed);

// Binds the view block and the G-buffer textures the AO shaders read (position, normal, albedo).
void bindAoPassInputs(const AoPassContext& ctx);


GlTexture createAoTexture(int width, int height);  // R32F, nearest, clamp to edge

// A std140 block uploaded into a new buffer and bound at `binding`.
template <typename T>
GlBuffer uploadUniformBlock(const T& block, GLuint binding) {
    GlBuffer buffer = createBuffer(sizeof(T), &block, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding, buffer.id());
    return buffer;
}

// Runs `program` over width x height invocations writing `output` at AO_IMAGE_OUTPUT, then
// makes the writes visible to texture fetches of the next pass.
void dispatchAoPass(GLuint program, const GlTexture& output, int width, int height);

}  // namespace vct
