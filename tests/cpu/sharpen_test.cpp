// vct.sharpen's filter (gpu::cone_sharpenTexel, shaders/cone/cone_shared.h) against closed
// forms, on the CPU: the weights it gives, and the shared march (cone_march_shared.h) through a
// one-texel sheet filtered along the crossing axis with it, where linear filtering leaks.
#include "cone/cone_march_shared.h"
#include "cone/cone_settings.h"
#include "core/errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vct {
namespace {

// The weight linear filtering gives texel i + 1 at coordinate x (texel units, centres at
// i + 1/2) when x lies between centres i and i + 1.
float upperWeight(float x) { return x - 0.5f - std::floor(x - 0.5f); }

TEST(Sharpen, TheFilterGivesTheSharpenedWeightsAndKeepsTheTexelPair) {
    for (float s : {1.f, 2.f, 4.f, 16.f})
        for (int i : {-3, 0, 7, 250})
            for (float f : {0.f, 0.1f, 0.2f, 0.375f, 0.45f, 0.5f, 0.55f, 0.625f, 0.8f, 0.99f}) {
                const float x = float(i) + 0.5f + f;
                const float y = gpu::cone_sharpenTexel(x, s);
                const float expected = std::clamp((f - 0.5f) * s + 0.5f, 0.f, 1.f);
                // Still between the same two centres, with the sharpened weight on the upper one.
                EXPECT_GE(y, float(i) + 0.5f - 1e-4f) << "s " << s << " i " << i << " f " << f;
                EXPECT_LE(y, float(i) + 1.5f + 1e-4f) << "s " << s << " i " << i << " f " << f;
                const float w = std::abs(y - (float(i) + 1.5f)) < 1e-5f ? 1.f : upperWeight(y);
                EXPECT_NEAR(w, expected, 2e-4f) << "s " << s << " i " << i << " f " << f;
                if (s == 1.f) {
                    EXPECT_NEAR(y, x, 2e-5f) << "s = 1 is the identity";
                }
            }
    // Monotone: a sample moving forward never moves back.
    float last = -1e9f;
    for (int k = 0; k <= 400; ++k) {
        const float y = gpu::cone_sharpenTexel(2.f + 0.01f * float(k), 4.f);
        EXPECT_GE(y, last - 1e-6f);
        last = y;
    }
}

// Texels along x (centres at i + 0.5) holding opacity `alpha[i]`, filtered linearly between
// centres as a GL texture filters them, at the coordinate vct.sharpen = s moves the sample to.
struct SharpenedRow {
    std::vector<float> alpha;
    float s = 1.f;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    float texel(int i) const { return (i >= 0 && i < int(alpha.size())) ? alpha[size_t(i)] : 0.f; }
    glm::vec4 sample(glm::vec3 p, glm::vec3, float, float, glm::vec2) const {
        const float x = gpu::cone_sharpenTexel(p.x, s) - 0.5f;
        const int i = int(std::floor(x));
        const float f = x - float(i);
        return glm::vec4(0.f, 0.f, 0.f, (1.f - f) * texel(i) + f * texel(i + 1));
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Transmittance of a march along +x from x0 over 20 voxels (the default step, half a voxel at
// a footprint of one voxel), no early exit.
float transmittance(const SharpenedRow& row, float x0) {
    const gpu::ConeMarch m{0.01f, gpu::CONE_DEFAULT_STEP, 1.f, 0.f, glm::vec3(0.f), 0.f, 0.f};
    const gpu::ConeResult r = gpu::cone_marchVolume(row, m, glm::vec3(x0, 0.f, 0.f), glm::vec3(1.f, 0.f, 0.f), 1.5f,
                                                    0.f, 20.f, 0.f);
    return 1.f - r.alpha;
}

// In the continuous limit a sheet of opacity a filtered with weights w(x) passes
// exp(integral of log(1 - a w)): exp(2 I(a)) for the linear tent, with I(a) = integral over
// [0, 1] of log(1 - a u) = -1 - (1 - a) log(1 - a) / a (exp(-2) = 13.5% for an opaque texel),
// and (1 - a)^(1 - 1/s) exp(2 I(a) / s) sharpened by s: closed for a = 1, and for a = 0.5 at
// s = 4 0.510 against the texel's own 0.5 (the tent: 0.541).
TEST(Sharpen, AMarchThroughAOneTexelSheetIsClosedAtEveryPhase) {
    for (float a : {1.f, 0.75f, 0.5f, 0.2f}) {
        SharpenedRow tent{std::vector<float>(12, 0.f), 1.f};
        tent.alpha[6] = a;
        SharpenedRow sharp = tent;
        sharp.s = 4.f;
        double sharpError = 0.0, tentError = 0.0;
        for (int k = 0; k < 20; ++k) {
            // Sample phases over one step (half a texel).
            const float x0 = 0.025f * float(k);
            const float t = transmittance(sharp, x0), tt = transmittance(tent, x0);
            if (a >= 1.f) {
                EXPECT_LT(t, 1e-3f) << "start " << x0 << ": an opaque sheet closes at every phase";
            } else {
                // Never farther from the texel's own transmittance than the tent (equal where a
                // sample meets the sheet's centre: both filters weigh it 1 and its neighbours 1/2).
                EXPECT_LE(std::abs(t - (1.f - a)), std::abs(tt - (1.f - a)) + 1e-5f) << "alpha " << a << " start " << x0;
            }
            sharpError += std::abs(t - (1.f - a));
            tentError += std::abs(tt - (1.f - a));
        }
        std::printf("[sharpen] alpha %.2f: mean |T - (1 - alpha)| sharpened %.4f, tent %.4f\n", a, sharpError / 20.0,
                    tentError / 20.0);
        if (a >= 1.f) {
            EXPECT_GT(tentError / 20.0, 0.1) << "the tent's leak (exp(-2) in the continuous limit)";
        }
        EXPECT_LT(sharpError, 0.6 * tentError) << "alpha " << a;
    }
}

// vct.sharpen defaults to 1 (trilinear), takes [1, 16], and filters the directional levels, so
// an isotropic march refuses it with the keys named.
TEST(Sharpen, TheParameterNeedsTheDirectionalLevels) {
    EXPECT_EQ(readConeSettings(ParamMap()).sharpen, 1.f);
    EXPECT_FALSE(sharpensLevels(readConeSettings(ParamMap())));
    ParamMap p;
    p.set("vct.sharpen", "4");
    EXPECT_EQ(readConeSettings(p).sharpen, 4.f);
    EXPECT_TRUE(sharpensLevels(readConeSettings(p)));
    p.set("vct.aniso", "0");
    try {
        readConeSettings(p);
        FAIL() << "vct.sharpen=4 with vct.aniso=0 was accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("vct.sharpen"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("vct.aniso=1"), std::string::npos) << e.what();
    }
    for (const char* bad : {"0.5", "17", "nan"}) {
        ParamMap b;
        b.set("vct.sharpen", bad);
        EXPECT_THROW(readConeSettings(b), UsageError) << bad;
    }
}

}  // namespace
}  // namespace vct
