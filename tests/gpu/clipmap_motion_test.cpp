// Clipmap cascades under a moving camera: the lattice is the region's, so a camera that moves
// by a fraction of a voxel keeps every cascade (the same voxels, nothing rebuilt), and a move of
// one voxel of a cascade shifts that cascade's contents by exactly one voxel, bit for bit.
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
    const ClipmapLayout b = computeClipmapLayout(scene.bounds, f + glm::vec3(0.3f, 0.25f, -0.2f) * a.baseVoxelSize, 3, 32);
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
    const glm::vec3 pan = glm::vec3(0.3f, 0.f, 0.f) * a.baseVoxelSize;
    r.camera.eye += pan;
    r.camera.target += pan;
    RenderResult second = session.render(r);
    GlContext::shared().checkErrors("clipmap_motion");
    EXPECT_EQ(session.passRunCounts().at("voxelize"), built) << "a sub-step pan rebuilt the clipmap";
    EXPECT_EQ(first.extra["voxels"]["levels"], second.extra["voxels"]["levels"]);
}

namespace {

// The voxels of level `level` (>= 1) that hold the finer level's nested means: those the finer
// level's voxels fill, [first, last] per axis in level `level`'s voxels.
bool nested(const ClipmapLayout& c, int level, const glm::ivec3& v) {
    if (level == 0) return false;
    for (int a = 0; a < 3; ++a) {
        const int fineOrigin = (c.originIndex[size_t(level - 1)][a] - c.originIndex[size_t(level)][a]) / (1 << (level - 1));
        const int first = (fineOrigin + 1) >> 1, last = (c.resolution - 2 + fineOrigin) >> 1;
        if (v[a] < first || v[a] > last) return false;
    }
    return true;
}

// Level `level`'s voxels of clipmap `b` against `a`'s shifted by `shift` voxels along x: every
// value must match bit for bit where both have it, but for the voxels the finer level's nested
// data covers in one and not the other (the finer level moved with the camera too).
void expectShifted(const Clipmap& a, const Clipmap& b, int level, int shift) {
    const int n = a.layout.resolution;
    for (const auto& [name, channels] : {std::pair<const char*, int>{"opacity", 1}, {"albedo", 4}}) {
        const bool opacity = std::strcmp(name, "opacity") == 0;
        const GlTexture& ta = opacity ? a.levels[size_t(level)].opacity : a.levels[size_t(level)].albedo;
        const GlTexture& tb = opacity ? b.levels[size_t(level)].opacity : b.levels[size_t(level)].albedo;
        const std::vector<float> va = readLevel(ta, channels), vb = readLevel(tb, channels);
        size_t differ = 0, occupied = 0, nestedBoth = 0;
        float worst = 0.f;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x + shift < n; ++x) {
                    const bool inA = nested(a.layout, level, {x + shift, y, z}), inB = nested(b.layout, level, {x, y, z});
                    if (inA != inB) continue;
                    nestedBoth += inA ? 1 : 0;
                    for (int c = 0; c < channels; ++c) {
                        const float before = va[((size_t(z) * n + y) * n + x + shift) * channels + c];
                        const float after = vb[((size_t(z) * n + y) * n + x) * channels + c];
                        occupied += before != 0.f;
                        if (std::memcmp(&before, &after, sizeof(float)) != 0) {
                            ++differ;
                            worst = std::max(worst, std::abs(before - after));
                        }
                    }
                }
        std::printf("level %d %s: %zu nonzero values, %zu differ after the shift, largest difference %g\n", level,
                    name, occupied, differ, worst);
        EXPECT_GT(occupied, 100u) << name;
        if (level > 0) {
            EXPECT_GT(nestedBoth, 1000u) << "the nested voxels were not compared";
        }
        EXPECT_EQ(differ, 0u) << "level " << level << " " << name << ": the shifted cascade resampled its voxels";
    }
}

}  // namespace

TEST(ClipmapMotion, AOneVoxelMoveShiftsThatCascadeByOneVoxel) {
    const Scene scene = roomScene();
    RenderSession session(scene);  // the GPU copy of the scene
    const GpuScene gpu = uploadScene(scene);
    // 0.4 of a base voxel below a point where every level's snap lands: moves of one and two
    // base voxels then cross level 0's and level 1's rounding, and no coarser level's.
    const glm::vec3 f = focusNearCentre(scene.bounds, 3, 32) - glm::vec3(0.5f, 0.f, 0.f) * computeClipmapLayout(
                            scene.bounds, scene.bounds.center(), 3, 32).baseVoxelSize;
    const ClipmapLayout a = computeClipmapLayout(scene.bounds, f, 3, 32);
    PassTimer timer(false);
    ParamMap params;
    const Clipmap ca = buildClipmap(gpu, scene, a, false, params, timer);
    // One voxel of level 0: level 0 moves by one voxel, level 1 (a voxel twice as wide) stays.
    const ClipmapLayout b = computeClipmapLayout(scene.bounds, f + glm::vec3(1.f, 0.f, 0.f) * a.baseVoxelSize, 3, 32);
    ASSERT_EQ(b.originIndex[0] - a.originIndex[0], glm::ivec3(1, 0, 0));
    ASSERT_EQ(b.originIndex[1], a.originIndex[1]);
    const Clipmap cb = buildClipmap(gpu, scene, b, false, params, timer);
    expectShifted(ca, cb, 0, 1);
    // Level 0's origin is now odd in level 1's lattice: the nested voxels of level 1 still hold
    // the mean of the eight level-0 voxels that fill them (read back and averaged here).
    {
        const int n = b.resolution;
        const int fineOrigin = b.originIndex[0].x - b.originIndex[1].x;
        ASSERT_EQ(fineOrigin % 2, 1);
        const std::vector<float> fine = readLevel(cb.levels[0].opacity, 1), coarse = readLevel(cb.levels[1].opacity, 1);
        const glm::ivec3 o = b.originIndex[0] - b.originIndex[1];
        size_t checked = 0, occupied = 0;
        float worst = 0.f;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    if (!nested(b, 1, {x, y, z})) continue;
                    float sum = 0.f;
                    for (int k = 0; k < 8; ++k) {
                        const glm::ivec3 f = 2 * glm::ivec3(x, y, z) - o + glm::ivec3(k & 1, (k >> 1) & 1, k >> 2);
                        sum += fine[(size_t(f.z) * n + f.y) * n + f.x];
                    }
                    const float mean = sum / 8.f, got = coarse[(size_t(z) * n + y) * n + x];
                    worst = std::max(worst, std::abs(mean - got));
                    occupied += mean > 0.f;
                    ++checked;
                }
        EXPECT_GT(occupied, 100u);
        EXPECT_GT(checked, 1000u);
        EXPECT_LT(worst, 1e-3f) << "a nested voxel is not the mean of the finer voxels that fill it";
    }
    // One voxel of level 1 (two of level 0): level 1 moves by one of its voxels; so does level 0
    // (by two of its own), whose means nested in level 1 shift with it.
    const ClipmapLayout c = computeClipmapLayout(scene.bounds, f + glm::vec3(2.f, 0.f, 0.f) * a.baseVoxelSize, 3, 32);
    ASSERT_EQ(c.originIndex[1] - a.originIndex[1], glm::ivec3(2, 0, 0));  // in level-0 voxels
    ASSERT_EQ(c.originIndex[2], a.originIndex[2]);
    const Clipmap cc = buildClipmap(gpu, scene, c, false, params, timer);
    GlContext::shared().checkErrors("clipmap_step");
    expectShifted(ca, cc, 1, 1);
}
