// Optical-depth levels (shaders/voxelize/opacity_depth.h) against closed forms, on the CPU:
// the encoding round-trips, and the shared march (cone_march_shared.h) through a one-texel
// sheet filtered linearly passes exactly the sheet's transmittance when the texels hold depth,
// at every phase of the samples against the texels, where filtering opacity leaks.
#include "cone/cone_march_shared.h"
#include "cone/cone_settings.h"
#include "core/errors.h"
#include "voxelize/opacity_depth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vct {
namespace {

// Texels along x (centres at i + 0.5) holding opacity `alpha[i]`, filtered linearly between
// centres as a GL texture filters them, in opacity or (depth) in optical depth, one level, no
// border. What the march composites is opacity either way.
struct TexelRow {
    std::vector<float> alpha;
    bool depth = false;
    float lod(float, glm::vec3) const { return 0.f; }
    bool leaving(glm::vec3, glm::vec3, float) const { return false; }
    float texel(int i, bool asDepth) const {
        const float a = (i >= 0 && i < int(alpha.size())) ? alpha[size_t(i)] : 0.f;
        return asDepth ? gpu::vox_depthFromAlpha(glm::vec4(0.f, 0.f, 0.f, a)).w : a;
    }
    glm::vec4 sample(glm::vec3 p, glm::vec3, float, float, glm::vec2) const {
        const float x = p.x - 0.5f;
        const int i = int(std::floor(x));
        const float f = x - float(i);
        const float v = (1.f - f) * texel(i, depth) + f * texel(i + 1, depth);
        return depth ? gpu::vox_alphaFromDepth(glm::vec4(0.f, 0.f, 0.f, v)) : glm::vec4(0.f, 0.f, 0.f, v);
    }
    float facing(glm::vec3, glm::vec3, float, glm::vec4) const { return 1.f; }
};

// Transmittance of a march along +x from x0 over 20 voxels (steps of half a voxel: beta 0.5,
// footprint one voxel, the default cone step), no early exit.
float transmittance(const TexelRow& row, float x0) {
    const gpu::ConeMarch m{0.01f, 0.5f, 1.f, 0.f, glm::vec3(0.f), 0.f, 0.f};
    const gpu::ConeResult r = gpu::cone_marchVolume(row, m, glm::vec3(x0, 0.f, 0.f), glm::vec3(1.f, 0.f, 0.f), 1.5f,
                                                    0.f, 20.f, 0.f);
    return 1.f - r.alpha;
}

TEST(OpacityDepth, EncodingRoundTrips) {
    for (float a : {0.f, 1e-4f, 0.01f, 0.3f, 0.5f, 0.9f, 0.99f}) {
        const glm::vec4 s(0.2f * a, 0.5f * a, a, a);  // premultiplied radiance (0.2, 0.5, 1)
        const glm::vec4 d = gpu::vox_depthFromAlpha(s);
        EXPECT_NEAR(d.w, -std::log2(1.f - a), 1e-5f) << "alpha " << a;
        const glm::vec4 back = gpu::vox_alphaFromDepth(d);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(back[k], s[k], 1e-5f) << "alpha " << a << " channel " << k;
        // Radiance is carried premultiplied by depth: the ratio to the channel is the colour.
        if (a > 0.f) {
            EXPECT_NEAR(d.z / d.w, 1.f, 1e-5f);
        }
    }
    // Opaque caps at VOX_DEPTH_MAX: crossing one opaque texel passes 2^-VOX_DEPTH_MAX.
    EXPECT_EQ(gpu::vox_depthFromAlpha(glm::vec4(1.f)).w, gpu::VOX_DEPTH_MAX);
    // The base level's 0 / 1 voxels: filtered opacity f is depth VOX_DEPTH_MAX * f.
    EXPECT_NEAR(gpu::vox_depthFromCoverage(glm::vec4(0.f, 0.f, 0.f, 0.25f)).w, 0.25f * gpu::VOX_DEPTH_MAX, 1e-6f);
}

TEST(OpacityDepth, AMarchThroughAOneTexelSheetPassesItsTransmittanceAtEveryPhase) {
    for (float a : {1.f, 0.75f, 0.5f, 0.2f}) {
        TexelRow alphaRow{std::vector<float>(12, 0.f), false};
        alphaRow.alpha[6] = a;
        TexelRow depthRow = alphaRow;
        depthRow.depth = true;
        const float exact = a >= 1.f ? std::exp2(-gpu::VOX_DEPTH_MAX) : 1.f - a;
        for (float x0 : {0.f, 0.1f, 0.25f, 0.37f, 0.5f}) {
            // Depth's tent integrates to the texel's own depth whatever the samples' phase.
            EXPECT_NEAR(transmittance(depthRow, x0), exact, 2e-4f) << "alpha " << a << " start " << x0;
        }
        if (a >= 1.f) {
            // Opacity's tent: -log(1 - alpha(x)) integrates to 2 e-folds for an opaque texel,
            // so the sheet passes about exp(-2) of the light (more between sample phases).
            for (float x0 : {0.1f, 0.37f}) EXPECT_GT(transmittance(alphaRow, x0), 0.1f) << "start " << x0;
        }
    }
}

TEST(OpacityDepth, TexelsInSeriesMultiplyTheirTransmittances) {
    TexelRow row{std::vector<float>(14, 0.f), true};
    row.alpha[5] = 0.5f;
    row.alpha[6] = 0.3f;
    row.alpha[9] = 0.6f;
    for (float x0 : {0.f, 0.2f, 0.45f})
        EXPECT_NEAR(transmittance(row, x0), 0.5f * 0.7f * 0.4f, 2e-4f) << "start " << x0;
}

// vct.opacity reads alpha (the default) or depth; depth lives in the directional levels, so an
// isotropic march refuses it with the keys named.
TEST(OpacityDepth, TheParameterNeedsTheDirectionalLevels) {
    EXPECT_EQ(readConeSettings(ParamMap()).opacity, ConeOpacity::Alpha);
    ParamMap depth;
    depth.set("vct.opacity", "depth");
    EXPECT_EQ(readConeSettings(depth).opacity, ConeOpacity::Depth);
    depth.set("vct.aniso", "0");
    try {
        readConeSettings(depth);
        FAIL() << "vct.opacity=depth with vct.aniso=0 was accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("vct.opacity=depth"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("vct.aniso=1"), std::string::npos) << e.what();
    }
    ParamMap bad;
    bad.set("vct.opacity", "optical");
    EXPECT_THROW(readConeSettings(bad), UsageError);
}

}  // namespace
}  // namespace vct
