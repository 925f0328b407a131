// Lanes (cone/cone_set.h): each cone of a set split into narrower cones over its cap, and the
// cubic grid shape (vct/voxel_region.h) the convergent march runs on.
#include "cone/cone_set.h"
#include "cone/cone_settings.h"
#include "cone/cone_shared.h"
#include "core/errors.h"
#include "eval/analytic_ao.h"
#include "eval/convergence.h"
#include "vct/voxel_region.h"
#include "voxelize/voxel_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace vct;

namespace {

const glm::vec3 kUp(0, 1, 0);

double angleBetween(glm::vec3 a, glm::vec3 b) {
    return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0));
}

}  // namespace

TEST(ConeLanes, OneLaneIsTheConeItself) {
    for (int n : {6, 16, 32, 64}) {
        const std::vector<glm::vec4> set = diffuseConeSet(n);
        const ConeLanes l = coneLanes(set, defaultConeAperture(n), 1);
        ASSERT_EQ(l.cones.size(), set.size());
        EXPECT_EQ(l.apertureDeg, defaultConeAperture(n));
        for (size_t i = 0; i < set.size(); ++i) EXPECT_EQ(l.cones[i], set[i]);
    }
}

TEST(ConeLanes, LanesShareTheirConesWeightSolidAngleAndCap) {
    const std::vector<glm::vec4> set = diffuseConeSet(6);
    const double alpha = 0.5 * 60.0 * M_PI / 180.0;
    for (int lanes : {4, 16, 64}) {
        const ConeLanes l = coneLanes(set, 60.f, lanes);
        ASSERT_EQ(l.cones.size(), set.size() * size_t(lanes));
        // The march finds a lane's cone by index (cone_laneCone) among the set's axes.
        EXPECT_EQ(l.lanesPerCone, lanes);
        EXPECT_EQ(l.axes, set);
        // Each lane: 1 / lanes of its cone's solid angle, 2 pi (1 - cos(alpha)).
        const double laneHalf = 0.5 * double(l.apertureDeg) * M_PI / 180.0;
        EXPECT_NEAR(double(lanes) * (1.0 - std::cos(laneHalf)), 1.0 - std::cos(alpha), 1e-6) << lanes;
        double total = 0.0;
        for (size_t c = 0; c < set.size(); ++c) {
            double weight = 0.0, meanCos = 0.0;
            for (int i = 0; i < lanes; ++i) {
                const glm::vec4& lane = l.cones[c * size_t(lanes) + size_t(i)];
                EXPECT_EQ(gpu::cone_laneCone(int(c) * lanes + i, lanes), int(c));
                EXPECT_NEAR(glm::length(glm::vec3(lane)), 1.f, 1e-5f);
                const double theta = angleBetween(glm::vec3(lane), glm::vec3(set[c]));
                EXPECT_LE(theta, alpha + 1e-5) << "lane " << i << " of cone " << c << " leaves its cap";
                weight += lane.w;
                meanCos += std::cos(theta) / double(lanes);
            }
            EXPECT_NEAR(weight, set[c].w, 1e-6) << "cone " << c;
            // Uniform in solid angle over the cap: E[cos(theta)] = (1 + cos(alpha)) / 2; the
            // lanes sit at the centres of equal shares of cos(theta), so the mean is exact.
            EXPECT_NEAR(meanCos, 0.5 * (1.0 + std::cos(alpha)), 1e-5) << "cone " << c;
            total += weight;
        }
        EXPECT_NEAR(total, 1.0, 1e-5);
    }
}

TEST(ConeLanes, RefiningLanesConvergesToTheConeModel) {
    // The lanes' own cone model (exact visibility over each lane's cap) tends to the cone's as
    // the lanes multiply: they are a quadrature of the cap, not a different estimator. One
    // case per family, RMS over its points, exact quadratures throughout.
    std::vector<AoConvergenceCase> cases;
    std::set<std::string> families;
    for (const AoConvergenceCase& c : aoConvergenceCases())
        if (!c.onScreen && families.insert(c.family).second) cases.push_back(c);
    const std::vector<glm::vec4> set = diffuseConeSet(6);
    std::vector<double> rms;
    for (int lanes : {1, 4, 16}) {
        const ConeLanes l = coneLanes(set, 60.f, lanes);
        double sum = 0.0;
        size_t n = 0;
        for (const AoConvergenceCase& c : cases)
            for (const glm::vec3& p : c.points) {
                const double cone = analyticConeModelAo(c.occluders, p, kUp, c.radius, set, 60.f, 32);
                const double lane = analyticConeModelAo(c.occluders, p, kUp, c.radius, l.cones, l.apertureDeg, 32);
                sum += (lane - cone) * (lane - cone);
                ++n;
            }
        rms.push_back(std::sqrt(sum / double(n)));
    }
    EXPECT_LT(rms[0], 1e-9) << "one lane is the cone";
    EXPECT_LT(rms[2], 0.6 * rms[1]) << "4 lanes " << rms[1] << ", 16 lanes " << rms[2];
    EXPECT_LT(rms[2], 0.03);
}

