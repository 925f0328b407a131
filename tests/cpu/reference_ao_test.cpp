// Closed-form checks of the ray-traced AO reference (src/reference/reference_ao.h).
// Every expected value below is derived analytically (form factors of a differential
// area on the floor), never produced by the code under test.
#include "reference/reference_ao.h"
#include "reference/camera_rays.h"
#include "reference/embree_scene.h"
#include "reference/scene_shapes.h"
#include "core/errors.h"
#include "core/params.h"
#include "core/view.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vct {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Form factor from a differential area to a parallel, centred square of half-size a at
// height h: four corner rectangles, F_corner = (1/2pi)(2 X/sqrt(1+X^2) atan(X/sqrt(1+X^2))), X = a/h.
double squareFormFactor(double a, double h) {
    double x = a / h, s = std::sqrt(1.0 + x * x);
    return 4.0 / kPi * x / s * std::atan(x / s);
}
// Disc of radius r at height h, centred above the point (Nusselt: projected area / pi).
double discFormFactor(double r, double h) { return r * r / (r * r + h * h); }

Scene floorScene(float halfSize = 100.f) {
    Scene s;
    uint32_t m = addDiffuseMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-halfSize, 0, -halfSize}, {0, 0, 2 * halfSize}, {2 * halfSize, 0, 0}, m);  // normal +y
    return s;
}

std::vector<SurfacePoint> pointsAt(glm::vec3 p, size_t count, glm::vec3 n = {0, 1, 0}) {
    return std::vector<SurfacePoint>(count, SurfacePoint{p, n, n, true});
}

struct MeanStats {
    double mean = 0, reportedStderr = 0, spread = 0;
};
MeanStats meanOf(const ReferenceAO& r) {
    MeanStats m;
    double n = double(r.ao.size());
    for (float a : r.ao) m.mean += a / n;
    double var = 0, se2 = 0;
    for (size_t i = 0; i < r.ao.size(); ++i) {
        var += (r.ao[i] - m.mean) * (r.ao[i] - m.mean) / (n - 1);
        se2 += double(r.standardError[i]) * r.standardError[i];
    }
    m.reportedStderr = std::sqrt(se2) / n;  // of the mean over points
    m.spread = std::sqrt(var);               // of a single point's estimate, measured
    return m;
}

ReferenceSettings quiet(float radius, int spp) {
    ReferenceSettings s;
    s.radius = radius;
    s.spp = spp;
    s.progress = false;
    return s;
}

TEST(ReferenceAO, OpenPlaneIsExactlyOne) {
    Scene s = floorScene(1e4f);
    std::vector<SurfacePoint> pts;
    for (int i = 0; i < 64; ++i)  // centre and scattered points, including big coordinates
        pts.push_back({{float(i % 8) * 37.3f - 130.f, 0.f, float(i / 8) * 411.1f - 1500.f}, {0, 1, 0}, {0, 1, 0}, true});
    ReferenceAO r = referenceAO(s, pts, quiet(1.f, 256));
    for (size_t i = 0; i < pts.size(); ++i) {
        EXPECT_EQ(r.ao[i], 1.f) << "point " << i;
        EXPECT_EQ(r.standardError[i], 0.f);
    }
    EXPECT_EQ(r.sppUsed, 256);
    EXPECT_GT(r.raysTraced, 0u);
}

TEST(ReferenceAO, SettingsFromParams) {
    ParamMap params;
    params.set("reference.spp=32");
    params.set("reference.ray-mode=packet16");
    params.set("reference.replicates=1");
    ReferenceSettings s = referenceSettingsFromParams(params);
    EXPECT_EQ(s.spp, 32);
    EXPECT_EQ(s.rayMode, RayMode::Packet16);
    EXPECT_EQ(s.replicates, 1);
    EXPECT_EQ(s.bounces, 4);  // untouched default
    ParamMap bad;
    bad.set("reference.spp=0");
    EXPECT_THROW(referenceSettingsFromParams(bad), UsageError);
}

TEST(ReferenceAO, InvalidPointsAreSky) {
    Scene s = floorScene();
    std::vector<SurfacePoint> pts = pointsAt({0, 0, 0}, 3);
    pts[1].valid = false;
    pts[1].position = glm::vec3(std::nanf(""));  // ignored when invalid
    ReferenceAO r = referenceAO(s, pts, quiet(1.f, 16));
    EXPECT_EQ(r.ao[1], 1.f);
    EXPECT_EQ(r.standardError[1], 0.f);
    pts[0].position.x = std::nanf("");
    EXPECT_THROW(referenceAO(s, pts, quiet(1.f, 16)), InternalError);
    ReferenceSettings bad = quiet(-1.f, 16);
    EXPECT_THROW(referenceAO(s, pts, bad), InternalError);
}

