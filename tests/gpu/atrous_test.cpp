// The edge-avoiding a-trous filter (src/denoise) on G-buffers built here: fronto-parallel
// planes at two depths, with sky and an albedo patch. Its normalized weights keep a constant
// image constant and conserve an impulse's mass, it does not average across a depth step, it
// removes noise within a surface, and it is deterministic.
#include "denoise/atrous.h"
#include "gl/context.h"
#include "gl/readback.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>

using namespace vct;

namespace {

// A camera at the origin looking down -z (90 degrees across); pixel (x, y), row 0 the top, sees
// the plane z = -depth(x, y) at world (u d, v d, -d). Depth <= 0 is sky.
struct Planes {
    int width = 64, height = 48;
    std::function<float(int, int)> depth;
    std::function<glm::vec3(int, int)> albedo = [](int, int) { return glm::vec3(0.5f); };
};

GBuffer makeGBuffer(const Planes& p) {
    Image position(p.width, p.height, 4), normal(p.width, p.height, 4), albedo(p.width, p.height, 4);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const float d = p.depth(x, y);
            if (!(d > 0.f)) continue;
            const float u = 2.f * (x + 0.5f) / p.width - 1.f, v = 1.f - 2.f * (y + 0.5f) / p.height;
            const glm::vec3 a = p.albedo(x, y);
            for (int c = 0; c < 3; ++c) {
                position.at(x, y, c) = glm::vec3(u * d, v * d, -d)[c];
                normal.at(x, y, c) = glm::vec3(0, 0, 1)[c];
                albedo.at(x, y, c) = a[c];
            }
            position.at(x, y, 3) = d;
            normal.at(x, y, 3) = 1.f;
            albedo.at(x, y, 3) = 1.f;
        }
    GlContext::shared();
    GBuffer g;
    g.width = p.width;
    g.height = p.height;
    g.position = createTexture2D(GL_RGBA32F, p.width, p.height);
    g.normal = createTexture2D(GL_RGBA32F, p.width, p.height);
    g.albedo = createTexture2D(GL_RGBA32F, p.width, p.height);
    uploadTexture2D(g.position.id(), position);
    uploadTexture2D(g.normal.id(), normal);
    uploadTexture2D(g.albedo.id(), albedo);
    return g;
}

Image filtered(const GBuffer& g, const Image& input, const AtrousSettings& s, bool demodulate = false) {
    GlTexture in = createTexture2D(input.channels == 1 ? GL_R32F : GL_RGBA32F, input.width, input.height);
    uploadTexture2D(in.id(), input);
    GlTexture out = runAtrousFilter(g, in, input.channels, s, demodulate);  // RGBA32F: read back what went in
    Image img = readTexture2D(out.id(), input.width, input.height, input.channels);
    GlContext::shared().checkErrors("atrous");
    return img;
}

// Deterministic noise in [-1, 1].
float hashNoise(int x, int y, int c) {
    uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(c + 1) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xFFFFu) / 32767.5f - 1.f;
}

// Left of column 24 a near plane (depth 3), right of it a far one (depth 6); the top-right
// corner is sky; a patch of a red material sits on the far plane.
Planes stepScene() {
    Planes p;
    p.depth = [](int x, int y) { return x >= 52 && y < 10 ? 0.f : (x < 24 ? 3.f : 6.f); };
    p.albedo = [](int x, int y) {
        return x >= 36 && x < 46 && y >= 30 && y < 40 ? glm::vec3(0.8f, 0.1f, 0.1f) : glm::vec3(0.5f);
    };
    return p;
}

}  // namespace

TEST(Atrous, KernelAndEdgeWeights) {
    double sum = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) sum += gpu::atrous_kernel(std::abs(dx)) * gpu::atrous_kernel(std::abs(dy));
    EXPECT_DOUBLE_EQ(sum, 1.0);
    const glm::vec4 sigmas(gpu::ATROUS_DEFAULT_SIGMA_DEPTH, gpu::ATROUS_DEFAULT_SIGMA_NORMAL,
                           gpu::ATROUS_DEFAULT_SIGMA_ALBEDO, 0.f);
    const glm::vec3 p(0, 0, -3), n(0, 0, 1), a(0.5f);
    // Along the centre's plane, same normal and albedo: full weight, however far.
    EXPECT_FLOAT_EQ(gpu::atrous_edgeWeight(p, n, a, 3.f, p + glm::vec3(2, -1, 0), n, a, sigmas), 1.f);
    // Across a depth step, a crease or a material edge: next to nothing.
    EXPECT_LT(gpu::atrous_edgeWeight(p, n, a, 3.f, p + glm::vec3(0.1f, 0, -0.3f), n, a, sigmas), 1e-6f);
    EXPECT_LT(gpu::atrous_edgeWeight(p, n, a, 3.f, p, glm::vec3(1, 0, 0), a, sigmas), 1e-6f);
    EXPECT_LT(gpu::atrous_edgeWeight(p, n, a, 3.f, p, n, glm::vec3(0.8f, 0.1f, 0.1f), sigmas), 1e-3f);
    // Luminance: equal values weigh 1 even where the deviation is 0; a difference of sigma
    // deviations weighs 1/e; without noise any difference stops the filter; sigma 0 = off.
    EXPECT_FLOAT_EQ(gpu::atrous_luminanceWeight(0.3f, 0.3f, 0.f, 4.f), 1.f);
    EXPECT_NEAR(gpu::atrous_luminanceWeight(0.3f, 0.7f, 0.1f, 4.f), std::exp(-1.f), 1e-6f);
    EXPECT_NEAR(gpu::atrous_luminanceWeight(0.7f, 0.3f, 0.1f, 4.f), std::exp(-1.f), 1e-6f);
    EXPECT_LT(gpu::atrous_luminanceWeight(0.3f, 0.31f, 0.f, 4.f), 1e-6f);
    EXPECT_FLOAT_EQ(gpu::atrous_luminanceWeight(0.3f, 0.9f, 0.f, 0.f), 1.f);
}

