// The shared cone march (shaders/cone/cone_march_shared.h) and tangent frame
// (shaders/common/tangent_frame.h) against closed forms, on the CPU: a uniform medium at
// level 0 composites to 1 - (1 - alpha)^L, a saturated cone closes to the medium's colour,
// the footprint and plane limit give the levels they state, the leaving test, and the frame.
// tests/gpu/cone_march_shared_test.cpp holds the shaders to the same text.
#include "common/tangent_frame.h"
#include "cone/cone_march_shared.h"
#include "cone/cone_settings.h"
#include "reference/sampling_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace vct {
namespace {

// A uniform medium of opacity `alpha` per voxel and colour `colour`, at level 0 everywhere
// and without a border.
struct UniformMedium {
    float alpha;
    glm::vec3 colour;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sample(glm::vec3, glm::vec3, float, float, glm::vec2) const { return glm::vec4(colour * alpha, alpha); }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

gpu::ConeMarch march(float maxAlpha) { return {0.1f, 0.5f, maxAlpha, 0.f, glm::vec3(0.f), 0.f, 0.f}; }

TEST(ConeMarch, UniformMediumCompositesToItsTransmittance) {
    UniformMedium medium{0.2f, {0.5f, 0.25f, 1.f}};
    const glm::vec3 d(0.f, 0.f, 1.f);
    for (float length : {1.f, 3.5f, 10.f}) {
        // Steps of beta = 0.5 voxels, each corrected to (1 - alpha)^0.5: the whole length
        // transmits (1 - alpha)^L, and the premultiplied radiance keeps the colour's ratio.
        const gpu::ConeResult r = gpu::cone_marchVolume(medium, march(1.f), glm::vec3(0.f), d, 1.5f, 1.f, length, 0.f);
        const float expected = 1.f - std::pow(1.f - medium.alpha, length);
        EXPECT_NEAR(r.alpha, expected, 1e-5f) << "length " << length;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.radiance[k], medium.colour[k] * expected, 1e-5f);
    }
}

TEST(ConeMarch, SaturatedConeClosesToTheMediumsColour) {
    UniformMedium medium{0.3f, {0.5f, 0.25f, 1.f}};
    const gpu::ConeResult r =
        gpu::cone_marchVolume(medium, march(0.9f), glm::vec3(0.f), glm::vec3(1.f, 0.f, 0.f), 1.5f, 1.f, 100.f, 0.f);
    EXPECT_EQ(r.alpha, 1.f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.radiance[k], medium.colour[k], 1e-6f);
}

TEST(ConeMarch, FootprintAndPlaneLimitLevels) {
    const gpu::ConeMarch open{0.5f, 0.5f, 0.99f, 0.f, glm::vec3(0.f), 0.f, 0.f};
    EXPECT_EQ(gpu::cone_footprintLod(open, 0.5f, 1.5f, 0.f), 0.f) << "at least one voxel";
    EXPECT_NEAR(gpu::cone_footprintLod(open, 8.f, 1.5f, 0.f), 3.f, 1e-6f) << "diameter 2 t tan = 8 voxels";
    // Plane limit: whole levels of at most h / 1.5 voxels, h = h0 + t rise.
    const gpu::ConeMarch limited{0.5f, 0.5f, 0.99f, 1.5f, glm::vec3(0.f), 0.f, 0.f};
    EXPECT_EQ(gpu::cone_footprintLod(limited, 8.f, 1.5f, 0.f), 0.f) << "a cone along the plane stays at level 0";
    EXPECT_EQ(gpu::cone_footprintLod(limited, 8.f, 1.5f, 0.5f), 1.f) << "h = 5.5: texels of 2 voxels";
    EXPECT_EQ(gpu::cone_footprintLod(limited, 8.f, 1.5f, 1.f), 2.f) << "h = 9.5: texels of 4 voxels";
    EXPECT_NEAR(gpu::cone_footprintLod(limited, 6.f, 20.f, 1.f), 2.5849625f, 1e-6f) << "the footprint, under the limit";
}

// GL halves each axis rounding down: a grid 127 voxels tall has texels of 127 / 3 = 42.3
// voxels at level 5 and 127 / 7 = 18.1 at level 4, so a sample 60 voxels above the tangent
// plane (reach 40) may use level 4 only: level 5's base texels reach up to 63.5 voxels,
// where a cube's reach 48 would have allowed it.
TEST(ConeMarch, ThePlaneLimitMeasuresTheTexelsALevelHas) {
    EXPECT_NEAR(gpu::cone_texelExtent(glm::vec3(128.f, 127.f, 128.f), 5.f), 127.f / 3.f, 1e-4f);
    EXPECT_NEAR(gpu::cone_texelExtent(glm::vec3(128.f, 127.f, 128.f), 4.f), 127.f / 7.f, 1e-4f);
    EXPECT_EQ(gpu::cone_texelExtent(glm::vec3(128.f), 5.f), 32.f);
    EXPECT_EQ(gpu::cone_texelExtent(glm::vec3(0.f), 3.f), 8.f) << "no base: texels of 2^level";
    // One texel along an axis shorter than 2^level spans the axis, less than 2^level.
    EXPECT_EQ(gpu::cone_texelExtent(glm::vec3(64.f, 11.f, 64.f), 4.f), 16.f);
    EXPECT_NEAR(gpu::cone_texelExtent(glm::vec3(64.f, 11.f, 64.f), 3.f), 11.f, 1e-6f);
    const gpu::ConeMarch cube{0.5f, 0.5f, 0.99f, 1.5f, glm::vec3(128.f), 0.f, 0.f};
    const gpu::ConeMarch tall{0.5f, 0.5f, 0.99f, 1.5f, glm::vec3(128.f, 127.f, 128.f), 0.f, 0.f};
    EXPECT_EQ(gpu::cone_footprintLod(cube, 200.f, 0.f, 0.3f), 5.f) << "h = 60, reach 40: 32-voxel texels";
    EXPECT_EQ(gpu::cone_footprintLod(tall, 200.f, 0.f, 0.3f), 4.f) << "level 5's texels are 42.3 > 40";
    EXPECT_EQ(gpu::cone_footprintLod(tall, 200.f, 0.f, 0.5f), 5.f) << "h = 100, reach 66.7";
}

TEST(ConeMarch, LeavingOnlyOutsideAndMovingAway) {
    const glm::vec3 size(32.f);
    EXPECT_FALSE(gpu::cone_leaving({16.f, 16.f, 16.f}, {1.f, 0.f, 0.f}, size, 1.5f));
    EXPECT_FALSE(gpu::cone_leaving({33.f, 16.f, 16.f}, {1.f, 0.f, 0.f}, size, 1.5f)) << "within the reach";
    EXPECT_TRUE(gpu::cone_leaving({34.f, 16.f, 16.f}, {1.f, 0.f, 0.f}, size, 1.5f));
    EXPECT_FALSE(gpu::cone_leaving({34.f, 16.f, 16.f}, {-1.f, 0.f, 0.f}, size, 1.5f)) << "coming back in";
    EXPECT_TRUE(gpu::cone_leaving({16.f, -2.f, 16.f}, {0.f, 0.f, 1.f}, size, 1.5f)) << "not coming back";
}

// vct.level-bias moves the footprint's level by b through the march's tangent (exactly the
// unbiased tangent at 0, so the default march is unchanged to the bit).
TEST(ConeMarch, TheLevelBiasMovesTheFootprintsLevel) {
    ConeSettings s;
    volatile float runtime = 60.f;  // tan at run time, as the passes call it
    const float aperture = runtime, half = 0.5f * aperture * float(M_PI) / 180.f;
    EXPECT_EQ(coneFootprintTangent(s, aperture), std::tan(half));
    for (float b : {-2.f, -1.f, -0.5f, 1.f}) {
        s.levelBias = b;
        const gpu::ConeMarch m{coneFootprintTangent(s, aperture), 0.5f, 0.99f, 0.f, glm::vec3(0.f), 0.f, 0.f};
        // Diameter 2 t tan(30 deg) = 36.95 voxels at t = 32: level 5.208 + b, never below 0.
        EXPECT_NEAR(gpu::cone_footprintLod(m, 32.f, 1.5f, 0.f), std::log2(64.f * std::tan(half)) + b, 1e-5f) << b;
        EXPECT_EQ(gpu::cone_footprintLod(m, 0.25f, 1.5f, 0.f), 0.f) << b << ": at least one voxel";
    }
}

// An empty volume that records where a march samples and at which level.
struct RecordingVolume {
    std::vector<glm::vec4> samples;  // position, level
    float lod(float l, glm::vec3) const { return l; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sample(glm::vec3 p, glm::vec3, float l, float, glm::vec2) {
        samples.push_back(glm::vec4(p, l));
        return glm::vec4(0.f);
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// vct.end-taper: a trilinear sample at distance s of level l sees up to s + 2^ceil(l). Untapered, a
// wide cone's last samples reach a footprint past the maximum distance; tapered, whole levels
// whose reach ends at it, down to level 0, whose texel is the only reach left past it, at the
// price of a few more steps.
TEST(ConeMarch, ATaperedEndSamplesNothingPastTheMaximumDistance) {
    const float maxDist = 40.f;
    const glm::vec3 d(0.f, 0.f, 1.f);
    gpu::ConeMarch m{0.5f, 0.5f, 0.99f, 0.f, glm::vec3(0.f), 0.f, 0.f};
    RecordingVolume plain, tapered;
    gpu::cone_marchVolume(plain, m, glm::vec3(0.f), d, 1.5f, 1.f, maxDist, 0.f);
    m.endRatio = gpu::cone_endRatio(m.stepFactor);
    EXPECT_FLOAT_EQ(m.endRatio, 1.25f) << "half a step of beta = 0.5 texels, and the texel the sample sees past it";
    gpu::cone_marchVolume(tapered, m, glm::vec3(0.f), d, 1.5f, 1.f, maxDist, 0.f);
    // A fractional level blends in the next coarser one: its texel is the reach.
    auto reach = [](const glm::vec4& s) { return s.z + std::exp2(std::ceil(s.w)); };
    ASSERT_FALSE(plain.samples.empty());
    EXPECT_GT(reach(plain.samples.back()), maxDist + 8.f) << "the last footprint is about 40 voxels wide";
    for (size_t i = 0; i < tapered.samples.size(); ++i) {
        const glm::vec4& s = tapered.samples[i];
        if (s.w > 0.f) {
            EXPECT_LE(reach(s), maxDist + 1e-4f) << "sample " << i << " at " << s.z << ", level " << s.w;
        } else {
            EXPECT_LE(reach(s), maxDist + 1.f) << "sample " << i;
        }
    }
    // The march still ends at the maximum distance, in a few more steps.
    EXPECT_GT(tapered.samples.back().z, maxDist - 0.5f);
    EXPECT_GT(tapered.samples.size(), plain.samples.size());
    EXPECT_LE(tapered.samples.size(), plain.samples.size() + 12);
    // Before the end both march the footprint's level.
    EXPECT_EQ(tapered.samples[0], plain.samples[0]);
}

TEST(TangentFrame, OrthonormalAroundTheNormalForBothSigns) {
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        for (const glm::mat3& f : {gpu::frame_fromZ(n), gpu::frame_fromZWithSign(n, std::copysign(1.f, n.z))}) {
            EXPECT_EQ(f[2], n);
            EXPECT_NEAR(glm::dot(f[0], f[1]), 0.f, 1e-6f);
            EXPECT_NEAR(glm::dot(f[0], n), 0.f, 1e-6f);
            EXPECT_NEAR(glm::dot(f[1], n), 0.f, 1e-6f);
            EXPECT_NEAR(glm::length(f[0]), 1.f, 1e-6f);
            EXPECT_NEAR(glm::length(f[1]), 1.f, 1e-6f);
            EXPECT_NEAR(glm::dot(glm::cross(f[0], f[1]), n), 1.f, 1e-6f) << "right-handed";
        }
    }
    // At n.z = -0 the cone passes (+1) and the reference (the sign bit) take opposite halves.
    const glm::vec3 n(1.f, 0.f, -0.f);
    const glm::mat3 cone = gpu::frame_fromZ(n);
    const Frame reference = Frame::fromZ(n);
    EXPECT_EQ(cone[0], -reference.x);
    EXPECT_EQ(cone[1], -reference.y);
}

}  // namespace
}  // namespace vct