// Floor point under a centred square occluder (half-size a, height h).
Scene squareOccluderScene(float a, float h) {
    Scene s = floorScene();
    uint32_t m = addDiffuseMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-a, h, -a}, {2 * a, 0, 0}, {0, 0, 2 * a}, m);  // faces down: back faces must occlude too
    return s;
}

void expectClose(const ReferenceAO& r, double expected, const char* what) {
    MeanStats m = meanOf(r);
    std::printf("[ %s ] expected %.5f measured %.5f (reported stderr of mean %.5f, %d spp, %zu points)\n", what,
                expected, m.mean, m.reportedStderr, r.sppUsed, r.ao.size());
    EXPECT_NEAR(m.mean, expected, 3.0 * m.reportedStderr + 2e-3) << what;
}

TEST(ReferenceAO, SquareOccluderBeyondRadius) {
    const float a = 0.5f, h = 1.f;
    Scene s = squareOccluderScene(a, h);
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 256), quiet(10.f, 256));
    expectClose(r, 1.0 - squareFormFactor(a, h), "square, R beyond");
}

TEST(ReferenceAO, SquareOccluderCutByRadius) {
    // R cuts the square inside its inscribed circle (r_c = sqrt(R^2 - h^2) < a): the part
    // of the occluder within R is a disc of radius r_c.
    const float a = 0.5f, h = 0.5f, R = 0.6f;
    Scene s = squareOccluderScene(a, h);
    double rc = std::sqrt(double(R) * R - double(h) * h);
    ASSERT_LT(rc, a);
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 256), quiet(R, 256));
    expectClose(r, 1.0 - discFormFactor(rc, h), "square, R cuts");
}

TEST(ReferenceAO, DiscOccluderCutByRadius) {
    const float radius = 1.f, h = 0.5f, R = 0.8f;
    Scene s = floorScene();
    addDisc(s, {0, h, 0}, {0, 1, 0}, radius, 64, addDiffuseMaterial(s, glm::vec3(0.5f)));
    double rc = std::sqrt(double(R) * R - double(h) * h);
    ASSERT_LT(rc, radius * std::cos(kPi / 64));  // the cut lies inside the 64-gon
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 256), quiet(R, 256));
    expectClose(r, 1.0 - discFormFactor(rc, h), "disc, R cuts");
}

// Point on the floor at distance d from an infinite vertical wall: a cosine-weighted
// direction is uniform on the projected unit disc, and reaches the wall within R iff its
// disc coordinate towards the wall exceeds c = d / R: A = 1 - (acos c - c sqrt(1 - c^2)) / pi.
double wallAO(double d, double R) {
    double c = d / R;
    return 1.0 - (std::acos(c) - c * std::sqrt(1.0 - c * c)) / kPi;
}

Scene wallScene(float d) {
    Scene s = floorScene();
    addQuad(s, {d, -1.f, -50.f}, {0, 0, 100.f}, {0, 60.f, 0}, addDiffuseMaterial(s, glm::vec3(0.5f)));
    return s;
}

TEST(ReferenceAO, WallAtDistance) {
    Scene s = wallScene(0.1f);
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 256), quiet(1.f, 256));
    expectClose(r, wallAO(0.1, 1.0), "wall d/R = 0.1");
}

TEST(ReferenceAO, WallAtBaseTendsToHalf) {
    Scene s = wallScene(1e-3f);
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 256), quiet(10.f, 256));
    expectClose(r, wallAO(1e-3, 10.0), "wall d/R = 1e-4 (-> 0.5)");
    EXPECT_NEAR(wallAO(1e-3, 10.0), 0.5, 1e-4);
}

