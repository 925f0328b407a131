// AO region fitting and clipmaps against the whole-scene grid (render/voxel_region.h,
// clipmap/clipmap.h): on a 40 m floor with a small table near the camera, spending the same
// --voxel-res on the visible region (or on clipmap levels around the camera) must at least
// halve the AO error against the ray-traced reference; on a fully visible small scene the
// fitted region must not crop anything that matters.
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "support/run_vct.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdlib>

using namespace vct;

namespace {

// A 40 m x 40 m floor, a 1.2 x 0.8 m table (0.77 m high) and a stool next to it, under the sun.
Scene tableScene() {
    Scene s;
    const uint32_t grey = vcttest::addMaterial(s, glm::vec3(0.7f));
    vcttest::addQuad(s, {-20.f, 0.f, -20.f}, {0.f, 0.f, 40.f}, {40.f, 0.f, 0.f}, grey);
    vcttest::addBox(s, {-0.6f, 0.72f, -0.4f}, {0.6f, 0.77f, 0.4f}, grey);
    for (float x : {-0.55f, 0.5f})
        for (float z : {-0.35f, 0.3f}) vcttest::addBox(s, {x, 0.f, z}, {x + 0.05f, 0.72f, z + 0.05f}, grey);
    vcttest::addBox(s, {0.8f, 0.f, 0.2f}, {1.15f, 0.45f, 0.55f}, grey);
    Light sun;  // for the GI request (AO ignores lights)
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
    s.lights.push_back(sun);
    vcttest::finish(s);
    return s;
}

RenderRequest tableRequest() {
    RenderRequest r;
    r.width = r.height = 64;
    r.camera.eye = {0.5f, 1.3f, 1.3f};
    r.camera.target = {0.2f, 0.3f, 0.f};
    r.camera.yfov = 0.8f;
    r.camera.znear = 0.05f;
    r.camera.zfar = 100.f;
    r.radius = 0.5f;
    r.voxelRes = 64;
    r.aovs = {"ao", "depth"};
    return r;
}

Image validMask(const Image& depth) {
    Image m(depth.width, depth.height, 1);
    for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = depth.pixels[i] > 0.f ? 1.f : 0.f;
    return m;
}

struct Scored {
    double rmse = 0, ms = 0, bias = 0;
    nlohmann::json voxels;
};

Scored renderVct(const Scene& scene, RenderRequest r, const Image& reference, const Image& mask,
                 const std::map<std::string, std::string>& params) {
    r.ao = "vct";
    r.reuseSceneData = false;
    for (const auto& [k, v] : params) r.params.set(k, v);
    RenderSession session(scene);
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("region_fit");
    Scored s;
    const ErrorMetrics m = computeErrorMetrics(res.aovs.at("ao"), reference, &mask);
    s.rmse = m.rmse;
    s.bias = m.bias;
    s.ms = res.totalMs;
    s.voxels = res.extra.at("voxels");
    return s;
}

}  // namespace

TEST(RegionFit, FitAndClipmapHalveTheAoErrorOfTheWholeSceneGrid) {
    const Scene scene = tableScene();
    RenderRequest r = tableRequest();
    RenderResult ref = [&] {
        RenderRequest q = r;
        q.ao = "reference";
        q.spp = 512;
        RenderSession session(scene);
        return session.render(q);
    }();
    const Image mask = validMask(ref.aovs.at("depth"));
    const Image& refAo = ref.aovs.at("ao");

    const Scored whole = renderVct(scene, r, refAo, mask, {{"vct.region", "scene"}});
    const Scored fit = renderVct(scene, r, refAo, mask, {{"vct.region", "fit"}});
    const Scored clip = renderVct(scene, r, refAo, mask, {{"vct.region", "scene"}, {"vct.clipmap.levels", "5"}});
    std::printf("table scene, 64 px, --voxel-res 64, R = 0.5, reference 512 spp (%.1f ms)\n", ref.totalMs);
    std::printf("  bias: whole %.4f, fit %.4f, clipmap %.4f\n", whole.bias, fit.bias, clip.bias);
    std::printf("  whole scene  rmse %.4f  %.1f ms  voxel %.3f m\n", whole.rmse, whole.ms,
                whole.voxels["voxel_size"].get<double>());
    std::printf("  region fit   rmse %.4f  %.1f ms  voxel %.3f m\n", fit.rmse, fit.ms,
                fit.voxels["voxel_size"].get<double>());
    std::printf("  clipmap x5   rmse %.4f  %.1f ms  level-0 voxel %.3f m\n", clip.rmse, clip.ms,
                clip.voxels["levels"][0]["voxel_size"].get<double>());

    EXPECT_EQ(whole.voxels["region"]["mode"], "scene");
    EXPECT_EQ(fit.voxels["region"]["mode"], "fit");
    EXPECT_LT(fit.voxels["voxel_size"].get<double>(), 0.5 * whole.voxels["voxel_size"].get<double>());
    EXPECT_EQ(clip.voxels["levels"].size(), 5u);
    // The clipmap halves the error; the fitted region (the far floor is in view, so its voxels
    // are only ~6x finer) cuts it by about a third (measured 0.180 -> 0.124; clipmap 0.066).
    EXPECT_LE(clip.rmse, 0.5 * whole.rmse);
    EXPECT_LE(fit.rmse, 0.75 * whole.rmse);
}

