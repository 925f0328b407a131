// vct.jitter's per-pixel turn of the cone set (cone_shared.h, shared by the cone passes and the
// cone-model reference): in [0, 2 pi), a function of pixel and seed alone, spread evenly over
// the circle, and different for neighbours and for another seed.
#include "cone/cone_shared.h"
#include "reference/cone_model.h"
#include "cone/cone_set.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

TEST(ConeJitter, AnglesAreDeterministicAndCoverTheCircleEvenly) {
    constexpr int kSide = 128;
    constexpr int kBins = 16;
    int bins[kBins] = {};
    double sumCos = 0.0, sumSin = 0.0;
    int sameAsRightNeighbour = 0, sameWithOtherSeed = 0;
    for (uint32_t y = 0; y < kSide; ++y)
        for (uint32_t x = 0; x < kSide; ++x) {
            const float a = vct::gpu::cone_jitterAngle(x, y, 7u);
            ASSERT_GE(a, 0.f);
            ASSERT_LT(a, float(kTwoPi));
            ASSERT_EQ(a, vct::gpu::cone_jitterAngle(x, y, 7u));
            bins[std::min(kBins - 1, int(a / kTwoPi * kBins))]++;
            sumCos += std::cos(a);
            sumSin += std::sin(a);
            sameAsRightNeighbour += a == vct::gpu::cone_jitterAngle(x + 1, y, 7u) ? 1 : 0;
            sameWithOtherSeed += a == vct::gpu::cone_jitterAngle(x, y, 8u) ? 1 : 0;
        }
    const double n = double(kSide * kSide), expected = n / kBins;
    // Each bin within 5 standard deviations of a uniform draw's count.
    for (int b = 0; b < kBins; ++b) EXPECT_NEAR(bins[b], expected, 5.0 * std::sqrt(expected)) << "bin " << b;
    // The mean direction of uniform angles is 0, within ~1/sqrt(n) per component.
    EXPECT_LT(std::hypot(sumCos, sumSin) / n, 5.0 / std::sqrt(n));
    EXPECT_LT(sameAsRightNeighbour, 4);
    EXPECT_LT(sameWithOtherSeed, 4);
}

// The cone model turns its set as cone_common.glsl turns the frame: a turn by a quarter maps
// the tangent frame's x onto its y, so a cone's axis moves by 90 degrees about the normal.
TEST(ConeJitter, TheConeModelTurnsItsAxesAboutTheNormal) {
    const std::vector<glm::vec4> one{glm::vec4(glm::normalize(glm::vec3(1.f, 0.f, 1.f)), 1.f)};
    const vct::ConeModelSampler sampler(one, 2.f);  // a 2 degree cone: directions hug the axis
    const glm::vec3 n(0.f, 0.f, 1.f);
    const glm::mat3 frame = vct::gpu::frame_fromZ(n);
    const glm::vec3 turnedAxis = glm::normalize(frame * glm::vec3(0.f, 1.f, 1.f));
    const glm::vec3 axis = glm::normalize(frame * glm::vec3(1.f, 0.f, 1.f));
    const vct::ConeModelSample straight = sampler.sample(glm::vec2(0.5f), n, n);
    const vct::ConeModelSample turned = sampler.sample(glm::vec2(0.5f), n, n, float(kTwoPi / 4));
    EXPECT_GT(glm::dot(straight.direction, axis), 0.999f);
    EXPECT_GT(glm::dot(turned.direction, turnedAxis), 0.999f);
}
