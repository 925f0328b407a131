// Cold and per-frame cost (core/timing.h, RenderResult::frameMs): which passes a static
// scene's next frame reruns. Checked against the renderer's own caching, an independent
// path: a second render of the same request in the same session reuses the scene's static
// data, so with the camera moved by a centimetre (a new view: G-buffer, cones and rays run
// again) every pass the first render ran and the second did not must be one that reruns only
// when the scene changes, and every pass classed as per-frame must run again.
#include "eval/comparison.h"
#include "eval/provenance.h"
#include "gl/context.h"
#include "methods/registry.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "support/records.h"
#include "support/run_vct.h"
#include "support/filter_precision.h"

#include <gtest/gtest.h>

#include <set>

using namespace vct;
using vcttest::record;

namespace {

RenderRequest cornellRequest(const Scene& s) {
    RenderRequest r;
    r.width = r.height = 24;
    r.camera = resolveCamera(s, CameraRequest{}, 1.f);
    r.voxelRes = 32;
    r.spp = 4;
    return r;
}

std::set<std::string> passNames(const RenderResult& r, bool everyFrameOnly) {
    std::set<std::string> names;
    for (const PassTiming& p : r.passes)
        if (!everyFrameOnly || p.reruns == Reruns::EveryFrame) names.insert(p.name);
    return names;
}

}  // namespace

TEST(FrameCost, WhatTheNextFrameReusesIsWhatFrameMsLeavesOut) {
    // (scene, ao, gi, vct.region). AO alone fits its voxels to the visible points: on the
    // Cornell box the fit is the whole box, a grid the next frame keeps; on the open plane it
    // is a part of the plane, which a moved camera fits anew.
    struct Case {
        std::string scene, ao, gi, region;
    };
    const std::vector<Case> cases = {{"cornell_box", "vct", "vct", ""},
                                     {"cornell_box", "vct", "none", ""},
                                     {"open_plane", "vct", "none", ""},
                                     {"open_plane", "vct", "none", "scene"},
                                     {"cornell_box", "reference", "reference", ""},
                                     {"cornell_box", "gtao", "none", ""},
                                     {"cornell_box", "rtao-denoised", "pt-denoised", ""}};
    for (const Case& c : cases) {
        const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/" + c.scene + ".gltf");
        const std::string what = c.scene + " " + c.ao + "/" + c.gi + " " + c.region;
        RenderSession session(scene);
        RenderRequest r = cornellRequest(scene);
        r.ao = c.ao;
        r.gi = c.gi;
        if (!c.region.empty()) r.params.set("vct.region", c.region);
        r.reuseSceneData = false;
        const RenderResult cold = session.render(r);
        r.reuseSceneData = true;
        session.render(r);  // a cold render keeps nothing: this one fills the session's caches
        r.camera.eye += glm::vec3(0.01f, 0.f, 0.f);
        const RenderResult warm = session.render(r);
        GlContext::shared().checkErrors("frame cost");
        const std::set<std::string> warmPasses = passNames(warm, false);
        // What the next frame ran again is what frame_ms counts...
        for (const PassTiming& p : warm.passes)
            EXPECT_EQ(p.reruns, Reruns::EveryFrame)
                << what << ": " << p.name << " ran again for a moved camera but frame_ms leaves it out";
        EXPECT_TRUE(warmPasses.count("gbuffer") || c.ao == "reference") << what << ": a moved camera draws the G-buffer";
        // ...and what it reused is what frame_ms leaves out.
        double staticMs = 0.0;
        std::set<std::string> staticPasses;
        for (const PassTiming& p : cold.passes) {
            if (!warmPasses.count(p.name)) {
                EXPECT_EQ(p.reruns, Reruns::WhenSceneChanges)
                    << what << ": " << p.name << " was reused by the next frame but counts in frame_ms";
            }
            if (p.reruns == Reruns::WhenSceneChanges) {
                staticMs += p.wallMs;
                staticPasses.insert(p.name);
            }
        }
        for (const std::string& name : passNames(cold, true))
            EXPECT_TRUE(warmPasses.count(name)) << what << ": " << name << " is per-frame but did not rerun";
        EXPECT_GT(cold.frameMs, 0.0);
        EXPECT_NEAR(cold.frameMs, cold.totalMs - staticMs - cold.programBuildMs, 1e-9);
        EXPECT_EQ(warm.programBuildMs, 0.0) << what << ": the next frame builds no program";
        // The per-frame passes' GPU time: none where the timer queries read 0 (llvmpipe) or a
        // per-frame pass runs on the CPU (the reference's and the denoised tracers' rays);
        // elsewhere at most the wall clock of the same passes, which waits for the GPU.
        const bool cpuRays = c.ao == "reference" || c.ao == "rtao-denoised";
        if (!GlContext::shared().info().gpuTimerQueries || cpuRays) {
            EXPECT_FALSE(cold.frameGpuMs.has_value()) << what;
            EXPECT_FALSE(warm.frameGpuMs.has_value()) << what;
        } else {
            ASSERT_TRUE(warm.frameGpuMs.has_value()) << what;
            EXPECT_GT(*warm.frameGpuMs, 0.0) << what;
            EXPECT_LE(*warm.frameGpuMs, warm.frameMs) << what;
        }
        const bool follows = c.ao == "vct" && cold.extra["voxels"]["region"]["follows_view"].get<bool>();
        EXPECT_EQ(follows, c.scene == "open_plane" && c.gi == "none" && c.region.empty()) << what;
        if (c.ao == "vct" || c.ao == "reference") {
            EXPECT_EQ(staticPasses.count(c.ao == "vct" ? "voxelize" : "bvh"), follows ? 0u : 1u)
                << what << ": voxels or a BVH the next frame keeps";
        }
        if (follows) {
            EXPECT_TRUE(warmPasses.count("voxelize") && warmPasses.count("mips")) << what;
        }
        if (c.ao == "gtao") {
            for (const std::string& name : staticPasses)
                EXPECT_EQ(name, "shadow") << "screen-space AO has no static data but the direct light's shadow map";
        }
    }
}