TEST(ConeLanes, AutoKeepsALanesFootprintInVoxelsAsTheGridRefines) {
    EXPECT_EQ(resolveConeLanes(0, 6, 32, gpu::CONE_LANES_BASE_RES), 1);
    EXPECT_EQ(resolveConeLanes(0, 6, 64, gpu::CONE_LANES_BASE_RES), 4);
    EXPECT_EQ(resolveConeLanes(0, 6, 128, gpu::CONE_LANES_BASE_RES), 16);
    EXPECT_EQ(resolveConeLanes(0, 6, 256, gpu::CONE_LANES_BASE_RES), 64);
    EXPECT_EQ(resolveConeLanes(0, 6, 1024, gpu::CONE_LANES_BASE_RES), gpu::CONE_MAX_CONES / 6) << "clamped to CONE_MAX_CONES";
    EXPECT_EQ(resolveConeLanes(0, 64, 256, gpu::CONE_LANES_BASE_RES), gpu::CONE_MAX_CONES / 64);
    EXPECT_EQ(resolveConeLanes(0, 6, 16, gpu::CONE_LANES_BASE_RES), 1);
    EXPECT_EQ(resolveConeLanes(5, 6, 256, gpu::CONE_LANES_BASE_RES), 5) << "an explicit count stays";
    // vct.lanes-base: one lane per cone at that resolution, (res / base)^2 above.
    EXPECT_EQ(resolveConeLanes(0, 6, 16, 16), 1);
    EXPECT_EQ(resolveConeLanes(0, 6, 32, 16), 4);
    EXPECT_EQ(resolveConeLanes(0, 6, 256, 16), 256) << "four times base 32's 64";
    EXPECT_EQ(resolveConeLanes(0, 6, 256, 64), 16);
    EXPECT_EQ(resolveConeLanes(0, 6, 512, 16), gpu::CONE_MAX_CONES / 6) << "clamped to CONE_MAX_CONES";
    EXPECT_EQ(resolveConeLanes(7, 6, 256, 16), 7) << "an explicit count stays";
    // Half the lane's aperture per doubling: tan(half) * resolution stays within ~2%.
    const std::vector<glm::vec4> set = diffuseConeSet(6);
    const double at128 = std::tan(0.5 * coneLanes(set, 60.f, 16).apertureDeg * M_PI / 180.0) * 128.0;
    const double at256 = std::tan(0.5 * coneLanes(set, 60.f, 64).apertureDeg * M_PI / 180.0) * 256.0;
    EXPECT_NEAR(at256 / at128, 1.0, 0.02);
}

TEST(ConeLanes, TooManyLanesAreRefusedNamingTheKey) {
    ParamMap p;
    p.set("vct.lanes=683");
    try {
        readConeSettings(p);
        FAIL() << "683 lanes x 6 cones accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("vct.lanes"), std::string::npos) << e.what();
    }
    p.set("vct.lanes=682");  // CONE_MAX_CONES = 4096
    EXPECT_EQ(readConeSettings(p).lanes, 682);
    EXPECT_THROW(coneLanes(diffuseConeSet(6), 60.f, 683), InternalError);
}

TEST(CubicGrid, EveryAxisGetsTheLongestAxisCountAroundTheSameCentre) {
    Bounds3 flat;
    flat.min = glm::vec3(-4.f, 0.f, -3.f);
    flat.max = glm::vec3(4.f, 0.5f, 3.f);
    const VoxelGrid fit = makeGridLayout(flat, 64);
    EXPECT_LT(fit.resolution.y, 16) << "a flat region makes a flat grid";
    const Bounds3 cube = cubeAround(flat);
    for (int a = 0; a < 3; ++a) {
        EXPECT_FLOAT_EQ(cube.extent()[a], 8.f);
        EXPECT_FLOAT_EQ(cube.center()[a], flat.center()[a]);
    }
    const VoxelGrid g = makeGridLayout(cube, 64);
    EXPECT_EQ(g.resolution, glm::ivec3(64));
    EXPECT_FLOAT_EQ(g.voxelSize, fit.voxelSize) << "the voxels keep their size";
    // Cubic texels at every level: GL halves each axis to max(1, floor(n / 2^l)).
    for (int l = 0; l < g.levels; ++l) {
        const int x = std::max(1, g.resolution.x >> l);
        EXPECT_EQ(std::max(1, g.resolution.y >> l), x);
        EXPECT_EQ(std::max(1, g.resolution.z >> l), x);
    }
    EXPECT_TRUE(cubeAround(Bounds3{}).empty());
}
