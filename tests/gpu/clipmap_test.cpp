// Clipmap cascades (clipmap/clipmap.h): exact nesting of the layout, no seam where a floor
// crosses a level border (AO and indirect light), and brightness that does not depend on the
// number of levels.
#include "clipmap/clipmap.h"
#include "cone/clipmap_shared.h"
#include "core/errors.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace vct;

TEST(ClipmapLayout, LevelsLieOnOneLatticeAndCoverTheRegion) {
    Bounds3 region;
    region.min = {-20.f, -1.f, -20.f};
    region.max = {20.f, 3.f, 20.f};
    for (int levels : {1, 3, 5}) {
        for (glm::vec3 focus : {glm::vec3(0.3f, 1.5f, 2.2f), glm::vec3(19.f, 0.f, -19.5f), glm::vec3(50.f, 9.f, 0.f)}) {
            const ClipmapLayout c = computeClipmapLayout(region, focus, levels, 30);
            EXPECT_EQ(c.resolution, 32);
            const Bounds3 coarse = c.bounds(levels - 1);
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(coarse.min[a], region.min[a]);
                EXPECT_GE(coarse.max[a], region.max[a]);
            }
            for (int l = 0; l + 1 < levels; ++l) {
                // Whole voxels of level l apart (one lattice: level l's voxels fill level l + 1's
                // wherever it stands), and level l inside level l + 1 with room for the border
                // margin and blend band of the finer level.
                const glm::ivec3 d = c.originIndex[size_t(l)] - c.originIndex[size_t(l + 1)];
                for (int a = 0; a < 3; ++a) EXPECT_EQ(d[a] % (1 << l), 0);
                for (int a = 0; a < 3; ++a) EXPECT_EQ(c.originIndex[size_t(l)][a] % (1 << l), 0);
                // Whole voxels apart in the layout's integers; the world bounds round.
                const float room = (gpu::CLIPMAP_BORDER_MARGIN + gpu::CLIPMAP_BLEND_WIDTH + 1.f) * c.voxelSize(l + 1) -
                                   1e-4f * c.voxelSize(l + 1);
                const Bounds3 fine = c.bounds(l), outer = c.bounds(l + 1);
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(fine.min[a] - outer.min[a], room);
                    EXPECT_GE(outer.max[a] - fine.max[a], room);
                }
                EXPECT_FLOAT_EQ(c.voxelSize(l + 1), 2.f * c.voxelSize(l));
            }
        }
    }
    EXPECT_THROW(computeClipmapLayout(region, glm::vec3(0.f), 9, 32), InternalError);
    EXPECT_THROW(computeClipmapLayout(Bounds3{}, glm::vec3(0.f), 2, 32), InternalError);
}

namespace {

// A 40 m floor with a low wall and a row of boxes, lit by the sun and the sky.
Scene floorScene(bool withObjects) {
    Scene s;
    const uint32_t grey = vcttest::addMaterial(s, glm::vec3(0.6f));
    vcttest::addQuad(s, {-20.f, 0.f, -20.f}, {0.f, 0.f, 40.f}, {40.f, 0.f, 0.f}, grey);
    if (withObjects) {
        vcttest::addBox(s, {-1.2f, 0.f, -12.f}, {-1.f, 0.6f, 4.f}, grey);
        for (int i = 0; i < 6; ++i)
            vcttest::addBox(s, {1.f, 0.f, 2.f - 2.5f * float(i)}, {1.6f, 0.5f, 2.6f - 2.5f * float(i)}, grey);
    }
    Light sun;
    sun.type = LightType::Directional;
    sun.color = glm::vec3(2.f);
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.f, 0.3f));
    s.lights.push_back(sun);
    vcttest::finish(s);
    return s;
}

RenderRequest floorRequest(int levels, int res) {
    RenderRequest r;
    r.width = r.height = 64;
    r.camera.eye = {0.f, 1.4f, 4.f};
    r.camera.target = {0.f, 0.f, -4.f};
    r.camera.yfov = 0.9f;
    r.camera.znear = 0.05f;
    r.camera.zfar = 100.f;
    r.radius = 1.f;
    r.voxelRes = res;
    r.ao = "vct";
    r.gi = "vct";
    r.aovs = {"ao", "indirect", "normal", "position"};
    r.params.set("vct.clipmap.levels", std::to_string(levels));
    return r;
}

