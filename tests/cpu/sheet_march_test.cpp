// vct.voxel.edges=sheet at the base level (gpu::cone_sampleSheets, shaders/cone/cone_march_shared.h)
// against closed forms, on the CPU: the shared march through a flat sheet that lies inside its
// voxel. A sample sees the sheet only when its step crosses it, so a march that ends short of
// the sheet stays open where the box a voxel wide closes it, one that crosses it closes, and a
// sheet that covers a share c of every column passes 1 - c at any angle and phase. A lane that
// meets a sheet near R is closed by the share of its directions that meet it before R. A plate's
// rim is seen where it lies in its voxel, a slab's edge read as boxes where it lies along the lane.
// GI's light is that of the sheets a step sees, each weighted by what it sees of it.
#include "cone/cone_march_shared.h"
#include "cone/cone_set.h"
#include "cone/cone_settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vct {
namespace {

// A flat sheet on the plane z = sheetZ (kSheetZ unless set) inside the voxels of its layer, covering
// `share` of every column; empty elsewhere. `plain`: the same voxels without their span (axis
// -1), read as boxes.
constexpr float kSheetZ = 10.8f;
struct SheetVolume {
    float share = 1.f;
    bool plain = false;
    float sheetZ = kSheetZ;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sheet(glm::ivec3 v) const {
        if (v.z != int(std::floor(sheetZ))) return glm::vec4(0.f, 0.f, 0.f, -1.f);
        const float in = sheetZ - std::floor(sheetZ);
        return plain ? glm::vec4(share, 0.f, 0.f, -1.f) : glm::vec4(share, in, in, 2.f);
    }
    uint32_t sheetExtent(glm::ivec3) const { return 0u; }  // none recorded: the whole voxel
    glm::vec3 sheetLight(glm::ivec3) const { return glm::vec3(0.f); }  // AO: no light
    glm::vec4 sample(glm::vec3 p, glm::vec3 d, float lod, float dt, glm::vec2 cap) {
        return gpu::cone_sampleSheets(*this, p, d, lod, dt, cap);
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Opacity a march from `origin` along unit d gathers over maxDist voxels (footprints of one
// voxel, the default step, no early exit).
// With `capTan` > 0, a lane of that half-aperture's tangent (its cap).
float marchAlpha(SheetVolume& volume, glm::vec3 origin, glm::vec3 d, float maxDist, float capTan = 0.f) {
    const gpu::ConeMarch m{0.001f, gpu::CONE_DEFAULT_STEP, 1.f, 0.f, glm::vec3(0.f), 0.f, capTan};
    return gpu::cone_marchVolume(volume, m, origin, d, 1.5f, d.z, maxDist, 0.f).alpha;
}

// The share of the directions of a cone of half-aperture alpha about unit d (uniform in solid
// angle) that meet the plane z = height within distance maxDist, by quadrature over the cone.
double coneShareWithin(glm::dvec3 d, double alpha, double height, double maxDist) {
    const glm::dvec3 e1 = glm::normalize(glm::cross(d, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 e2 = glm::cross(d, e1);
    const int nu = 400, nphi = 720;
    double met = 0.0, all = 0.0;
    for (int i = 0; i < nu; ++i) {
        const double u = alpha * (double(i) + 0.5) / double(nu);
        for (int j = 0; j < nphi; ++j) {
            const double phi = 2.0 * M_PI * (double(j) + 0.5) / double(nphi);
            const glm::dvec3 w = std::cos(u) * d + std::sin(u) * (std::cos(phi) * e1 + std::sin(phi) * e2);
            all += std::sin(u);
            if (w.z > 0.0 && height / w.z <= maxDist) met += std::sin(u);
        }
    }
    return met / all;
}

TEST(SheetMarch, AMarchEndingShortOfTheSheetStaysOpenWhereTheBoxClosesIt) {
    SheetVolume sheet, box;
    box.plain = true;
    for (int k = 0; k < 10; ++k) {
        const glm::vec3 origin(3.37f + 0.11f * float(k), 4.6f, 2.f + 0.05f * float(k));
        const glm::vec3 up(0.f, 0.f, 1.f);
        // Ends 0.3 voxel below the sheet: nothing crosses it.
        const float shortOf = kSheetZ - 0.3f - origin.z;
        EXPECT_LT(marchAlpha(sheet, origin, up, shortOf), 1e-6f) << "start " << origin.z;
        // The same voxel without its span, a box, reaches below the sheet and closes the same march.
        EXPECT_GT(marchAlpha(box, origin, up, shortOf), 0.5f) << "start " << origin.z;
        // Past it, closed (an opaque sample passes the composite's floor, 1e-7 to the power of
        // the step in texels: 3e-4 at the default step).
        EXPECT_GT(marchAlpha(sheet, origin, up, shortOf + 2.f), 0.999f) << "start " << origin.z;
    }
}

TEST(SheetMarch, ASheetCoveringAShareOfEachColumnPassesTheRestAtAnyAngle) {
    for (float share : {1.f, 0.75f, 0.5f, 0.2f}) {
        SheetVolume volume;
        volume.share = share;
        for (float rise : {1.f, 0.8f, 0.5f, 0.2f, 0.05f})
            for (int k = 0; k < 8; ++k) {
                const float phase = 0.13f * float(k);
                const glm::vec3 d = glm::normalize(glm::vec3(std::sqrt(1.f - rise * rise), 0.3f * rise, rise));
                const glm::vec3 origin(20.f + phase, 7.f - phase, 9.f + 0.1f * phase);
                // Far enough to cross the sheet once, in a whole step.
                const float reach = (kSheetZ - origin.z) / d.z + 2.f;
                const float alpha = marchAlpha(volume, origin, d, reach);
                EXPECT_NEAR(alpha, share, share < 1.f ? 2e-4f : 4e-4f)
                    << "share " << share << " rise " << rise << " phase " << phase;
            }
    }
}

// A lane whose ray meets a sheet near the maximum distance R is closed by the share of its
// directions that meet it before R (the cone model's cut), not by 1 before R and 0 past it: a
// flat sheet crossed by lanes of half-aperture 3.7 degrees at 40-72 degrees from its normal, from past the
// lane's cap before R (s = 1.2) to past it beyond R or the end of the zone the march reads.
TEST(SheetMarch, ALaneCrossingASheetNearItsEndIsClosedByTheShareThatMeetsItBeforeR) {
    const float alpha = 3.71f * float(M_PI) / 180.f, maxDist = 50.f;
    double worstCapped = 0.0, worstRay = 0.0;
    for (float theta : {40.f, 60.f, 72.f}) {
        const float th = theta * float(M_PI) / 180.f;
        const glm::vec3 d(std::sin(th), 0.f, std::cos(th));
        for (float s : {-1.2f, -0.7f, -0.3f, -0.05f, 0.05f, 0.3f, 0.7f, 1.2f}) {
            // Past the zone the march reads (cone_capZone) a lane's share is left out.
            if (s < 0.f && -s * std::tan(th) > gpu::CONE_CAP_ZONE) continue;
            // The ray meets the sheet at t_c = R (1 - s tan(alpha) tan(theta)) (not at R itself,
            // where two steps meet and each may count it).
            const float tc = maxDist * (1.f - s * std::tan(alpha) * std::tan(th));
            const glm::vec3 origin(30.f, 30.f, 0.5f);
            SheetVolume sheet;
            sheet.sheetZ = origin.z + tc * d.z;
            const double exact = coneShareWithin(glm::dvec3(d), alpha, double(tc * d.z), maxDist);
            const double capped = marchAlpha(sheet, origin, d, maxDist, std::tan(alpha));
            const double ray = marchAlpha(sheet, origin, d, maxDist);
            EXPECT_NEAR(capped, exact, 0.03) << "theta " << theta << " s " << s;
            worstCapped = std::max(worstCapped, std::abs(capped - exact));
            worstRay = std::max(worstRay, std::abs(ray - exact));
        }
    }
    std::printf("largest |alpha - share|: with the cap %.4f, as a ray %.4f\n", worstCapped, worstRay);
    // Without its cap the lane is a ray there: wrong by most of the share somewhere.
    EXPECT_GT(worstRay, 0.3);
    EXPECT_LT(worstCapped, 0.1 * worstRay);
}

// Only lanes take a cap: the default set's whole cones of 60 degrees march to R as they did (no
// zone about R read at the base level), auto lanes take their own half-aperture.
TEST(SheetMarch, OnlyLanesTakeACap) {
    ConeSettings whole;
    const ConeLanes cones = coneMarchLanes(whole, 128);
    ASSERT_EQ(cones.lanesPerCone, 1);
    EXPECT_EQ(laneCapTangent(cones.lanesPerCone, cones.apertureDeg), 0.f);
    EXPECT_EQ(gpu::cone_capZone(40.f, laneCapTangent(cones.lanesPerCone, cones.apertureDeg)), 0.f);
    ConeSettings lanes;
    lanes.lanes = 0;
    lanes.lanesBase = 16;
    const ConeLanes split = coneMarchLanes(lanes, 128);
    ASSERT_GT(split.lanesPerCone, 1);
    EXPECT_NEAR(laneCapTangent(split.lanesPerCone, split.apertureDeg),
                std::tan(0.5 * double(split.apertureDeg) * M_PI / 180.0), 1e-6);
}

// A plate's rim inside its voxel: a flat sheet at z = 10.5 (voxel layer 10) covering x < kRimX,
// whose rim voxel (x = 10) records its extent across (vox_extentBits; y left unrecorded, the
// whole voxel). `box`: the same voxels without their span (axis -1, opacity 1), a slab's edge
// read as boxes, their surfaces in the voxels' upper 0.4 along z. `extentless`: no extent
// recorded, the whole voxel.
constexpr float kRimX = 10.4f;
struct RimVolume {
    bool box = false;
    bool extentless = false;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sheet(glm::ivec3 v) const {
        if (v.z != 10 || v.x > 10) return glm::vec4(0.f, 0.f, 0.f, -1.f);
        const float share = v.x < 10 ? 1.f : kRimX - 10.f;
        return box ? glm::vec4(1.f, 0.f, 0.f, -1.f) : glm::vec4(share, 0.5f, 0.5f, 2.f);
    }
    uint32_t sheetExtent(glm::ivec3 v) const {
        if (extentless || v.z != 10 || v.x > 10) return 0u;
        const uint32_t across = gpu::vox_extentBits(0.f, v.x < 10 ? 1.f : kRimX - 10.f, 0);
        if (box) return across | gpu::vox_extentBits(0.6f, 1.f, 2);
        return v.x < 10 ? 0u : across | gpu::vox_extentBits(0.5f, 0.5f, 2);
    }
    glm::vec3 sheetLight(glm::ivec3) const { return glm::vec3(0.f); }  // AO: no light
    glm::vec4 sample(glm::vec3 p, glm::vec3 d, float lod, float dt, glm::vec2 cap) {
        return gpu::cone_sampleSheets(*this, p, d, lod, dt, cap);
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Opacity of a march up the z axis from (x, 20.3, 5.13) to height `end`.
float rimAlphaTo(RimVolume& volume, float x, float end) {
    const gpu::ConeMarch m{0.001f, gpu::CONE_DEFAULT_STEP, 1.f, 0.f, glm::vec3(0.f), 0.f, 0.f};
    return gpu::cone_marchVolume(volume, m, glm::vec3(x, 20.3f, 5.13f), glm::vec3(0.f, 0.f, 1.f), 1.5f, 1.f,
                                 end - 5.13f, 0.f)
        .alpha;
}
float rimAlpha(RimVolume& volume, float x) { return rimAlphaTo(volume, x, 15.13f); }

// A sample sees a voxel's surfaces where they lie across it: a lane crossing the plate at x sees
// the share of its box one voxel wide about x that the plate covers, min(max(kRimX - (x - 1/2),
// 0), 1), whichever voxel the rim is in. The tent about the rim voxel's centre saw its share
// spread over the voxel: 0.24 at half a voxel past the rim, 0.76 half a voxel inside it.
TEST(SheetMarch, APlatesRimIsSeenWhereItLiesInItsVoxel) {
    RimVolume plate, tent;
    tent.extentless = true;
    double worstTent = 0.0;
    for (int k = 0; k <= 96; ++k) {
        const float x = 8.f + 0.05f * float(k);
        const float expected = std::clamp(kRimX - (x - 0.5f), 0.f, 1.f);
        EXPECT_NEAR(rimAlpha(plate, x), expected, 1e-3f) << "x " << x;
        worstTent = std::max(worstTent, double(std::abs(rimAlpha(tent, x) - expected)));
    }
    EXPECT_GT(worstTent, 0.2) << "the tent spread the rim's share over its voxel";
}

// Read as boxes (a slab's edge, where its faces of two axes meet), the rim voxel's extent along
// the lane's main axis decides where the lane crosses it: a lane that ends below the surfaces
// in its voxel (here in its upper 0.4) stays open, where the whole voxel closed it; one that
// ends past them is closed. Across the lane the box is the whole voxel (the tent).
TEST(SheetMarch, ABoxIsCrossedWhereItsSurfacesLieAlongTheLane) {
    RimVolume slab, whole;
    slab.box = whole.box = true;
    whole.extentless = true;
    for (float x : {9.6f, 10.2f, 10.45f}) {
        EXPECT_LT(rimAlphaTo(slab, x, 10.5f), 1e-6f) << "x " << x;
        EXPECT_GT(rimAlphaTo(whole, x, 10.5f), 0.3f) << "x " << x << ": the whole voxel closed it";
        EXPECT_NEAR(rimAlphaTo(slab, x, 12.f), rimAlphaTo(whole, x, 12.f), 1e-6f) << "x " << x;
    }
}

// GI over sheets: a sheet at z = 10.8 in the layer z in [10, 11), lit `left` where x < 10 and
// `right` from x = 10, under a dark box layer z in [11, 12) (a non-emitting surface one voxel up).
struct LitSheetVolume {
    glm::vec3 left{1.f, 0.5f, 0.25f}, right{0.f, 2.f, 4.f};
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sheet(glm::ivec3 v) const {
        if (v.z == 10) return glm::vec4(1.f, 0.8f, 0.8f, 2.f);
        if (v.z == 11) return glm::vec4(1.f, 0.f, 0.f, -1.f);
        return glm::vec4(0.f, 0.f, 0.f, -1.f);
    }
    uint32_t sheetExtent(glm::ivec3) const { return 0u; }
    glm::vec3 sheetLight(glm::ivec3 v) const { return v.z != 10 ? glm::vec3(0.f) : v.x < 10 ? left : right; }
};

// The light a step sees is the sheet's own where it crosses only the sheet (the trilinear
// radiance at z = 10.8 would blend in the dark layer above with weight 0.3), and the sheets'
// lights weighted by what it sees of each where the sample's box straddles two.
TEST(SheetMarch, AStepSeesTheLightOfTheSheetsItCrosses) {
    LitSheetVolume v;
    const glm::vec3 up(0.f, 0.f, 1.f);
    auto light = [&](glm::vec3 p) {
        const glm::vec4 s = gpu::cone_sampleSheets(v, p, up, 0.f, 0.2f, glm::vec2(0.f));
        EXPECT_NEAR(s.w, 1.f, 1e-6f) << "the step crosses the opaque sheet";
        return glm::vec3(s) / s.w;
    };
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(light(glm::vec3(5.5f, 5.5f, 10.8f))[i], v.left[i], 1e-5f);
        EXPECT_NEAR(light(glm::vec3(14.5f, 5.5f, 10.75f))[i], v.right[i], 1e-5f);
        EXPECT_NEAR(light(glm::vec3(10.f, 5.5f, 10.85f))[i], 0.5f * (v.left[i] + v.right[i]), 1e-5f);
    }
    // A step short of the sheet sees nothing, and gives no light.
    EXPECT_EQ(gpu::cone_sampleSheets(v, glm::vec3(5.5f, 5.5f, 10.3f), up, 0.f, 0.2f, glm::vec2(0.f)), glm::vec4(0.f));
}

// A floor (sheets across y at y = 0.2 in the layer y in [0, 1)) with a plate 1.3 voxels above it
// (layer 1, across y), and a wall across x at x = 10.5 from the floor up (its foot, voxel column x
// = 10 of layer 0, a box where the two meet).
struct FloorWallVolume {
    glm::vec4 sheet(glm::ivec3 v) const {
        if (v.x == 10 && v.y == 0) return glm::vec4(1.f, 0.f, 0.f, -1.f);
        if (v.x == 10 && v.y > 0) return glm::vec4(1.f, 0.5f, 0.5f, 0.f);
        if (v.y == 0) return glm::vec4(1.f, 0.2f, 0.2f, 1.f);
        if (v.y == 1 && v.x < 6) return glm::vec4(1.f, 0.5f, 0.5f, 1.f);
        return glm::vec4(0.f, 0.f, 0.f, -1.f);
    }
};

// GI over sheets: a pixel's lanes start CONE_SHEET_START voxels up where no other surface is
// within a voxel of that start (under the low plate too, whose sheet lies across the same
// axis), and at the offset beside the wall and its foot.
TEST(SheetMarch, LanesStartHalfAVoxelUpAwayFromOtherSurfaces) {
    FloorWallVolume v;
    const glm::vec3 up(0.f, 1.f, 0.f);
    EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(3.5f, 0.2f, 5.5f), up, 1.5f), gpu::CONE_SHEET_START);
    EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(7.9f, 0.2f, 5.5f), up, 1.5f), gpu::CONE_SHEET_START);
    EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(13.1f, 0.2f, 5.5f), up, 1.5f), gpu::CONE_SHEET_START);
    EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(3.5f, 0.2f, 5.5f), glm::normalize(glm::vec3(0.5f, 1.f, 0.f)), 1.5f),
              gpu::CONE_SHEET_START);
    for (float x : {9.2f, 10.3f, 11.9f})
        EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(x, 0.2f, 5.5f), up, 1.5f), 1.5f) << "x " << x;
    EXPECT_EQ(gpu::cone_sheetStartOffset(v, glm::vec3(3.5f, 0.2f, 5.5f), up, 0.25f), 0.25f) << "never above the offset";
}

}  // namespace
}  // namespace vct
