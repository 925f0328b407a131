// Clipmap cascades under a moving camera: the lattice is the region's, so a camera that moves
// less than a cascade's step keeps every cascade (the same voxels, nothing rebuilt), and a
// step moves the finest cascade's contents by whole voxels.
#include "clipmap/clipmap.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

using namespace vct;

namespace {

Scene roomScene() {
    Scene s;
    const uint32_t grey = vcttest::addMaterial(s, glm::vec3(0.6f));
    vcttest::addQuad(s, {-8.f, 0.f, -8.f}, {0.f, 0.f, 16.f}, {16.f, 0.f, 0.f}, grey);
    for (int i = 0; i < 5; ++i)
        vcttest::addBox(s, {-3.f + 1.37f * float(i), 0.f, -1.f - 0.61f * float(i)},
                        {-2.4f + 1.37f * float(i), 0.3f + 0.23f * float(i), -0.3f - 0.61f * float(i)}, grey);
    vcttest::finish(s);
    return s;
}

std::vector<float> readLevel(const GlTexture& tex, int channels) {
    glm::ivec3 size;
    glGetTextureLevelParameteriv(tex.id(), 0, GL_TEXTURE_WIDTH, &size.x);
    glGetTextureLevelParameteriv(tex.id(), 0, GL_TEXTURE_HEIGHT, &size.y);
    glGetTextureLevelParameteriv(tex.id(), 0, GL_TEXTURE_DEPTH, &size.z);
    std::vector<float> data(size_t(size.x) * size.y * size.z * channels);
    glGetTextureImage(tex.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT, GLsizei(data.size() * sizeof(float)),
                      data.data());
    return data;
}

// A focus a tenth of a base voxel off a point where every level's snap lands (a multiple of
// 2^levels base voxels), so small moves stay clear of every level's rounding boundary.
glm::vec3 focusNearCentre(const Bounds3& region, int levels, int res) {
    const ClipmapLayout c = computeClipmapLayout(region, region.center(), levels, res);
    const int grain = 1 << levels;
    glm::ivec3 index = c.originIndex[0] + glm::ivec3(c.resolution / 2);
    for (int a = 0; a < 3; ++a) index[a] = index[a] / grain * grain;
    return c.anchor + (glm::vec3(index) + glm::vec3(0.1f)) * c.baseVoxelSize;
}

}  // namespace

TEST(ClipmapMotion, TheLatticeDoesNotDependOnTheFocus) {
    const Scene scene = roomScene();
    const ClipmapLayout a = computeClipmapLayout(scene.bounds, glm::vec3(-5.f, 0.5f, 5.f), 3, 32);
    const ClipmapLayout b = computeClipmapLayout(scene.bounds, glm::vec3(4.f, 1.f, -6.f), 3, 32);
    EXPECT_EQ(a.baseVoxelSize, b.baseVoxelSize);
    EXPECT_EQ(a.anchor, b.anchor);
    EXPECT_EQ(a.originIndex.back(), b.originIndex.back()) << "the coarsest level covers the region from its centre";
    EXPECT_NE(a.originIndex.front(), b.originIndex.front()) << "the finest level follows the focus";
}

TEST(ClipmapMotion, AMoveShorterThanAStepKeepsEveryCascade) {
    const Scene scene = roomScene();
    const glm::vec3 f = focusNearCentre(scene.bounds, 3, 32);
    const ClipmapLayout a = computeClipmapLayout(scene.bounds, f, 3, 32);
    const ClipmapLayout b = computeClipmapLayout(scene.bounds, f + glm::vec3(0.4f, 0.3f, -0.2f) * a.baseVoxelSize, 3, 32);
    EXPECT_EQ(a.originIndex, b.originIndex);

    // In a session: the camera pans by that much, the clipmap is not built again.
    RenderSession session(scene);
    RenderRequest r;
    r.width = r.height = 32;
    // The camera whose cascades centre on f (they sit a little ahead of the eye).
    const glm::vec3 view(0.f, -0.5f, -2.f);
    r.camera.eye = f;
    r.camera.target = f + view;
    r.camera.eye = f - (clipmapFocus(scene.bounds, r.camera, 3, 32) - f);
    r.camera.target = r.camera.eye + view;
    ASSERT_LT(glm::length(clipmapFocus(scene.bounds, r.camera, 3, 32) - f), 1e-3f * a.baseVoxelSize);
    r.camera.znear = 0.05f;
    r.voxelRes = 32;
    r.ao = "vct";
    r.aovs = {"ao"};
    r.params.set("vct.clipmap.levels", "3");
    RenderResult first = session.render(r);
    const int built = session.passRunCounts().at("voxelize");
    const glm::vec3 pan = glm::vec3(0.4f, 0.f, 0.f) * a.baseVoxelSize;
    r.camera.eye += pan;
    r.camera.target += pan;
    RenderResult second = session.render(r);
    GlContext::shared().checkErrors("clipmap_motion");
    EXPECT_EQ(session.passRunCounts().at("voxelize"), built) << "a sub-step pan rebuilt the clipmap";
    EXPECT_EQ(first.extra["voxels"]["levels"], second.extra["voxels"]["levels"]);
}

TEST(ClipmapMotion, AStepMovesTheFinestCascadeByWholeVoxels) {
    const Scene scene = roomScene();
    RenderSession session(scene);  // the GPU copy of the scene
    const GpuScene gpu = uploadScene(scene);
    const glm::vec3 f = focusNearCentre(scene.bounds, 2, 32);
    const ClipmapLayout a = computeClipmapLayout(scene.bounds, f, 2, 32);
    // One step of level 0 is two of its voxels (one voxel of level 1, which keeps nesting exact).
    const ClipmapLayout b = computeClipmapLayout(scene.bounds, f + glm::vec3(2.f, 0.f, 0.f) * a.baseVoxelSize, 2, 32);
    ASSERT_EQ(b.originIndex[0] - a.originIndex[0], glm::ivec3(2, 0, 0));
    PassTimer timer(false);
    ParamMap params;
    const Clipmap ca = buildClipmap(gpu, scene, a, false, params, timer);
    const Clipmap cb = buildClipmap(gpu, scene, b, false, params, timer);
    GlContext::shared().checkErrors("clipmap_step");
    const int n = a.resolution;
    for (const auto& [name, channels] : {std::pair<const char*, int>{"opacity", 1}, {"albedo", 4}}) {
        const GlTexture& ta = std::strcmp(name, "opacity") == 0 ? ca.levels[0].opacity : ca.levels[0].albedo;
        const GlTexture& tb = std::strcmp(name, "opacity") == 0 ? cb.levels[0].opacity : cb.levels[0].albedo;
        const std::vector<float> va = readLevel(ta, channels), vb = readLevel(tb, channels);
        size_t differ = 0, occupied = 0;
        float worst = 0.f;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x + 2 < n; ++x)
                    for (int c = 0; c < channels; ++c) {
                        const float before = va[((size_t(z) * n + y) * n + x + 2) * channels + c];
                        const float after = vb[((size_t(z) * n + y) * n + x) * channels + c];
                        occupied += before != 0.f;
                        if (std::memcmp(&before, &after, sizeof(float)) != 0) {
                            ++differ;
                            worst = std::max(worst, std::abs(before - after));
                        }
                    }
        std::printf("%s: %zu nonzero values, %zu differ after the shift, largest difference %g\n", name, occupied,
                    differ, worst);
        EXPECT_GT(occupied, 100u) << name;
        EXPECT_EQ(differ, 0u) << name << ": the shifted cascade resampled its voxels";
    }
}