// Pixels of the open floor whose right and lower neighbours are open floor too.
std::vector<size_t> floorPixels(const RenderResult& res) {
    const Image& n = res.aovs.at("normal");
    const Image& p = res.aovs.at("position");
    auto isFloor = [&](int x, int y) { return n.at(x, y, 1) > 0.99f && std::abs(p.at(x, y, 1)) < 1e-3f; };
    std::vector<size_t> out;
    for (int y = 0; y + 1 < n.height; ++y)
        for (int x = 0; x + 1 < n.width; ++x)
            if (isFloor(x, y) && isFloor(x + 1, y) && isFloor(x, y + 1)) out.push_back(size_t(y) * n.width + x);
    return out;
}

// Largest difference between a floor pixel and its right or lower neighbour (channel mean).
double maxStep(const Image& img, const std::vector<size_t>& pixels) {
    const int c = img.channels == 1 ? 1 : 3;
    auto value = [&](size_t i) {
        double v = 0;
        for (int k = 0; k < c; ++k) v += img.pixels[i * img.channels + k];
        return v / c;
    };
    double m = 0;
    for (size_t i : pixels)
        m = std::max({m, std::abs(value(i) - value(i + 1)), std::abs(value(i) - value(i + img.width))});
    return m;
}

double meanOf(const Image& img, const std::vector<size_t>& pixels) {
    double s = 0;
    for (size_t i : pixels) s += img.pixels[i * img.channels + 1];
    return pixels.empty() ? 0.0 : s / double(pixels.size());
}

}  // namespace

TEST(Clipmap, NoSeamWhereTheFloorCrossesALevelBorder) {
    const Scene scene = floorScene(true);
    RenderSession session(scene);
    // Three levels of 32^3 against one level of 128^3 whose voxels are as fine as level 0's.
    RenderResult clip = session.render(floorRequest(3, 32));
    RenderResult one = session.render(floorRequest(1, 128));
    GlContext::shared().checkErrors("clipmap_seam");
    const std::vector<size_t> floor = floorPixels(clip);
    ASSERT_GT(floor.size(), 1000u);

    // The view must cross level 0's border, else there is nothing to test.
    const auto& l0 = clip.extra["voxels"]["levels"][0];
    const Image& pos = clip.aovs.at("position");
    size_t inside = 0;
    for (size_t i : floor) {
        bool in = true;
        for (int a = 0; a < 3; ++a) {
            const double v = pos.pixels[3 * i + a];
            in = in && v > l0["min"][a].get<double>() && v < l0["max"][a].get<double>();
        }
        inside += in;
    }
    std::printf("floor pixels %zu, inside level 0 %zu\n", floor.size(), inside);
    ASSERT_GT(inside, floor.size() / 10);
    ASSERT_LT(inside, floor.size() * 9 / 10);

    for (const char* aov : {"ao", "indirect"}) {
        const double stepClip = maxStep(clip.aovs.at(aov), floor), stepOne = maxStep(one.aovs.at(aov), floor);
        std::printf("%-8s max neighbour step: clipmap %.4f, one level %.4f\n", aov, stepClip, stepOne);
        // A seam would add a jump of the size of the level change on top of the one-level
        // image's own steps (its box and wall edges).
        EXPECT_LE(stepClip, stepOne * 1.25 + 0.02) << aov;
        EXPECT_GT(stepOne, 0.0) << aov;
    }
}

TEST(Clipmap, BrightnessDoesNotDependOnTheNumberOfLevels) {
    const Scene scene = floorScene(false);
    RenderSession session(scene);
    double first = -1;
    for (int levels : {1, 2, 4}) {
        for (int res : {32, 64}) {
            RenderResult r = session.render(floorRequest(levels, res));
            GlContext::shared().checkErrors("clipmap_levels");
            const std::vector<size_t> floor = floorPixels(r);
            const double gi = meanOf(r.aovs.at("indirect"), floor), ao = meanOf(r.aovs.at("ao"), floor);
            std::printf("open floor, %d levels of %d^3: mean indirect %.4f, mean AO %.4f, memory %.1f MB\n", levels,
                        res, gi, ao, r.extra["voxels"]["memory_bytes"].get<double>() / 1e6);
            // Open floor under a uniform sky: indirect = albedo * sky = 0.6, AO = 1.
            EXPECT_NEAR(gi, 0.6, 0.03) << levels << " levels of " << res;
            EXPECT_NEAR(ao, 1.0, 0.02);
            if (first < 0) first = gi;
            EXPECT_NEAR(gi, first, 0.01 * first);
        }
    }
}
