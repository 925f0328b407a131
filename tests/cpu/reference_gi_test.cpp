// Closed-form checks of the reference path tracer (src/reference/reference_gi.h) and of its
// CPU texture sampler. Expected values are analytic: geometric series in a closed box, the
// white furnace, inverse-square point lights, the form factor of a square emitter.
#include "reference/reference_gi.h"
#include "reference/scene_shapes.h"
#include "scene/texture_sampler.h"
#include "core/view.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdio>

namespace vct {
namespace {

constexpr double kPi = 3.14159265358979323846;

ReferenceSettings quiet(int spp, int bounces, float sky) {
    ReferenceSettings s;
    s.spp = spp;
    s.bounces = bounces;
    s.sky = sky;
    s.progress = false;
    return s;
}

// Image mean of channel c and its standard error measured from the spread over pixels
// (pixels are independent estimates with independent scrambles).
struct ImageMean {
    double mean = 0, stderrOfMean = 0;
};
ImageMean imageMean(const Image& img, int c) {
    double n = double(img.width) * img.height, sum = 0, sq = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            sum += img.at(x, y, c);
            sq += double(img.at(x, y, c)) * img.at(x, y, c);
        }
    ImageMean m;
    m.mean = sum / n;
    m.stderrOfMean = std::sqrt(std::max(0.0, sq / n - m.mean * m.mean) / (n - 1));
    return m;
}

double srgbDecode(int v) {
    double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Closed diffuse box, albedo rho and emission Le on every wall, camera inside, sky 0:
// radiance after at most B reflections is sum_{k=0..B} rho^k Le everywhere.
Scene closedBox(float rho, float le) {
    Scene s;
    addBox(s, glm::vec3(-1.f), glm::vec3(1.f), addDiffuseMaterial(s, glm::vec3(rho), glm::vec3(le)), true);
    return s;
}
View insideBox() {
    Camera cam;
    cam.eye = {0.1f, -0.2f, 0.3f};
    cam.target = {0.5f, 0.3f, -1.f};
    cam.yfov = 1.2f;
    return makeView(cam, 24, 24);
}

TEST(ReferenceGI, ClosedBoxTruncatedSeries) {
    const float rho = 0.5f, le = 1.f;
    Scene s = closedBox(rho, le);
    ReferenceSettings set = quiet(16, 2, 0.f);
    ReferenceGI gi = referenceGI(s, insideBox(), set);
    // B = 2: Le + rho Le + rho^2 Le = 1.75; no punctual lights, so direct = 0 and indirect =
    // rho Le + rho^2 Le = 0.75 (light from emitters is indirect: BRIEF section 1).
    for (int c = 0; c < 3; ++c) {
        ImageMean e = imageMean(gi.emission, c), d = imageMean(gi.direct, c), i = imageMean(gi.indirect, c),
                  b = imageMean(gi.beauty, c);
        std::printf("[ box B=2 ch%d ] Le %.5f direct %.5f+-%.5f (0) indirect %.5f+-%.5f (0.75) beauty %.5f (1.75)\n",
                    c, e.mean, d.mean, d.stderrOfMean, i.mean, i.stderrOfMean, b.mean);
        EXPECT_NEAR(e.mean, 1.0, 1e-6);
        EXPECT_EQ(d.mean, 0.0);
        EXPECT_NEAR(i.mean, 0.75, 3 * i.stderrOfMean + 2e-3);
        EXPECT_NEAR(b.mean, 1.75, 3 * i.stderrOfMean + 2e-3);
    }
    EXPECT_NEAR(gi.meanStderr, imageMean(gi.indirect, 0).stderrOfMean, 0.5 * gi.meanStderr + 1e-4);
}

TEST(ReferenceGI, ClosedBoxConvergesToGeometricLimit) {
    const float rho = 0.5f, le = 1.f;
    Scene s = closedBox(rho, le);
    ReferenceSettings set = quiet(16, 64, 0.f);  // 0.5^64 truncation: the limit Le / (1 - rho) = 2
    ReferenceGI gi = referenceGI(s, insideBox(), set);
    ImageMean b = imageMean(gi.beauty, 1), i = imageMean(gi.indirect, 1);
    std::printf("[ box B=64 ] beauty %.5f +- %.5f (limit 2), reported mean stderr %.5f\n", b.mean, b.stderrOfMean,
                gi.meanStderr);
    EXPECT_NEAR(b.mean, 2.0, 3 * b.stderrOfMean + 2e-3);
    EXPECT_NEAR(i.mean, 1.0, 3 * i.stderrOfMean + 2e-3);  // beauty - Le: no punctual lights
    for (float v : gi.beauty.pixels) ASSERT_TRUE(std::isfinite(v));
}

// White furnace: an albedo-1 plane under a uniform sky with nothing above it reflects exactly
// the sky (every cosine-sampled bounce escapes): Lo = sky, with zero variance.
Scene upwardPlane(uint32_t* material, glm::vec3 albedo = glm::vec3(1.f)) {
    Scene s;
    *material = addDiffuseMaterial(s, albedo);
    addQuad(s, {-1e3f, 0, -1e3f}, {0, 0, 2e3f}, {2e3f, 0, 0}, *material);
    return s;
}
View lookingDown(int size = 16) {
    Camera cam;
    cam.eye = {0, 2, 0};
    cam.target = {0, 0, 0};
    cam.up = {0, 0, -1};
    return makeView(cam, size, size);
}

TEST(ReferenceGI, WhiteFurnace) {
    uint32_t m;
    Scene s = upwardPlane(&m);
    ReferenceGI gi = referenceGI(s, lookingDown(), quiet(8, 4, 1.5f), true);
    for (size_t i = 0; i < gi.beauty.pixels.size(); ++i) {
        EXPECT_NEAR(gi.beauty.pixels[i], 1.5f, 1e-5f);
        EXPECT_NEAR(gi.indirect.pixels[i], 1.5f, 1e-5f);
        EXPECT_EQ(gi.direct.pixels[i], 0.f);
        EXPECT_NEAR(gi.indirectStderr.pixels[i], 0.f, 1e-5f);
    }
    // Sky pixels: the camera looking up sees the sky radiance in beauty, nothing else.
    Camera up;
    up.eye = {0, 1, 0};
    up.target = {0, 3, 0.2f};
    ReferenceGI sky = referenceGI(s, makeView(up, 8, 8), quiet(8, 4, 1.5f));
    for (size_t i = 0; i < sky.beauty.pixels.size(); ++i) {
        EXPECT_EQ(sky.beauty.pixels[i], 1.5f);
        EXPECT_EQ(sky.indirect.pixels[i], 0.f);
    }
    for (float c : sky.coverage.pixels) EXPECT_EQ(c, 0.f);
}

TEST(ReferenceGI, TexturedFurnaceReturnsDecodedTexel) {
    uint32_t m;
    Scene s = upwardPlane(&m);
    Texture t;
    t.width = 2;
    t.height = 2;
    t.rgba.resize(16);
    for (int i = 0; i < 4; ++i) {
        t.rgba[4 * i + 0] = 200;
        t.rgba[4 * i + 1] = 100;
        t.rgba[4 * i + 2] = 30;
        t.rgba[4 * i + 3] = 255;
    }
    s.textures.push_back(t);
    s.materials[m].baseColorTexture = 0;
    ReferenceGI gi = referenceGI(s, lookingDown(8), quiet(8, 4, 1.f));
    const double expected[3] = {srgbDecode(200), srgbDecode(100), srgbDecode(30)};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(gi.beauty.at(3, 4, c), expected[c], 1e-5) << "channel " << c;
}

TEST(ReferenceGI, TextureSamplerDecodesThenFilters) {
    Texture t;
    t.width = 2;
    t.height = 2;
    // Row 0 (top, v = 0): texels 10 and 250; row 1: 128 and 0.
    t.rgba = {10, 10, 10, 255, 250, 250, 250, 128, 128, 128, 128, 255, 0, 0, 0, 0};
    EXPECT_NEAR(sampleTexture(t, {0.25f, 0.25f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {0.75f, 0.25f}).x, srgbDecode(250), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {0.75f, 0.25f}).w, 128 / 255.0, 1e-6);  // alpha stays linear
    EXPECT_NEAR(sampleTexture(t, {0.25f, 0.75f}).y, srgbDecode(128), 1e-6);
    // Centre: average of the decoded texels (GL decodes sRGB before filtering).
    double avg = (srgbDecode(10) + srgbDecode(250) + srgbDecode(128) + srgbDecode(0)) / 4;
    EXPECT_NEAR(sampleTexture(t, {0.5f, 0.5f}).z, avg, 1e-6);
    // Repeat wraps; clamp-to-edge holds the border texel.
    EXPECT_NEAR(sampleTexture(t, {1.25f, -0.75f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {0.f, 0.25f}).x, (srgbDecode(10) + srgbDecode(250)) / 2, 1e-6);  // wraps across
    t.wrapS = TextureWrap::ClampToEdge;
    EXPECT_NEAR(sampleTexture(t, {0.f, 0.25f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {5.f, 0.25f}).x, srgbDecode(250), 1e-6);
    // Mirrored repeat runs backwards every other period, and an edge texel neighbours itself.
    t.wrapS = TextureWrap::MirroredRepeat;
    EXPECT_NEAR(sampleTexture(t, {1.25f, 0.25f}).x, srgbDecode(250), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {-0.25f, 0.25f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {2.25f, 0.25f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {1.f, 0.25f}).x, srgbDecode(250), 1e-6);
    EXPECT_NEAR(sampleTexture(t, {0.f, 0.25f}).x, srgbDecode(10), 1e-6);
    EXPECT_NEAR(srgbToLinear(255), 1.0, 1e-7);
    EXPECT_NEAR(srgbToLinear(0), 0.0, 1e-9);
}

// Point light at height h above an albedo-rho plane: the point right below it receives
// irradiance I / h^2, so Lo = rho / pi * I / h^2 (deterministic: no sampling in NEE).
TEST(ReferenceGI, PointAndSpotLightsInverseSquare) {
    uint32_t m;
    const float rho = 0.6f, h = 0.5f;
    Scene s = upwardPlane(&m, glm::vec3(rho));
    Light point;
    point.type = LightType::Point;
    point.position = {0, h, 0};
    point.color = {3.f, 2.f, 1.f};
    s.lights.push_back(point);
    View view = lookingDown(17);  // the centre pixel (8, 8) sees the origin
    ReferenceGI gi = referenceGI(s, view, quiet(8, 1, 0.f));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(gi.direct.at(8, 8, c), rho / kPi * point.color[c] / (h * h), 1e-4) << "channel " << c;
    EXPECT_EQ(gi.indirect.at(8, 8, 0), 0.f);

    // A spot pointing down with the point on its axis gets full intensity; rotated so the
    // point sits between inner and outer cone it gets the glTF ramp squared.
    s.lights[0].type = LightType::Spot;
    s.lights[0].direction = {0, -1, 0};
    s.lights[0].innerConeAngle = 0.2f;
    s.lights[0].outerConeAngle = 0.6f;
    gi = referenceGI(s, view, quiet(8, 1, 0.f));
    EXPECT_NEAR(gi.direct.at(8, 8, 0), rho / kPi * 3.f / (h * h), 1e-4);
    float tilt = 0.4f;
    s.lights[0].direction = {std::sin(tilt), -std::cos(tilt), 0};
    gi = referenceGI(s, view, quiet(8, 1, 0.f));
    double ramp = (std::cos(0.4) - std::cos(0.6)) / (std::cos(0.2) - std::cos(0.6));
    EXPECT_NEAR(gi.direct.at(8, 8, 0), rho / kPi * 3.f / (h * h) * ramp * ramp, 1e-4);
    EXPECT_NEAR(spotAttenuation(s.lights[0], std::cos(0.1f)), 1.f, 1e-6);
    EXPECT_EQ(spotAttenuation(s.lights[0], std::cos(0.7f)), 0.f);

    // Directional light at 60 degrees from the normal: E = color cos(60).
    s.lights[0].type = LightType::Directional;
    s.lights[0].direction = glm::normalize(glm::vec3(std::sin(1.0471976f), -std::cos(1.0471976f), 0));
    gi = referenceGI(s, view, quiet(8, 1, 0.f));
    EXPECT_NEAR(gi.direct.at(8, 8, 2), rho / kPi * 1.f * 0.5f, 1e-4);
    // ...and an occluder between it and the plane casts a shadow.
    addQuad(s, {-2.f, 0.3f, -2.f}, {0, 0, 4.f}, {4.f, 0, 0}, addDiffuseMaterial(s, glm::vec3(0.f)));
    Camera below;
    below.eye = {0, 0.2f, 0};
    below.target = {0, 0, 0};
    below.up = {0, 0, -1};
    gi = referenceGI(s, makeView(below, 17, 17), quiet(8, 1, 0.f));
    EXPECT_EQ(gi.direct.at(8, 8, 2), 0.f);
}

// A floor point below a centred square emitter (half-size a, height h, radiance Le) receives
// E = pi Le F, so its reflected radiance is rho Le F with F the parallel-square form factor;
// light from emitters is indirect (BRIEF section 1), direct holds punctual lights only.
// Exercises area sampling of emitters and MIS with BSDF hits. A single-sided emitter turned
// away from the floor lights nothing (glTF culls its back face); a doubleSided one still does.
TEST(ReferenceGI, SquareEmitterFormFactor) {
    const float rho = 0.8f, a = 0.5f, h = 1.f, le = 2.f;
    uint32_t m;
    Scene s = upwardPlane(&m, glm::vec3(rho));
    addQuad(s, {-a, h, -a}, {2 * a, 0, 0}, {0, 0, 2 * a}, addDiffuseMaterial(s, glm::vec3(0.f), glm::vec3(le)));
    Camera cam;
    cam.eye = {0, 0.3f, 0};
    cam.target = {0, 0, 0};
    cam.up = {0, 0, -1};
    cam.yfov = 0.001f;  // all pixels see the centre
    ReferenceGI gi = referenceGI(s, makeView(cam, 24, 24), quiet(32, 1, 0.f));
    double x = a / h, r = std::sqrt(1 + x * x);
    double F = 4.0 / kPi * x / r * std::atan(x / r);
    ImageMean d = imageMean(gi.indirect, 0);
    std::printf("[ square emitter ] indirect %.5f +- %.5f, closed form rho Le F = %.5f\n", d.mean, d.stderrOfMean,
                rho * le * F);
    EXPECT_NEAR(d.mean, rho * le * F, 3 * d.stderrOfMean + 1e-3);
    EXPECT_EQ(imageMean(gi.direct, 0).mean, 0.0);

    for (bool doubleSided : {false, true}) {
        Scene away = upwardPlane(&m, glm::vec3(rho));
        const uint32_t lamp = addDiffuseMaterial(away, glm::vec3(0.f), glm::vec3(le));
        away.materials[lamp].doubleSided = doubleSided;
        addQuad(away, {-a, h, -a}, {0, 0, 2 * a}, {2 * a, 0, 0}, lamp);  // winding normal +y: back to the floor
        ReferenceGI g = referenceGI(away, makeView(cam, 24, 24), quiet(32, 1, 0.f));
        ImageMean e = imageMean(g.indirect, 0);
        if (doubleSided)
            EXPECT_NEAR(e.mean, rho * le * F, 3 * e.stderrOfMean + 1e-3) << "doubleSided emitter";
        else
            EXPECT_EQ(e.mean, 0.0) << "a single-sided emitter lit the floor through its back";
    }
}

TEST(ReferenceGI, DeterministicAcrossThreadCounts) {
    Scene s = closedBox(0.7f, 0.3f);
    Light l;
    l.position = {0.2f, 0.5f, 0.f};
    l.color = glm::vec3(2.f);
    s.lights.push_back(l);
    ReferenceSettings set = quiet(8, 4, 0.f);
    set.seed = 3;
    ReferenceGI one, two;
    tbb::task_arena(1).execute([&] { one = referenceGI(s, insideBox(), set, true); });
    tbb::task_arena(2).execute([&] { two = referenceGI(s, insideBox(), set, true); });
    EXPECT_EQ(one.beauty.pixels, two.beauty.pixels);
    EXPECT_EQ(one.indirectStderr.pixels, two.indirectStderr.pixels);
}

}  // namespace
}  // namespace vct
