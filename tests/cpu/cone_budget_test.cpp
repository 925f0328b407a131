// The loop bound behind a cone pass's dispatches (src/cone/cone_budget.h): the shared march
// (shaders/cone/cone_march_shared.h) never takes more steps than coneLoopBound allows for, the
// plane limit's level search steps down at most once per step, and the cones per dispatch stay
// within the budget.
#include "cone/cone_budget.h"
#include "cone/cone_march_shared.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vct {
namespace {

// An empty volume (no cone ever saturates) whose level is the footprint's, as the dense grid's
// is below its coarsest level: the march runs to its distance limit.
struct EmptyVolume {
    float lod(float l, glm::vec3) const { return l; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sample(glm::vec3, glm::vec3, float, float, glm::vec2) const { return glm::vec4(0.f); }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Steps the bound allows one cone (coneLoopBound less the gather's own iteration, over the
// loops per step).
long long boundSteps(float maxDist, float beta) { return (coneLoopBound(maxDist, beta, 1) - 1); }

}  // namespace

TEST(ConeBudget, AMarchTakesNoMoreStepsThanTheBound) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    const EmptyVolume volume;
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
        const float beta = 0.05f + 1.95f * unit(rng);
        const float maxDist = (i % 4 == 0) ? 2000.f : 200.f * unit(rng);  // past CONE_MAX_STEPS too
        const float tanHalf = std::tan(0.5f * (1.f + 119.f * unit(rng)) * float(M_PI) / 180.f);
        // Rise 0 (a cone along the tangent plane) keeps the plane limit at level 0: the
        // longest march there is.
        const float rise = (i % 3 == 0) ? 0.f : unit(rng);
        const float planeRatio = (i % 2 == 0) ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f;
        // vct.end-taper: finer levels near the end, never below level 0, so still beta a step.
        const float endRatio = (i % 5 < 2) ? gpu::cone_endRatio(beta) : 0.f;
        const gpu::ConeMarch m{tanHalf, beta, 1.f, planeRatio, glm::vec3(64.f, 41.f, 64.f), endRatio, 0.f};
        const gpu::ConeResult r =
            gpu::cone_marchVolume(volume, m, glm::vec3(0.f), glm::vec3(0.f, 0.f, 1.f), 1.5f, rise, maxDist, 0.f);
        EXPECT_LE((long long)r.samples, boundSteps(maxDist, beta))
            << "beta " << beta << " R " << maxDist << " rise " << rise << " end ratio " << endRatio;
        ++checked;
    }
    // A cone along the plane with the plane limit meets the bound within two steps.
    const gpu::ConeMarch flat{0.5f, 0.5f, 1.f, gpu::CONE_PLANE_LIMIT_RATIO, glm::vec3(0.f), 0.f, 0.f};
    const gpu::ConeResult r =
        gpu::cone_marchVolume(volume, flat, glm::vec3(0.f), glm::vec3(1.f, 0.f, 0.f), 1.5f, 0.f, 100.f, 0.f);
    EXPECT_GE((long long)r.samples + 2, boundSteps(100.f, 0.5f));
    EXPECT_EQ(checked, 400);
}

// The plane limit's search (cone_footprintLod) starts at floor(log2(reach)) and steps down
// while a texel is longer than the reach: a texel of level c is shorter than 2^(c + 1) voxels
// on any grid, so one step down always ends it.
TEST(ConeBudget, ThePlaneLimitsSearchStepsDownAtMostOnce) {
    for (int x = 1; x <= 300; x += 7)
        for (int y = 1; y <= 300; y += 13) {
            const glm::vec3 base(float(x), float(y), 64.f);
            for (int c = 0; c <= 9; ++c) EXPECT_LT(gpu::cone_texelExtent(base, float(c)), std::exp2(float(c + 1)));
        }
}

TEST(ConeBudget, ConesPerDispatchStayWithinTheBudget) {
    for (float maxDist : {1.f, 8.f, 64.f, 500.f, 1e6f})
        for (float beta : {0.05f, 0.5f, 2.f})
            for (int loops : {1, 2, 16}) {
                const int cones = conesPerDispatch(maxDist, beta, loops, 0);
                EXPECT_GE(cones, 1);
                EXPECT_LE(cones, gpu::CONE_BLOCK_CONES);
                if (cones > 1) {
                    EXPECT_LE(cones * coneLoopBound(maxDist, beta, loops), gpu::CONE_LOOP_BUDGET);
                }
                EXPECT_LE(conesPerDispatch(maxDist, beta, loops, 3), 3) << "vct.dispatch-cones lowers it";
            }
    // A short AO march fits the whole uniform block; a GI march to the grid's far side
    // (CONE_MAX_STEPS steps) fits 29 cones with the plane limit's search.
    EXPECT_EQ(conesPerDispatch(8.f, 0.5f, 2, 0), gpu::CONE_BLOCK_CONES);
    EXPECT_EQ(coneLoopBound(1e6f, 0.5f, 2), 2 * gpu::CONE_MAX_STEPS + 1);
    EXPECT_EQ(conesPerDispatch(1e6f, 0.5f, 2, 0), gpu::CONE_LOOP_BUDGET / (2 * gpu::CONE_MAX_STEPS + 1));
}

}  // namespace vct