TEST(ReferenceAO, ScaleInvariance) {
    const float radius = 1.f, h = 0.5f, R = 0.8f;
    auto run = [&](float scale) {
        Scene s = floorScene();
        addDisc(s, {0, h, 0}, {0, 1, 0}, radius, 64, addDiffuseMaterial(s, glm::vec3(0.5f)));
        addQuad(s, {0.3f, -0.5f, -5.f}, {0, 0, 10.f}, {0, 3.f, 0}, addDiffuseMaterial(s, glm::vec3(0.5f)));
        scaleScene(s, scale);
        std::vector<SurfacePoint> pts;
        for (int i = 0; i < 64; ++i)
            pts.push_back({glm::vec3(-0.2f + 0.007f * i, 0.f, 0.1f) * scale, {0, 1, 0}, {0, 1, 0}, true});
        return referenceAO(s, pts, quiet(R * scale, 128));
    };
    ReferenceAO base = run(1.f);
    for (float scale : {1e-4f, 1e4f, 1e5f}) {
        ReferenceAO r = run(scale);
        MeanStats a = meanOf(base), b = meanOf(r);
        std::printf("[ scale %g ] mean A %.5f vs %.5f at scale 1\n", scale, b.mean, a.mean);
        EXPECT_NEAR(b.mean, a.mean, 3.0 * a.reportedStderr + 1e-3) << "scale " << scale;
        int differing = 0;
        for (size_t i = 0; i < r.ao.size(); ++i) differing += std::abs(r.ao[i] - base.ao[i]) > 3.f / 128.f;
        EXPECT_LE(differing, 2) << "scale " << scale;  // same samples: only grazing rays may flip
    }
}

TEST(ReferenceAO, DeterministicAcrossThreadCounts) {
    Scene s = squareOccluderScene(0.5f, 0.5f);
    std::vector<SurfacePoint> pts;
    for (int i = 0; i < 500; ++i) pts.push_back({{0.002f * i - 0.5f, 0.f, 0.f}, {0, 1, 0}, {0, 1, 0}, true});
    ReferenceSettings set = quiet(1.f, 32);
    set.seed = 7;
    ReferenceAO one, two, other;
    tbb::task_arena(1).execute([&] { one = referenceAO(s, pts, set); });
    tbb::task_arena(2).execute([&] { two = referenceAO(s, pts, set); });
    EXPECT_EQ(one.ao, two.ao);
    EXPECT_EQ(one.standardError, two.standardError);
    set.seed = 8;
    other = referenceAO(s, pts, set);
    EXPECT_NE(one.ao, other.ao);  // the seed matters

    Camera cam;
    cam.eye = {0.3f, 2.f, 1.5f};
    cam.target = {0, 0, 0};
    View view = makeView(cam, 48, 32);
    ReferenceAO img1, img2;
    tbb::task_arena(1).execute([&] { img1 = referenceAOPixelArea(s, view, set); });
    tbb::task_arena(2).execute([&] { img2 = referenceAOPixelArea(s, view, set); });
    EXPECT_EQ(img1.ao, img2.ao);
}

// The reported per-point error bar against the measured spread of many independent
// estimates of the same integral (each point has its own scramble).
TEST(ReferenceAO, StandardErrorIsHonest) {
    const float radius = 1.f, h = 0.5f, R = 0.8f;
    const double expected = 1.0 - discFormFactor(std::sqrt(R * R - h * h), h);
    Scene s = floorScene();
    addDisc(s, {0, h, 0}, {0, 1, 0}, radius, 64, addDiffuseMaterial(s, glm::vec3(0.5f)));
    for (int replicates : {4, 1}) {
        for (int spp : {16, 64, 256}) {
            ReferenceSettings set = quiet(R, spp);
            set.replicates = replicates;
            ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 1000), set);
            MeanStats m = meanOf(r);
            double rms = 0;  // root mean square of the reported error bars
            for (float e : r.standardError) rms += double(e) * e / 1000.0;
            rms = std::sqrt(rms);
            double ratio = m.spread / rms;
            std::printf("[ stderr %d replicates, %d spp ] measured spread %.5f, reported rms %.5f, ratio %.3f\n",
                        replicates, spp, m.spread, rms, ratio);
            if (replicates > 1) {
                EXPECT_NEAR(ratio, 1.0, 0.2) << spp << " spp";  // honest
            } else {
                EXPECT_LT(ratio, 1.1) << spp << " spp";  // i.i.d. bound: conservative for Sobol
                EXPECT_GT(ratio, 0.1) << spp << " spp";
            }
            EXPECT_NEAR(m.mean, expected, 3.0 * m.spread / std::sqrt(1000.0) + 1e-3);
        }
    }
}

TEST(ReferenceAO, TargetStderrStopsEarly) {
    Scene s = squareOccluderScene(0.5f, 0.5f);
    ReferenceSettings set = quiet(1.f, 1024);
    set.targetStderr = 0.01f;
    ReferenceAO r = referenceAO(s, pointsAt({0, 0, 0}, 100), set);
    EXPECT_LT(r.sppUsed, 1024);
    EXPECT_GE(r.sppUsed, set.minSpp);
    EXPECT_LT(r.meanStderr, 0.01);
}

