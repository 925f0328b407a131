// glTF sampler wrap modes on the GPU (one REPEAT sampler for the whole texture array, the
// modes applied in common/scene.glsl) against the CPU sampler the path tracer and the sparse
// voxelizer use (scene/texture_sampler.cpp): an independent implementation of the same rule.
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/texture_sampler.h"
#include "common/scene_shared.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace vct;

namespace {

// A quad facing the camera whose u runs from -1 to 2 (v from 0 to 1) under a texture that is
// black on its left half and white on its right, at the array's own size (no resampling).
Scene wrapScene(TextureWrap wrapS) {
    Scene s;
    const uint32_t m = vcttest::addMaterial(s, glm::vec3(1.f));
    vcttest::addQuad(s, glm::vec3(-1.f, -1.f, 0.f), glm::vec3(2.f, 0.f, 0.f), glm::vec3(0.f, 2.f, 0.f), m);
    s.uvs = {glm::vec2(-1.f, 0.f), glm::vec2(2.f, 0.f), glm::vec2(2.f, 1.f), glm::vec2(-1.f, 1.f)};
    Texture t;
    t.name = "halves";
    t.width = t.height = gpu::SCENE_TEXTURE_SIZE;
    t.rgba.assign(size_t(t.width) * size_t(t.height) * 4, 255);
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width / 2; ++x)
            for (int c = 0; c < 3; ++c) t.rgba[(size_t(y) * size_t(t.width) + size_t(x)) * 4 + size_t(c)] = 0;
    t.wrapS = wrapS;
    s.textures.push_back(t);
    s.materials[m].baseColorTexture = 0;
    vcttest::finish(s);
    return s;
}

}  // namespace

TEST(TextureWrap, TheGBufferWrapsAsTheCpuSamplerDoes) {
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat}) {
        const Scene s = wrapScene(wrap);
        RenderSession session(s);
        RenderRequest r;
        r.width = r.height = 96;
        r.camera = vcttest::lookAt(s, glm::vec3(0.f, 0.f, 3.f), glm::vec3(0.f), 40.f);
        r.aovs = {"albedo", "position", "depth"};
        const RenderResult out = session.render(r);
        GlContext::shared().checkErrors("texture wrap");
        const Image& albedo = out.aovs.at("albedo");
        const Image& position = out.aovs.at("position");
        const Image& depth = out.aovs.at("depth");
        int checked = 0, black = 0;
        for (int y = 0; y < albedo.height; ++y)
            for (int x = 0; x < albedo.width; ++x) {
                if (!(depth.at(x, y, 0) > 0.f)) continue;  // no surface
                const float u = -1.f + 1.5f * (position.at(x, y, 0) + 1.f), v = 0.5f * (position.at(x, y, 1) + 1.f);
                // Away from the texture's own edges and its black-white step, where both
                // samplers must agree whatever their filters' widths.
                bool flat = true;
                for (float du : {-0.12f, 0.12f})
                    if (sampleTexture(s.textures[0], {u + du, v}).x != sampleTexture(s.textures[0], {u, v}).x)
                        flat = false;
                if (!flat) continue;
                const float expected = sampleTexture(s.textures[0], {u, v}).x;
                EXPECT_NEAR(albedo.at(x, y, 0), expected, 0.02f)
                    << "wrap " << int(wrap) << ", pixel (" << x << ", " << y << "), u " << u;
                ++checked;
                black += expected < 0.5f;
            }
        // Each mode has both colours in its flat regions: a GPU that ignored the mode would
        // differ from the CPU on a large share of them.
        EXPECT_GT(checked, 1000) << int(wrap);
        EXPECT_GT(black, 200) << int(wrap);
        EXPECT_GT(checked - black, 200) << int(wrap);
    }
}
