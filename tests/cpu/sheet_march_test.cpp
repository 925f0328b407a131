// vct.voxel.edges=sheet at the base level (gpu::cone_sampleSheets, shaders/cone/cone_march_shared.h)
// against closed forms, on the CPU: the shared march through a flat sheet that lies inside its
// voxel. A sample sees the sheet only when its step crosses it, so a march that ends short of
// the sheet stays open where the box a voxel wide closes it, one that crosses it closes, and a
// sheet that covers a share c of every column passes 1 - c at any angle and phase.
#include "cone/cone_march_shared.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vct {
namespace {

// A flat sheet on the plane z = kSheetZ inside the voxels of layer floor(kSheetZ), covering
// `share` of every column; empty elsewhere. `plain`: the same voxels without their span (axis
// -1), as the box filter reads them.
constexpr float kSheetZ = 10.8f;
struct SheetVolume {
    float share = 1.f;
    bool plain = false;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    glm::vec4 sheet(glm::ivec3 v) const {
        if (v.z != int(std::floor(kSheetZ))) return glm::vec4(0.f, 0.f, 0.f, -1.f);
        const float in = kSheetZ - std::floor(kSheetZ);
        return plain ? glm::vec4(share, 0.f, 0.f, -1.f) : glm::vec4(share, in, in, 2.f);
    }
    glm::vec4 sample(glm::vec3 p, glm::vec3 d, float lod, float dt) {
        return glm::vec4(0.f, 0.f, 0.f, gpu::cone_sampleSheets(*this, p, d, dt, std::exp2(std::max(lod, 0.f)), 4.f));
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Opacity a march from `origin` along unit d gathers over maxDist voxels (footprints of one
// voxel, the default step, no early exit).
float marchAlpha(SheetVolume& volume, glm::vec3 origin, glm::vec3 d, float maxDist) {
    const gpu::ConeMarch m{0.001f, gpu::CONE_DEFAULT_STEP, 1.f, 0.f, glm::vec3(0.f), 0.f};
    return gpu::cone_marchVolume(volume, m, origin, d, 1.5f, d.z, maxDist, 0.f).alpha;
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
        // The sharpened box of the sheet's voxel reaches below it and closes the same march.
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

}  // namespace
}  // namespace vct
