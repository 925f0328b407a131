// The CPU cone tracer over sparse voxels (src/vdb/sparse_cone.h) against closed forms: an open
// floor is unoccluded, a white furnace (every surface emits Le, sky Le) returns albedo * Le
// whatever the geometry, and a low ceiling closes the hemisphere.
#include "common/tangent_frame.h"
#include "cone/cone_set.h"
#include "core/errors.h"
#include "support/test_scenes.h"
#include "vdb/sparse_cone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

// Lanes take their cone's side of the surface's plane (cone_laneState): the Vogel sets' outer
// cones reach below the plane (16 cones: 2.2% of the set's weight), and a lane there is open
// as that part of its cone is in the cone model, so an open floor stays open with lanes as
// with the cones alone. With lanes closed below the plane, 16 cones x 4 lanes gave AO 0.978 and
// GI 2.2% short of albedo * sky. A shading normal tilted 40 degrees off the geometric one
// puts whole cones below the plane: every lane of those is closed, the closed weight is the
// closed cones' (computed here from the set), and a lane of them that rises above the plane is
// not marched open. Mirrored (vct.below-plane=mirror) the lanes below the plane are marched
// reflected above it, and over the open floor see what the open ones are given: nothing.
TEST(VdbCone, LanesTakeTheirConesSideOfTheSurfacesPlane) {
    const float Le = 1.5f;
    Scene s;
    const glm::vec3 albedo(0.5f);
    uint32_t m = vcttest::addMaterial(s, albedo);
    vcttest::addQuad(s, {-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, m);
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 64, true, Le, params);
    const glm::vec3 ng(0, 1, 0), tilted = glm::normalize(glm::vec3(std::sin(0.7f), std::cos(0.7f), 0.f));
    const glm::vec3 positions[] = {{0, 0, 0}, {2.1f, 0, -1.3f}};
    for (int cones : {16, 32}) {
        // The weight of the cones whose axis the tilted frame puts below the plane.
        double closed = 0.0;
        for (const glm::vec4& c : diffuseConeSet(cones))
            if (glm::dot(gpu::frame_fromZ(tilted) * glm::vec3(c), ng) <= 0.f) closed += c.w;
        ASSERT_GT(closed, 0.05) << "the tilt should close some of the " << cones << " cones";
        for (int lanes : {1, 4, 16})
        for (ConeBelowPlane below : {ConeBelowPlane::Open, ConeBelowPlane::Mirror}) {
            ConeSettings cs = defaults();
            cs.coneCount = cones;
            cs.apertureDeg = defaultConeAperture(cones);
            cs.lanes = lanes;
            cs.belowPlane = below;
            const std::string what = std::to_string(cones) + " cones x " + std::to_string(lanes) + " lanes" +
                                     (below == ConeBelowPlane::Mirror ? ", mirrored" : "");
            std::vector<SparsePoint> up, tilt;
            for (glm::vec3 p : positions) {
                up.push_back({p, ng, ng, albedo, true});
                tilt.push_back({p, tilted, ng, albedo, true});
            }
            for (float a : sparseConeAO(v, up, 2.f, cs)) EXPECT_NEAR(a, 1.f, 1e-5f) << what;
            for (const glm::vec3& gi : sparseConeGI(v, up, Le, cs)) EXPECT_NEAR(gi.x, albedo.x * Le, 1e-4f) << what;
            for (float a : sparseConeAO(v, tilt, 2.f, cs)) EXPECT_NEAR(a, 1.0 - closed, 1e-5) << what << ", tilted";
        }
    }
}

// A closed room (a box's six faces, one voxel thick, the floor its bottom) with R longer than
// its diagonal leaves nothing open: the exact AO is 0 at every floor point, and what VCT reports
// crossed a wall. The mean AO over four floor points, the room voxelized sparse at `res`
// (directional levels), marched by 16 cones of `lanes` lanes at vct.sharpen = `sharpen`.
double closedRoomMeanAo(int res, int lanes, float sharpen) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    vcttest::addBox(s, {-0.3f, 0.f, -0.3f}, {0.3f, 0.4f, 0.3f}, m);
    vcttest::addQuad(s, {-0.4f, 0, -0.4f}, {0, 0, 0.8f}, {0.8f, 0, 0}, m);  // a floor around it: the walls off the grid's faces
    vcttest::finish(s);
    ParamMap params;
    SparseBuildOptions options;
    options.anisotropic = true;
    const SparseVoxelScene v = buildSparseVoxels(s, res, false, 1.f, params, options);
    const std::vector<SparsePoint> pts = floorPoints({{0, 0, 0}, {0.12f, 0, -0.05f}, {-0.2f, 0, 0.2f}, {0.22f, 0, 0.1f}});
    ConeSettings cs;
    cs.coneCount = 16;
    cs.apertureDeg = defaultConeAperture(16);
    cs.lanes = lanes;
    cs.sharpen = sharpen;
    double sum = 0.0;
    for (float a : sparseConeAO(v, pts, 1.f, cs)) sum += a;
    return sum / double(pts.size());
}