TEST(Atrous, ConstantImageStaysConstant) {
    const Planes planes = stepScene();
    const GBuffer g = makeGBuffer(planes);
    for (int channels : {1, 3})
        for (int iterations : {1, 3, 5, 8}) {
            AtrousSettings s;
            s.iterations = iterations;
            Image input(planes.width, planes.height, channels);
            for (size_t i = 0; i < input.pixels.size(); ++i) input.pixels[i] = 0.37f + 0.1f * float(i % channels);
            const Image out = filtered(g, input, s);
            double worst = 0.0;
            for (int y = 0; y < out.height; ++y)
                for (int x = 0; x < out.width; ++x)
                    for (int c = 0; c < channels; ++c)
                        worst = std::max(worst, double(std::abs(out.at(x, y, c) - input.at(x, y, c))));
            EXPECT_LT(worst, 1e-6) << channels << " channels, " << iterations << " iterations";
        }
}

// On one uniform plane every tap weighs its kernel weight alone (the luminance term off: it
// would keep the impulse as the edge it is), so an impulse far from the borders spreads into
// the product of the iterations' kernels: its mass stays 1 when the weights of every pixel sum
// to 1.
TEST(Atrous, WeightsSumToOne) {
    Planes planes;
    planes.width = planes.height = 320;  // the 5 iterations reach 62 + 62 pixels: every pixel touched keeps all its taps
    planes.depth = [](int, int) { return 4.f; };
    const GBuffer g = makeGBuffer(planes);
    for (int iterations : {1, 2, 3, 4, 5}) {
        AtrousSettings s;
        s.iterations = iterations;
        s.sigmaLuminance = 0.f;
        Image impulse(planes.width, planes.height, 1, 0.f);
        impulse.at(160, 160) = 1.f;
        const Image out = filtered(g, impulse, s);
        double mass = 0.0;
        for (float v : out.pixels) mass += v;
        std::printf("[atrous] impulse after %d iterations: mass %.7f, centre %.5f\n", iterations, mass, out.at(160, 160));
        EXPECT_NEAR(mass, 1.0, 1e-5) << iterations << " iterations";
        EXPECT_LT(out.at(160, 160), 0.15f);  // it did spread
    }
}

TEST(Atrous, DoesNotBlurAcrossADepthStep) {
    const Planes planes = stepScene();
    const GBuffer g = makeGBuffer(planes);
    // 0.2 on the near plane, 0.8 on the far one, each with +-0.15 of noise.
    Image input(planes.width, planes.height, 1);
    for (int y = 0; y < input.height; ++y)
        for (int x = 0; x < input.width; ++x) input.at(x, y) = (x < 24 ? 0.2f : 0.8f) + 0.15f * hashNoise(x, y, 0);
    AtrousSettings s;  // the defaults: 5 iterations reach 62 pixels, across the whole step
    const Image out = filtered(g, input, s);
    double in[2] = {0, 0}, res[2] = {0, 0}, sq[2] = {0, 0}, sqIn[2] = {0, 0};
    int count[2] = {0, 0};
    for (int y = 0; y < input.height; ++y)
        for (int x = 0; x < input.width; ++x) {
            if (!(planes.depth(x, y) > 0.f)) continue;
            const int side = x < 24 ? 0 : 1;
            const double base = side == 0 ? 0.2 : 0.8;
            in[side] += input.at(x, y);
            res[side] += out.at(x, y);
            sq[side] += (out.at(x, y) - base) * (out.at(x, y) - base);
            sqIn[side] += (input.at(x, y) - base) * (input.at(x, y) - base);
            ++count[side];
        }
    for (int side = 0; side < 2; ++side) {
        const double inMean = in[side] / count[side], outMean = res[side] / count[side];
        const double rmsIn = std::sqrt(sqIn[side] / count[side]), rmsOut = std::sqrt(sq[side] / count[side]);
        std::printf("[atrous] depth step, %s side: mean %.4f -> %.4f (%+.3f%%), noise rms %.4f -> %.4f\n",
                    side == 0 ? "near" : "far", inMean, outMean, 100.0 * (outMean / inMean - 1.0), rmsIn, rmsOut);
        EXPECT_LT(std::abs(outMean / inMean - 1.0), 0.01) << (side == 0 ? "near" : "far");
        EXPECT_LT(rmsOut, 0.25 * rmsIn) << "the filter should remove most of the noise within a surface";
    }
    // Next to the step on both sides, too: no pixel within 4 of it is pulled toward the other side.
    for (int y = 0; y < input.height; ++y)
        for (int x = 20; x < 28; ++x) {
            EXPECT_NEAR(out.at(x, y), x < 24 ? 0.2f : 0.8f, 0.1f) << x << "," << y;
        }
}

TEST(Atrous, Deterministic) {
    const Planes planes = stepScene();
    const GBuffer g = makeGBuffer(planes);
    Image input(planes.width, planes.height, 3);
    for (int y = 0; y < input.height; ++y)
        for (int x = 0; x < input.width; ++x)
            for (int c = 0; c < 3; ++c) input.at(x, y, c) = 0.5f + 0.4f * hashNoise(x, y, c);
    AtrousSettings s;
    const Image a = filtered(g, input, s, true), b = filtered(g, input, s, true);
    EXPECT_EQ(a.pixels, b.pixels);
}