TEST(ReferenceAO, PixelAreaOpenPlaneAndSky) {
    Scene s = floorScene(1e3f);
    Camera cam;
    cam.eye = {0, 3, 0.01f};
    cam.target = {0, 0, 0};
    View down = makeView(cam, 32, 32);
    ReferenceAO r = referenceAOPixelArea(s, down, quiet(1.f, 16));
    ASSERT_EQ(r.ao.size(), 32u * 32u);
    for (float a : r.ao) EXPECT_EQ(a, 1.f);
    EXPECT_GT(r.primaryRays, 0u);

    cam.eye = {0, 1, 0};
    cam.target = {0, 5, 0.1f};  // looking up: sky everywhere
    ReferenceAO sky = referenceAOPixelArea(s, makeView(cam, 16, 16), quiet(1.f, 16));
    for (size_t i = 0; i < sky.ao.size(); ++i) {
        EXPECT_EQ(sky.ao[i], 1.f);
        EXPECT_EQ(sky.standardError[i], 0.f);
    }
}

// Pixel-centre points from Embree and the pixel-area image agree with the closed form at
// the image centre, looking straight down through the occluder-free gap.
TEST(ReferenceAO, PixelCentrePointsMatchClosedForm) {
    const float d = 0.1f, R = 1.f;
    Scene s = wallScene(d);
    Camera cam;
    cam.eye = {0, 0.5f, 0};
    cam.target = {0, 0, 0};
    cam.up = {0, 0, -1};
    cam.yfov = 0.002f;  // every pixel sees (almost exactly) the origin
    View view = makeView(cam, 16, 16);
    EmbreeScene es(s);
    std::vector<SurfacePoint> pts = surfacePointsAtPixelCentres(es, view);
    for (const SurfacePoint& p : pts) {
        ASSERT_TRUE(p.valid);
        EXPECT_NEAR(p.position.y, 0.f, 1e-6f);
        EXPECT_NEAR(p.normal.y, 1.f, 1e-6f);
    }
    ReferenceAO centres = referenceAO(es, pts, quiet(R, 64));
    expectClose(centres, wallAO(d, R), "pixel centres, wall");
    ReferenceAO area = referenceAOPixelArea(es, view, quiet(R, 64));
    expectClose(area, wallAO(d, R), "pixel area, wall");
}

// The pixel-area reference traces each pixel's primary rays as one coherent stream: every ray
// must get the hit a single rtcIntersect1 gives it (same triangle, distance and barycentrics),
// including rays that miss.
TEST(ReferenceAO, CoherentPrimaryStreamsHitWhatSingleRaysHit) {
    Scene s = squareOccluderScene(0.5f, 0.4f);
    EmbreeScene embree(s);
    Camera cam;
    cam.eye = {0.3f, 0.6f, 1.2f};
    cam.target = {0.f, 0.3f, 0.f};  // the occluder, the floor and the sky above the horizon
    const View view = makeView(cam, 24, 24);
    size_t hits = 0, misses = 0;
    for (int y = 0; y < view.height; y += 3)
        for (int x = 0; x < view.width; x += 3) {
            RTCRayHit stream[16];
            for (int j = 0; j < 16; ++j) {
                const CameraRay cr = cameraRay(view, float(x) + float(j % 4) / 4.f, float(y) + float(j / 4) / 4.f);
                stream[j] = rayHit(cr.origin, cr.direction, cr.tnear, 1e30f);
            }
            RTCRayHit expected[16];
            std::copy(stream, stream + 16, expected);
            embree.intersectCoherent(stream, 16);
            for (int j = 0; j < 16; ++j) {
                const RTCRayHit& e = expected[j];
                uint32_t tri = 0;
                float u = 0.f, v = 0.f, t = 0.f;
                const bool hit = embree.intersect(glm::vec3(e.ray.org_x, e.ray.org_y, e.ray.org_z),
                                                  glm::vec3(e.ray.dir_x, e.ray.dir_y, e.ray.dir_z), e.ray.tnear,
                                                  e.ray.tfar, &tri, &u, &v, &t);
                ASSERT_EQ(hit, stream[j].hit.geomID != RTC_INVALID_GEOMETRY_ID) << x << "," << y << " ray " << j;
                if (!hit) {
                    ++misses;
                    continue;
                }
                ++hits;
                EXPECT_EQ(stream[j].hit.primID, tri);
                EXPECT_NEAR(stream[j].ray.tfar, t, 1e-5f * t);
                EXPECT_NEAR(stream[j].hit.u, u, 1e-4f);
                EXPECT_NEAR(stream[j].hit.v, v, 1e-4f);
            }
        }
    EXPECT_GT(hits, 100u);
    EXPECT_GT(misses, 0u) << "the rays above the horizon should miss";
}

}  // namespace
}  // namespace vct