TEST(RegionFit, AutoFitsAoOnlyAndExplainsIt) {
    const Scene scene = tableScene();
    RenderRequest r = tableRequest();
    r.ao = "vct";
    r.aovs = {"ao"};
    RenderSession session(scene);
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("region_auto");
    EXPECT_EQ(res.extra["voxels"]["region"]["mode"], "fit");
    const std::string explain = describePlan(res.plan);
    EXPECT_NE(explain.find("region fit to the visible points"), std::string::npos) << explain;
    // The fitted region lies inside the scene and around what the camera sees.
    const auto& mn = res.extra["voxels"]["region"]["min"];
    const auto& mx = res.extra["voxels"]["region"]["max"];
    EXPECT_GE(mn[0].get<double>(), -20.0);
    EXPECT_LE(mx[0].get<double>(), 20.0);
    EXPECT_LT(mx[0].get<double>() - mn[0].get<double>(), 20.0);

    // GI keeps the whole scene unless told otherwise.
    r.gi = "vct";
    r.aovs = {"beauty"};
    RenderResult gi = session.render(r);
    EXPECT_EQ(gi.extra["voxels"]["region"]["mode"], "scene");
    EXPECT_NE(describePlan(gi.plan).find("region = scene bounds (GI"), std::string::npos);
}

TEST(RegionFit, FullyVisibleSmallSceneMatchesTheWholeSceneGrid) {
    const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    RenderRequest r;
    r.width = r.height = 64;
    r.camera = resolveCamera(scene, CameraRequest{}, 1.f);
    r.ao = "vct";
    r.voxelRes = 32;
    r.radius = 0.5f;
    r.aovs = {"ao"};
    RenderSession session(scene);
    RenderRequest whole = r, fit = r;
    whole.params.set("vct.region", "scene");
    fit.params.set("vct.region", "fit");
    RenderResult a = session.render(whole), b = session.render(fit);
    GlContext::shared().checkErrors("region_cornell");
    const ErrorMetrics m = computeErrorMetrics(b.aovs.at("ao"), a.aovs.at("ao"));
    std::printf("cornell box: fit vs whole scene  mae %.5f  max %.4f\n", m.mae, m.maxAbs);
    EXPECT_EQ(b.extra["voxels"]["region"]["mode"], "fit");
    EXPECT_LT(m.mae, 0.01);
    EXPECT_LT(m.maxAbs, 0.1);
}

// The fit grows the visible points by R plus a footprint's radius at R, and by the start
// offset and one voxel. By default the footprint is the cone set's: 6 cones of 60 deg reach
// R (1 + tan 30 deg), whatever lanes march them. vct.fit-reach=lanes takes the lanes' own:
// split into lanes (vct.lanes=0: (64 / 32)^2 = 4 lanes a cone at 64^3, each a quarter of the
// cone's cap, half-angle acos(1 - (1 - cos 30 deg) / 4)) sampled at half the footprint's level
// (vct.level-bias=-1), they reach R (1 + tan(that) / 2), so the same voxels cover less space.
TEST(RegionFit, TheFitReachesAsFarAsTheFootprintItIsToldTo) {
    const Scene scene = tableScene();
    RenderRequest r = tableRequest();
    r.ao = "vct";
    r.aovs = {"ao"};
    const double pi = 3.14159265358979;
    const double coneHalf = 30.0 * pi / 180.0, laneHalf = std::acos(1.0 - (1.0 - std::cos(coneHalf)) / 4.0);
    struct Variant {
        std::map<std::string, std::string> params;
        double tangent;
    };
    const Variant variants[] = {
        {{}, std::tan(coneHalf)},
        {{{"vct.lanes", "0"}, {"vct.level-bias", "-1"}}, std::tan(coneHalf)},
        {{{"vct.lanes", "0"}, {"vct.level-bias", "-1"}, {"vct.fit-reach", "lanes"}}, 0.5 * std::tan(laneHalf)}};
    double grows[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        RenderRequest v = r;
        for (const auto& [k, val] : variants[i].params) v.params.set(k, val);
        RenderSession session(scene);
        RenderResult res = session.render(v);
        GlContext::shared().checkErrors("region_reach");
        const nlohmann::json& region = res.extra["voxels"]["region"];
        ASSERT_EQ(region["mode"], "fit");
        double extent = 0;
        for (int a = 0; a < 3; ++a)
            extent = std::max(extent, region["visible"]["max"][a].get<double>() - region["visible"]["min"][a].get<double>());
        // Voxel = (visible extent + 2 reach) / (res - 2 - 2 margin) with margin = offset + 1 = 2.5.
        const double reach = r.radius * (1.0 + variants[i].tangent), margin = 2.5;
        const double voxel = (extent + 2.0 * reach) / (double(r.voxelRes) - 2.0 - 2.0 * margin);
        // The floor is 40 m wide: x is not clipped to the scene on either side.
        const double growMax = region["max"][0].get<double>() - region["visible"]["max"][0].get<double>();
        const double growMin = region["visible"]["min"][0].get<double>() - region["min"][0].get<double>();
        std::printf("variant %d: reach %.4f, grown by %.4f / %.4f (expected %.4f)\n", i, reach, growMin, growMax,
                    reach + margin * voxel);
        EXPECT_NEAR(growMax, reach + margin * voxel, 1e-4);
        EXPECT_NEAR(growMin, reach + margin * voxel, 1e-4);
        grows[i] = growMax;
        if (i == 2) EXPECT_NE(describePlan(res.plan).find("the lanes' footprint"), std::string::npos);
    }
    EXPECT_LT(grows[2], 0.8 * grows[1]);
}
