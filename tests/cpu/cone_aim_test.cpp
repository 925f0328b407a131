// vct.aim's direction and reach (gpu::cone_aimedDirection, gpu::cone_aimedReach,
// shaders/cone/cone_shared.h) against closed forms: a cone started `offset` voxels up the normal
// and aimed passes through the point its ray from the surface reaches at the maximum distance,
// and ends there; one whose ray ends lower than the offset
// stays level; and the setting parses, off by default.
#include "cone/cone_settings.h"
#include "cone/cone_shared.h"
#include "core/errors.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vct {
namespace {

TEST(ConeAim, AnAimedConeMeetsItsRayAtTheMaximumDistance) {
    const float offset = 1.5f, maxDist = 40.f;
    // Normals along an axis and tilted; directions from steep to just above offset / maxDist.
    for (const glm::vec3 ng : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f))}) {
        const glm::vec3 t = glm::normalize(glm::cross(ng, glm::vec3(0.2f, 0.1f, 1.f)));
        for (float rise : {0.05f, 0.1f, 0.3f, 0.7f, 0.99f}) {
            const glm::vec3 d = glm::normalize(rise * ng + std::sqrt(1.f - rise * rise) * t);
            const glm::vec3 p(3.f, -2.f, 7.f), origin = p + ng * offset;
            const glm::vec3 a = gpu::cone_aimedDirection(d, ng, offset, maxDist);
            EXPECT_NEAR(glm::length(a), 1.f, 1e-5f);
            // The line from origin along a passes through p + d maxDist.
            const glm::vec3 target = p + d * maxDist;
            const float along = glm::dot(target - origin, a);
            EXPECT_GT(along, 0.f);
            EXPECT_LT(glm::length(origin + a * along - target), 1e-3f) << "rise " << rise;
            // It rises less than d: it descends the offset over maxDist.
            EXPECT_LT(glm::dot(a, ng), glm::dot(d, ng)) << "rise " << rise;
        }
    }
}

// It marches as far as that point (cone_aimedReach): maxDist from the raised start would carry it
// about offset * rise past its ray's end, where it would see what lies beyond maxDist.
TEST(ConeAim, AnAimedConeEndsAtItsRaysPointAtTheMaximumDistance) {
    const float offset = 1.5f, maxDist = 40.f;
    for (const glm::vec3 ng : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f))}) {
        const glm::vec3 t = glm::normalize(glm::cross(ng, glm::vec3(0.2f, 0.1f, 1.f)));
        for (float rise : {0.05f, 0.1f, 0.3f, 0.7f, 0.9f, 1.f}) {
            const glm::vec3 d = glm::normalize(rise * ng + std::sqrt(1.f - rise * rise) * t);
            const glm::vec3 p(3.f, -2.f, 7.f), origin = p + ng * offset;
            const glm::vec3 a = gpu::cone_aimedDirection(d, ng, offset, maxDist);
            const float reach = gpu::cone_aimedReach(d, ng, offset, maxDist);
            EXPECT_LT(glm::length(origin + a * reach - (p + d * maxDist)), 1e-3f) << "rise " << rise;
            // The law of cosines: shorter than maxDist by about offset * rise.
            const float exact = std::sqrt(maxDist * maxDist - 2.f * maxDist * offset * rise + offset * offset);
            EXPECT_NEAR(reach, exact, 1e-3f) << "rise " << rise;
        }
    }
    // Kept level, it ends above its ray's end, at the horizontal distance of it.
    const glm::vec3 ng(0, 1, 0), d = glm::normalize(glm::vec3(1.f, 0.02f, 0.f));
    EXPECT_NEAR(gpu::cone_aimedReach(d, ng, offset, maxDist), maxDist * d.x, 1e-4f);
}

TEST(ConeAim, AConeWhoseRayEndsBelowTheOffsetStaysLevel) {
    const float offset = 1.5f, maxDist = 40.f;  // rays rising less than 1.5 / 40 = 0.0375
    const glm::vec3 ng(0, 1, 0);
    for (float rise : {0.001f, 0.02f, 0.0374f}) {
        const glm::vec3 d = glm::normalize(glm::vec3(std::sqrt(1.f - rise * rise), rise, 0.f));
        const glm::vec3 a = gpu::cone_aimedDirection(d, ng, offset, maxDist);
        EXPECT_NEAR(a.y, 0.f, 1e-6f) << "rise " << rise;
        EXPECT_NEAR(a.x, 1.f, 1e-6f) << "rise " << rise;
    }
    // Straight up there is no way to aim: the direction is kept.
    const glm::vec3 up = gpu::cone_aimedDirection(ng, ng, offset, maxDist);
    EXPECT_NEAR(up.y, 1.f, 1e-6f);
    const glm::vec3 upShort = gpu::cone_aimedDirection(ng, ng, offset, 1.f);  // maxDist below the offset
    EXPECT_NEAR(upShort.y, 1.f, 1e-6f);
}

TEST(ConeAim, TheParameterIsOffByDefaultAndParses) {
    EXPECT_FALSE(readConeSettings(ParamMap()).aim);
    ParamMap p;
    p.set("vct.aim=1");
    EXPECT_TRUE(readConeSettings(p).aim);
    ParamMap bad;
    bad.set("vct.aim=sideways");
    EXPECT_THROW(readConeSettings(bad), UsageError);
}

}  // namespace
}  // namespace vct