// On directional levels filtered linearly a crossing passes the tent's leak (exp(-2) of an
// opaque texel); sharpened along each level's axis (vct.sharpen=4) most of it closes.
TEST(VdbCone, SharpenedLevelsCloseARoomTheTrilinearTentLeaks) {
    const double tent = closedRoomMeanAo(64, 16, 1.f), sharp = closedRoomMeanAo(64, 16, 4.f);
    std::printf("[vdb_cone] closed room, mean AO (exact 0): trilinear %.4f, sharpened %.4f\n", tent, sharp);
    // Measured 0.225 and 0.040 (16 cones x 16 lanes at 64^3, the room 53 voxels wide); what is
    // left falls as the grid refines (docs/convergence.md).
    EXPECT_GT(tent, 0.1) << "the leak the sharpened filter closes";
    EXPECT_LT(sharp, 0.3 * tent);
}

// The same room at 32^3 marched by lanes so narrow (16 cones x 256, 3.1 degrees) that their
// footprints are below a voxel where they meet the walls: those samples read the isotropic base
// level, not the directional ones. Fetched linearly the base is the same tent; sharpened
// (vct.sharpen=4 fetches it once per axis, each sharpened along it, blended as the directional
// axes) the room closes there too.
TEST(VdbCone, NarrowLanesMeetTheWallsInTheBaseLevelWhichSharpeningClosesToo) {
    const double tent = closedRoomMeanAo(32, 256, 1.f), sharp = closedRoomMeanAo(32, 256, 4.f);
    std::printf("[vdb_cone] closed room, narrow lanes, mean AO (exact 0): trilinear %.4f, sharpened %.4f\n", tent,
                sharp);
    // Measured 0.062 and 0.0215; with the base fetched linearly the sharpened march gave 0.060,
    // the directional levels' sharpening alone all but unused. What is left is the room's edges
    // and corners at 32^3 (24 voxels across).
    EXPECT_GT(tent, 0.04) << "the base level's tent";
    EXPECT_LT(sharp, 0.5 * tent);
}

