// The CPU cone tracer over sparse voxels (src/vdb/sparse_cone.h) against closed forms: an open
// floor is unoccluded, a white furnace (every surface emits Le, sky Le) returns albedo * Le
// whatever the geometry, and a low ceiling closes the hemisphere.
#include "support/test_scenes.h"
#include "vdb/sparse_cone.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vct {
namespace {

std::vector<SparsePoint> floorPoints(const std::vector<glm::vec3>& positions, glm::vec3 albedo = glm::vec3(0.5f)) {
    std::vector<SparsePoint> pts;
    for (glm::vec3 p : positions) pts.push_back({p, {0, 1, 0}, {0, 1, 0}, albedo, true});
    return pts;
}

ConeSettings defaults() {
    ConeSettings s;
    s.anisotropic = false;
    return s;
}

TEST(VdbCone, OpenFloorIsUnoccluded) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    vcttest::addQuad(s, {-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, m);
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 64, false, 1.f, params);
    auto pts = floorPoints({{0, 0, 0}, {2.1f, 0, -1.3f}, {-3.7f, 0, 3.9f}});
    pts.push_back(SparsePoint{});  // sky
    std::vector<float> ao = sparseConeAO(v, pts, 2.f, defaults());
    ASSERT_EQ(ao.size(), 4u);
    for (float a : ao) EXPECT_NEAR(a, 1.f, 1e-5);
}

TEST(VdbCone, LowCeilingClosesTheHemisphere) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    vcttest::addQuad(s, {-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, m);
    vcttest::addQuad(s, {-5, 0.5f, -5}, {10, 0, 0}, {0, 0, 10}, m);  // ceiling facing down
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 64, false, 1.f, params);
    auto pts = floorPoints({{0, 0, 0}, {1.3f, 0, 0.7f}});
    std::vector<float> ao = sparseConeAO(v, pts, 3.f, defaults());
    for (float a : ao) EXPECT_LT(a, 0.1f);
    // A radius shorter than the ceiling's height sees nothing of it.
    std::vector<float> shortR = sparseConeAO(v, pts, 0.15f, defaults());
    for (float a : shortR) EXPECT_NEAR(a, 1.f, 1e-5);
}

// Every surface emits Le (albedo 0, no lights) and the sky is Le: whatever the cones see, they
// gather Le, so GI = albedo * Le exactly (up to float rounding).
TEST(VdbCone, WhiteFurnace) {
    const glm::vec3 Le(0.8f, 1.5f, 2.f);
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.f), Le);
    vcttest::addQuad(s, {-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, m);
    vcttest::addBox(s, {-1, 0, -1}, {1, 1.2f, 0.5f}, m);
    vcttest::addBox(s, {1.5f, 0, 1.f}, {2.f, 2.5f, 1.5f}, m);
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 48, true, 1.f, params);
    const glm::vec3 albedo(0.25f, 0.5f, 0.75f);
    auto pts = floorPoints({{0, 0, 0.9f}, {1.2f, 0, 1.2f}, {-2.5f, 0, 2.5f}, {0.2f, 0, -1.3f}}, albedo);
    for (int cones : {6, 16}) {
        ConeSettings cs = defaults();
        cs.coneCount = cones;
        cs.apertureDeg = defaultConeAperture(cones);
        std::vector<glm::vec3> gi = sparseConeGI(v, pts, 1.f, cs);  // sky 1 != Le: expect a difference
        std::vector<glm::vec3> furnace = sparseConeGI(v, pts, 0.f, cs);
        for (size_t i = 0; i < pts.size(); ++i) {
            (void)gi;
            // Sky = Le in each channel: run once per channel's sky value is not possible with a
            // scalar sky, so use a grey Le check below and here only bound the result.
            for (int c = 0; c < 3; ++c) EXPECT_LE(furnace[i][c], albedo[c] * Le[c] * 1.0001f);
        }
    }
    // Grey furnace: Le = 1.5 everywhere, sky 1.5.
    Scene g;
    uint32_t mg = vcttest::addMaterial(g, glm::vec3(0.f), glm::vec3(1.5f));
    vcttest::addQuad(g, {-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, mg);
    vcttest::addBox(g, {-1, 0, -1}, {1, 1.2f, 0.5f}, mg);
    vcttest::addBox(g, {1.5f, 0, 1.f}, {2.f, 2.5f, 1.5f}, mg);
    vcttest::finish(g);
    SparseVoxelScene vg = buildSparseVoxels(g, 48, true, 1.f, params);
    std::vector<glm::vec3> gi = sparseConeGI(vg, pts, 1.5f, defaults());
    std::vector<float> ao = sparseConeAO(vg, pts, 1.f, defaults());
    bool someOccluded = false;
    for (size_t i = 0; i < pts.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gi[i][c], albedo[c] * 1.5f, 1e-4f * albedo[c] * 1.5f) << i;
        someOccluded = someOccluded || ao[i] < 0.9f;
    }
    EXPECT_TRUE(someOccluded) << "the furnace points should see some geometry";
}

TEST(VdbCone, RejectsMissingInputs) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    vcttest::addQuad(s, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0}, m);
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 16, false, 1.f, params);
    auto pts = floorPoints({{0, 0, 0}});
    EXPECT_THROW(sparseConeGI(v, pts, 1.f, defaults()), std::invalid_argument);
    EXPECT_THROW(sparseConeAO(v, pts, -1.f, defaults()), std::invalid_argument);
    SparseVoxelScene bare = voxelizeSparse(s, 16);  // no levels
    EXPECT_THROW(sparseConeAO(bare, pts, 1.f, defaults()), std::invalid_argument);
}

}  // namespace
}  // namespace vct
