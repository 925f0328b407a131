// Pass planning (src/render/plan.h): what runs and what is left out, for a range of
// requests. Pure logic: no GL context.
#include "ao/screen_space.h"
#include "reference/reference_methods.h"
#include "render/plan.h"
#include "vct/vct_passes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace vct;

namespace {

SceneFeatures litScene() {
    SceneFeatures f;
    f.triangles = 100;
    f.materials = 2;
    f.lights = 1;
    return f;
}

RenderRequest request(const std::string& ao, const std::string& gi, std::vector<std::string> aovs = {"beauty"}) {
    RenderRequest r;
    r.ao = ao;
    r.gi = gi;
    r.aovs = std::move(aovs);
    return r;
}

std::string reasonFor(const RenderPlan& p, PassId pass) {
    for (const auto& s : p.skipped)
        if (s.id == pass) return s.reason;
    return "";
}

}  // namespace

TEST(Plan, ScreenSpaceAoRunsNoVoxelPasses) {
    RenderPlan p = planRender(litScene(), request("gtao", "none"));
    for (PassId pass : {kPassVoxelize, kPassInject, kPassMips, kPassConeAo, kPassConeGi}) {
        EXPECT_FALSE(p.runs(pass)) << pass.name;
        EXPECT_FALSE(reasonFor(p, pass).empty()) << pass.name << " has no reason";
    }
    for (PassId pass : {kPassGBuffer, kPassShadow, kPassDirect, kPassSsao, kPassBlur, kPassComposite})
        EXPECT_TRUE(p.runs(pass)) << pass.name;
}

TEST(Plan, VctAoRunsNoInjection) {
    RenderPlan p = planRender(litScene(), request("vct", "none", {"ao"}));
    EXPECT_TRUE(p.runs(kPassVoxelize));
    EXPECT_TRUE(p.runs(kPassMips));
    EXPECT_TRUE(p.runs(kPassConeAo));
    EXPECT_FALSE(p.runs(kPassInject));
    EXPECT_NE(reasonFor(p, kPassInject).find("opacity"), std::string::npos) << reasonFor(p, kPassInject);
    // AO alone needs no lights: no shadow maps, no direct light, no composite.
    EXPECT_FALSE(p.runs(kPassShadow));
    EXPECT_FALSE(p.runs(kPassDirect));
    EXPECT_FALSE(p.runs(kPassComposite));
}

TEST(Plan, SceneWithoutLightsOrEmissionRunsNoShadowOrInjection) {
    SceneFeatures dark = litScene();
    dark.lights = 0;
    dark.hasEmission = false;
    RenderRequest noSky = request("vct", "vct", {"beauty", "indirect"});
    noSky.sky = 0.f;
    RenderPlan p = planRender(dark, noSky);
    EXPECT_FALSE(p.runs(kPassShadow));
    EXPECT_FALSE(p.runs(kPassDirect));
    EXPECT_FALSE(p.runs(kPassInject));
    EXPECT_NE(reasonFor(p, kPassShadow).find("no punctual lights"), std::string::npos);
    EXPECT_TRUE(p.runs(kPassConeGi));

    // Under a sky the voxels carry its light once it bounces (default vct.bounces = 1) ...
    EXPECT_TRUE(planRender(dark, request("vct", "vct", {"indirect"})).runs(kPassInject));
    // ... unless nothing bounces.
    RenderRequest noBounce = request("vct", "vct", {"indirect"});
    noBounce.params.set("vct.bounces", "0");
    EXPECT_FALSE(planRender(dark, noBounce).runs(kPassInject));

    SceneFeatures emissive = dark;
    emissive.hasEmission = true;
    EXPECT_TRUE(planRender(emissive, request("none", "vct")).runs(kPassInject));
}

TEST(Plan, DepthAloneRunsOnlyTheGBuffer) {
    RenderPlan p = planRender(litScene(), request("gtao", "vct", {"depth"}));
    ASSERT_EQ(p.runNames(), std::vector<std::string>{"gbuffer"});
    EXPECT_EQ(p.skipped.size(), allPassIds().size() - 1);
}

TEST(Plan, GiReplacesAmbientAoInBeauty) {
    // With GI the sky visibility is part of the indirect term: AO is not needed for beauty.
    RenderPlan p = planRender(litScene(), request("vct", "vct", {"beauty"}));
    EXPECT_TRUE(p.runs(kPassConeGi));
    EXPECT_FALSE(p.runs(kPassConeAo));
    RenderPlan both = planRender(litScene(), request("vct", "vct", {"beauty", "ao"}));
    EXPECT_TRUE(both.runs(kPassConeAo));
    // Both cone passes share one voxelization in the plan.
    const std::vector<std::string> names = both.runNames();
    EXPECT_EQ(std::count(names.begin(), names.end(), "voxelize"), 1);
}

TEST(Plan, PathTracedGiTakesOverDirectAndComposite) {
    RenderPlan p = planRender(litScene(), request("none", "reference", {"beauty", "direct"}));
    EXPECT_TRUE(p.runs(kPassReferenceGi));
    EXPECT_FALSE(p.runs(kPassShadow));
    EXPECT_FALSE(p.runs(kPassComposite));
}

TEST(Plan, BlurAndHalfResFollowParams) {
    RenderRequest r = request("hbao", "none", {"ao"});
    r.params.set("blur", "0");
    r.params.set("ao.half-res", "1");
    RenderPlan p = planRender(litScene(), r);
    EXPECT_TRUE(p.runs(kPassSsao));
    EXPECT_FALSE(p.runs(kPassBlur));
    EXPECT_TRUE(p.runs(kPassUpsample));
}

TEST(Plan, NoPruneRunsEveryDeclaredPass) {
    RenderRequest r = request("vct", "none", {"depth"});
    r.prune = false;
    RenderPlan p = planRender(litScene(), r);
    EXPECT_TRUE(p.runs(kPassConeAo));
    EXPECT_TRUE(p.runs(kPassShadow));
}

TEST(Plan, ImpossibleRequestsAreErrors) {
    EXPECT_THROW(planRender(litScene(), request("none", "none", {"ao"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("gtao", "none", {"ao_stderr"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("gtao", "none", {"voxel_opacity"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("none", "none", {"bogus"})), std::invalid_argument);
}

TEST(Plan, ReferenceAlwaysReportsItsNoise) {
    RenderPlan p = planRender(litScene(), request("reference", "none", {"ao"}));
    EXPECT_TRUE(p.runs(kPassReferenceAo));
    EXPECT_FALSE(p.runs(kPassShadow));  // AO alone
}
