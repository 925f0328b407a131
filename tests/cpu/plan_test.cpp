// Pass planning (src/render/plan.h): what runs and what is left out, for the requests the
// pass-planning issue names. Pure logic: no GL context.
#include "render/plan.h"

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

std::string reasonFor(const RenderPlan& p, const std::string& pass) {
    for (const auto& s : p.skipped)
        if (s.name == pass) return s.reason;
    return "";
}

}  // namespace

TEST(Plan, ScreenSpaceAoRunsNoVoxelPasses) {
    RenderPlan p = planRender(litScene(), request("gtao", "none"));
    for (const char* pass : {"voxelize", "inject", "mips", "cone_ao", "cone_gi"}) {
        EXPECT_FALSE(p.runs(pass)) << pass;
        EXPECT_FALSE(reasonFor(p, pass).empty()) << pass << " has no reason";
    }
    for (const char* pass : {"gbuffer", "shadow", "direct", "ssao", "blur", "composite"}) EXPECT_TRUE(p.runs(pass)) << pass;
}

TEST(Plan, VctAoRunsNoInjection) {
    RenderPlan p = planRender(litScene(), request("vct", "none", {"ao"}));
    EXPECT_TRUE(p.runs("voxelize"));
    EXPECT_TRUE(p.runs("mips"));
    EXPECT_TRUE(p.runs("cone_ao"));
    EXPECT_FALSE(p.runs("inject"));
    EXPECT_NE(reasonFor(p, "inject").find("opacity"), std::string::npos) << reasonFor(p, "inject");
    // AO alone needs no lights: no shadow maps, no direct light, no composite.
    EXPECT_FALSE(p.runs("shadow"));
    EXPECT_FALSE(p.runs("direct"));
    EXPECT_FALSE(p.runs("composite"));
}

TEST(Plan, SceneWithoutLightsOrEmissionRunsNoShadowOrInjection) {
    SceneFeatures dark = litScene();
    dark.lights = 0;
    dark.hasEmission = false;
    RenderRequest noSky = request("vct", "vct", {"beauty", "indirect"});
    noSky.sky = 0.f;
    RenderPlan p = planRender(dark, noSky);
    EXPECT_FALSE(p.runs("shadow"));
    EXPECT_FALSE(p.runs("direct"));
    EXPECT_FALSE(p.runs("inject"));
    EXPECT_NE(reasonFor(p, "shadow").find("no punctual lights"), std::string::npos);
    EXPECT_TRUE(p.runs("cone_gi"));

    // Under a sky the voxels carry its light once it bounces (default vct.bounces = 1) ...
    EXPECT_TRUE(planRender(dark, request("vct", "vct", {"indirect"})).runs("inject"));
    // ... unless nothing bounces.
    RenderRequest noBounce = request("vct", "vct", {"indirect"});
    noBounce.params.set("vct.bounces", "0");
    EXPECT_FALSE(planRender(dark, noBounce).runs("inject"));

    SceneFeatures emissive = dark;
    emissive.hasEmission = true;
    EXPECT_TRUE(planRender(emissive, request("none", "vct")).runs("inject"));
}

TEST(Plan, DepthAloneRunsOnlyTheGBuffer) {
    RenderPlan p = planRender(litScene(), request("gtao", "vct", {"depth"}));
    ASSERT_EQ(p.runNames(), std::vector<std::string>{"gbuffer"});
    EXPECT_EQ(p.skipped.size(), allPassNames().size() - 1);
}

TEST(Plan, GiReplacesAmbientAoInBeauty) {
    // With GI the sky visibility is part of the indirect term: AO is not needed for beauty.
    RenderPlan p = planRender(litScene(), request("vct", "vct", {"beauty"}));
    EXPECT_TRUE(p.runs("cone_gi"));
    EXPECT_FALSE(p.runs("cone_ao"));
    RenderPlan both = planRender(litScene(), request("vct", "vct", {"beauty", "ao"}));
    EXPECT_TRUE(both.runs("cone_ao"));
    // Both cone passes share one voxelization in the plan.
    const std::vector<std::string> names = both.runNames();
    EXPECT_EQ(std::count(names.begin(), names.end(), "voxelize"), 1);
}

TEST(Plan, PathTracedGiTakesOverDirectAndComposite) {
    RenderPlan p = planRender(litScene(), request("none", "reference", {"beauty", "direct"}));
    EXPECT_TRUE(p.runs("reference_gi"));
    EXPECT_FALSE(p.runs("shadow"));
    EXPECT_FALSE(p.runs("composite"));
}

TEST(Plan, BlurAndHalfResFollowParams) {
    RenderRequest r = request("hbao", "none", {"ao"});
    r.params.set("blur", "0");
    r.params.set("ao.half-res", "1");
    RenderPlan p = planRender(litScene(), r);
    EXPECT_TRUE(p.runs("ssao"));
    EXPECT_FALSE(p.runs("blur"));
    EXPECT_TRUE(p.runs("upsample"));
}

TEST(Plan, NoPruneRunsEveryDeclaredPass) {
    RenderRequest r = request("vct", "none", {"depth"});
    r.prune = false;
    RenderPlan p = planRender(litScene(), r);
    EXPECT_TRUE(p.runs("cone_ao"));
    EXPECT_TRUE(p.runs("shadow"));
}

TEST(Plan, ImpossibleRequestsAreErrors) {
    EXPECT_THROW(planRender(litScene(), request("none", "none", {"ao"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("gtao", "none", {"ao_stderr"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("gtao", "none", {"voxel_opacity"})), std::invalid_argument);
    EXPECT_THROW(planRender(litScene(), request("none", "none", {"bogus"})), std::invalid_argument);
}

TEST(Plan, ReferenceAlwaysReportsItsNoise) {
    RenderPlan p = planRender(litScene(), request("reference", "none", {"ao"}));
    EXPECT_TRUE(p.runs("reference_ao"));
    EXPECT_FALSE(p.runs("shadow"));  // AO alone
}