TEST(FrameCost, CompareReportsBothCostsAndProvenance) {
    const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    ComparisonSettings cs;
    cs.base = cornellRequest(scene);
    cs.base.radius = 0.5f;
    cs.referenceSpp = 8;
    cs.timingRuns = 1;
    cs.variants = parseMethodList("gtao,vct,rtao-denoised", "ao");
    const nlohmann::json doc = runComparison(scene, cs);
    for (const auto& rec : doc["records"]) {
        const double t = rec["time_ms"].get<double>(), f = rec["frame_ms"].get<double>();
        EXPECT_GT(f, 0.0) << rec["label"];
        EXPECT_LE(f, t) << rec["label"];
        // The GPU time of the per-frame passes: null without timer queries (llvmpipe) and for
        // the CPU's rays, at most frame_ms elsewhere.
        ASSERT_TRUE(rec.contains("frame_gpu_ms")) << rec["label"];
        if (!GlContext::shared().info().gpuTimerQueries || rec["method"] == "rtao-denoised")
            EXPECT_TRUE(rec["frame_gpu_ms"].is_null()) << rec["label"];
        else
            EXPECT_LE(rec["frame_gpu_ms"].get<double>(), f) << rec["label"];
        // The timed runs draw their G-buffer, as a new view does: the reference's times hold
        // its primary rays, the rasterizing methods' their raster.
        EXPECT_TRUE(rec["passes"].contains("gbuffer")) << rec["label"] << rec["passes"].dump();
        if (rec["method"] != "gtao") {
            // The cold runs build the voxels (vct) or the BVH (rtao-denoised) anew.
            const auto& passes = rec["passes"];
            EXPECT_TRUE(passes.contains(rec["method"] == "vct" ? "voxelize" : "bvh")) << rec["label"] << passes.dump();
            EXPECT_LT(f, t) << rec["label"];
        }
    }
    EXPECT_NE(resultsCsv(doc).find("time_ms,frame_ms"), std::string::npos);
    // Provenance: the scene file's hash computed independently of the comparison, the seed,
    // the commit, and the record's own parameters resolved over the method's defaults.
    const std::string hash = fileSha256(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    for (const auto& rec : doc["records"]) {
        const auto& p = rec["provenance"];
        EXPECT_EQ(p["scene_sha256"], hash) << rec["label"];
        EXPECT_EQ(p["seed"], cs.base.seed);
        EXPECT_EQ(p["commit"], buildCommit());
        EXPECT_FALSE(p["params"].empty()) << rec["label"];
    }
    EXPECT_EQ(record(doc, "vct")["provenance"]["params"]["vct.cones"], "6");
    // Device-independent costs.
    EXPECT_GT(record(doc, "rtao-denoised")["cost"]["rays_per_pixel"].get<double>(), 0.0);
    EXPECT_TRUE(record(doc, "gtao")["cost"]["rays_per_pixel"].is_null());
    EXPECT_GT(record(doc, "vct")["cost"]["voxel_bytes"].get<double>(), 0.0);
    EXPECT_NE(resultsCsv(doc).find("samples_per_pixel,fetches_per_pixel,rays_per_pixel,voxel_bytes"), std::string::npos);
}

TEST(FrameCost, ConeCountersFollowTheShadersFetchRules) {
    // Per volume sample: the directional fetches (AO: one, the three axes' opacity in one
    // texture; GI: three of the six RGBA textures), one more (the base level) below level 1,
    // and for GI one for the facing normal; isotropic levels: one (AO), two (GI). Lanes multiply
    // the cones and narrow them, so the samples grow at least as fast as the lanes.
    const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    RenderSession session(scene);
    auto counters = [&](const std::string& ao, const std::string& gi, const std::vector<std::string>& params) {
        RenderRequest r = cornellRequest(scene);
        r.ao = ao;
        r.gi = gi;
        for (const std::string& p : params) r.params.set(p);
        const RenderResult res = session.render(r);
        GlContext::shared().checkErrors("cone counters");
        return res.extra.at(ao == "vct" ? "cone_ao" : "cone_gi");
    };
    const auto ratio = [](const nlohmann::json& c) {
        return c["fetches_per_pixel"].get<double>() / c["samples_per_pixel"].get<double>();
    };
    const nlohmann::json ao = counters("vct", "none", {}), gi = counters("none", "vct", {});
    const nlohmann::json aoIso = counters("vct", "none", {"vct.aniso=0"}), giIso = counters("none", "vct", {"vct.aniso=0"});
    EXPECT_GE(ao["samples_per_pixel"].get<double>(), 6.0) << "at least one sample per open cone";
    EXPECT_GE(ratio(ao), 1.0);
    EXPECT_LE(ratio(ao), 2.0);
    EXPECT_GE(ratio(gi), 4.0);
    EXPECT_LE(ratio(gi), 5.0);
    EXPECT_DOUBLE_EQ(ratio(aoIso), 1.0);
    EXPECT_DOUBLE_EQ(ratio(giIso), 2.0);
    // The sparse CPU tracer runs the same march over the same levels and counts as the GPU:
    // the same steps within 1%, 5% where hardware filtering moves where a cone saturates
    // (support/filter_precision.h; an H200: 2.2%).
    RenderRequest sparseAo = cornellRequest(scene);
    sparseAo.ao = "vct";
    sparseAo.gi = "none";
    sparseAo.backend = "vdb";
    const nlohmann::json vdb = session.render(sparseAo).extra.at("cone_ao");
    EXPECT_NEAR(vdb["samples_per_pixel"].get<double>(), ao["samples_per_pixel"].get<double>(),
                vcttest::filterTolerance(0.01, 0.05) * ao["samples_per_pixel"].get<double>());
    EXPECT_NEAR(ratio(vdb), ratio(ao), 0.01);
    const nlohmann::json lanes = counters("vct", "none", {"vct.lanes=4"});
    EXPECT_EQ(lanes["cones_marched"], 24);
    EXPECT_GE(lanes["samples_per_pixel"].get<double>(), 4.0 * ao["samples_per_pixel"].get<double>());
    // The dispatches per marching stage: the default sets fit one; one cone per dispatch
    // (vct.dispatch-cones=1) makes one per cone, the same samples; the CPU tracer has none.
    EXPECT_EQ(ao["dispatches"], 1);
    EXPECT_EQ(gi["dispatches"], 1);
    const nlohmann::json split = counters("vct", "none", {"vct.dispatch-cones=1"});
    EXPECT_EQ(split["dispatches"], 6);
    EXPECT_EQ(split["samples"], ao["samples"]);
    EXPECT_EQ(lanes["dispatches"], 1);
    EXPECT_EQ(counters("vct", "none", {"vct.lanes=4", "vct.dispatch-cones=5"})["dispatches"], 5);  // 24 cones
    EXPECT_EQ(vdb["dispatches"], 0);
    // Injection reports its dispatches too: one where the lights fit, one per light at
    // vct.inject.dispatch-lights=1; an AO-only grid is not lit.
    const auto injectDispatches = [&](const std::vector<std::string>& params, bool gi = true) {
        RenderRequest r = cornellRequest(scene);
        r.ao = gi ? "none" : "vct";
        r.gi = gi ? "vct" : "none";
        for (const std::string& p : params) r.params.set(p);
        return session.render(r).extra.at("voxels").at("inject_dispatches").get<int>();
    };
    ASSERT_GE(scene.lights.size(), 1u);
    EXPECT_EQ(injectDispatches({}), 1);
    EXPECT_EQ(injectDispatches({"vct.inject.dispatch-lights=1"}), int(scene.lights.size()));
    EXPECT_EQ(injectDispatches({}, false), 0);
}