// A ceiling over the floor occludes, more the lower it is (the exact A_R for an infinite ceiling
// at height h is (h / R)^2; VCT, whose footprints blur a one-voxel ceiling into partly
// transparent coarse texels, leaks above it, so only the ordering and bounds are checked here;
// the agreement with the GPU path is tests/gpu/vdb_vs_gl_test.cpp's job).
TEST(VdbCone, LowerCeilingOccludesMore) {
    const float R = 3.f;
    auto aoUnder = [&](float h, float radius) {
        Scene s;
        uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
        vcttest::addQuad(s, {-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, m);
        vcttest::addQuad(s, {-5, h, -5}, {10, 0, 0}, {0, 0, 10}, m);  // ceiling facing down
        vcttest::finish(s);
        s.bounds.expand(glm::vec3(0.f, 2.f, 0.f));  // the same grid for every h
        ParamMap params;
        SparseVoxelScene v = buildSparseVoxels(s, 64, false, 1.f, params);
        return sparseConeAO(v, floorPoints({{0, 0, 0}, {1.3f, 0, 0.7f}}), radius, defaults());
    };
    std::vector<float> low = aoUnder(0.5f, R), high = aoUnder(1.f, R);
    for (size_t i = 0; i < low.size(); ++i) {
        EXPECT_LT(low[i], high[i]);
        EXPECT_LT(high[i], 0.9f);
        EXPECT_GE(low[i], 0.f);
    }
    // A radius well short of the ceiling (1.9 voxels, the ceiling 6 voxels up) sees nothing.
    for (float a : aoUnder(1.f, 0.3f)) EXPECT_NEAR(a, 1.f, 1e-5);
}

// An open-topped box whose inner faces all emit Le (albedo 0, no lights) under a sky of Le:
// whatever the cones see, they gather Le, so GI = albedo * Le, with either cone set. Every
// face looks into the box: radiance leaves surfaces from their fronts only (vox_facingWeight),
// and no point here sees a back, except the floor's own voxels grazed by the first samples of
// low cones (a cone rising along d meets +y faces from below): measured up to 0.7% dark, so
// the tolerance is 1%.
TEST(VdbCone, WhiteFurnace) {
    const float Le = 1.5f;
    Scene g;
    uint32_t m = vcttest::addMaterial(g, glm::vec3(0.f), glm::vec3(Le));
    vcttest::addQuad(g, {-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, m);  // floor, +y
    vcttest::addQuad(g, {-3, 0, -3}, {6, 0, 0}, {0, 2, 0}, m);  // +z
    vcttest::addQuad(g, {-3, 0, 3}, {0, 2, 0}, {6, 0, 0}, m);   // -z
    vcttest::addQuad(g, {-3, 0, -3}, {0, 2, 0}, {0, 0, 6}, m);  // +x
    vcttest::addQuad(g, {3, 0, -3}, {0, 0, 6}, {0, 2, 0}, m);   // -x
    vcttest::finish(g);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(g, 48, true, 1.f, params);
    const glm::vec3 albedo(0.25f, 0.5f, 0.75f);
    auto pts = floorPoints({{0, 0, 0.9f}, {1.2f, 0, 1.2f}, {-2.5f, 0, 2.5f}, {2.6f, 0, -0.3f}}, albedo);
    for (int cones : {6, 16}) {
        ConeSettings cs = defaults();
        cs.coneCount = cones;
        cs.apertureDeg = defaultConeAperture(cones);
        std::vector<glm::vec3> gi = sparseConeGI(v, pts, Le, cs);
        std::vector<glm::vec3> dark = sparseConeGI(v, pts, 0.f, cs);
        std::vector<float> ao = sparseConeAO(v, pts, 1.f, cs);
        bool someOccluded = false;
        for (size_t i = 0; i < pts.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(gi[i][c], albedo[c] * Le, 1e-2f * albedo[c] * Le) << cones << " cones, point " << i;
                EXPECT_LT(dark[i][c], gi[i][c]) << "without sky the open part must be darker";
            }
            someOccluded = someOccluded || ao[i] < 0.9f;
        }
        EXPECT_TRUE(someOccluded) << "the furnace points should see some geometry";
    }
}

// An emissive panel (Le, no lights, no sky) 2.5 voxels above a floor; the floor's cones start
// 1.5 voxels up, one voxel under it. Facing the floor, the panel lights it with nearly its
// whole hemisphere (view factor of a 2 m square at 0.16 m: ~0.97, so GI ~ albedo * Le; the
// cones saturate on the panel and read 0.98 of it). Facing away, the floor sees the panel's
// back, which emits nothing: GI ~ 0. Without the facing rule (vox_facingWeight, at every
// level) the second case gathered 0.48 of the first through the panel's back.
TEST(VdbCone, EmitterSeenFromBehindPassesNoLight) {
    const float Le = 4.f, albedo = 0.5f;
    auto giUnderPanel = [&](bool facingFloor) {
        Scene s;
        const uint32_t floorMat = vcttest::addMaterial(s, glm::vec3(albedo));
        const uint32_t lamp = vcttest::addMaterial(s, glm::vec3(0.f), glm::vec3(Le));
        s.materials[lamp].doubleSided = false;  // emits from its front only (glTF culls the back)
        vcttest::addQuad(s, {-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, floorMat);
        // A 64-voxel grid over the 4 m floor padded by one voxel each side: 4 / 62 m voxels.
        const float voxel = 4.f / 62.f, h = 2.5f * voxel;
        if (facingFloor)
            vcttest::addQuad(s, {-1, h, -1}, {2, 0, 0}, {0, 0, 2}, lamp);  // normal -y
        else
            vcttest::addQuad(s, {-1, h, -1}, {0, 0, 2}, {2, 0, 0}, lamp);  // normal +y
        vcttest::finish(s);
        ParamMap params;
        SparseVoxelScene v = buildSparseVoxels(s, 64, true, 0.f, params);
        EXPECT_NEAR(v.voxelSize, voxel, 1e-3f * voxel) << "the grid layout changed: recompute h";
        ConeSettings cs = defaults();
        std::vector<glm::vec3> gi = sparseConeGI(v, floorPoints({{0, 0, 0}, {0.3f, 0, -0.2f}}, glm::vec3(albedo)), 0.f, cs);
        return std::max(gi[0].x, gi[1].x);
    };
    const float front = giUnderPanel(true), back = giUnderPanel(false);
    std::printf("  floor under the panel: front %.3f back %.3f (albedo * Le = %.3f)\n", front, back, albedo * Le);
    EXPECT_GT(front, 0.7f * albedo * Le);
    EXPECT_LT(back, 0.05f * albedo * Le);
}

TEST(VdbCone, RejectsMissingInputs) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    vcttest::addQuad(s, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0}, m);
    vcttest::finish(s);
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 16, false, 1.f, params);
    auto pts = floorPoints({{0, 0, 0}});
    EXPECT_THROW(sparseConeGI(v, pts, 1.f, defaults()), InternalError);
    EXPECT_THROW(sparseConeAO(v, pts, -1.f, defaults()), InternalError);
    SparseVoxelScene bare = voxelizeSparse(s, 16);  // no levels
    EXPECT_THROW(sparseConeAO(bare, pts, 1.f, defaults()), InternalError);
}

}  // namespace
}  // namespace vct
