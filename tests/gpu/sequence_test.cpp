// Comparisons along camera paths (eval/sequence_comparison.h) on a box on a floor: a still path
// leaves a deterministic method unchanged and a re-seeded one (SSAO's kernel, VCT's cone set
// turned per pixel by vct.jitter) flickering; a pan leaves the
// reference's AO (which does not depend on the camera) changed by its noise only, which is what
// the reprojection must give; the records carry what the tables need.
#include "eval/sequence_comparison.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

namespace {

using namespace vcttest;

vct::Scene boxOnFloor() {
    vct::Scene s;
    const uint32_t m = addMaterial(s, glm::vec3(0.6f));
    addQuad(s, glm::vec3(-3, 0, 3), glm::vec3(6, 0, 0), glm::vec3(0, 0, -6), m);
    addBox(s, glm::vec3(-0.5f, 0.f, -0.5f), glm::vec3(0.5f, 1.f, 0.5f), m);
    finish(s);
    return s;
}

vct::CameraPath pathThrough(std::vector<glm::vec3> eyes, glm::vec3 target) {
    vct::CameraPath p;
    p.source = "test";
    p.interpolation = vct::PathInterpolation::Linear;
    for (size_t i = 0; i < eyes.size(); ++i) {
        vct::CameraKey k;
        k.time = double(i);
        k.eye = eyes[i];
        k.target = target;
        k.fovDeg = 50.f;
        p.keys.push_back(k);
    }
    return p;
}

vct::SequenceSettings settingsFor(const vct::CameraPath& path, int frames, const std::string& methods) {
    vct::SequenceSettings s;
    s.path = path;
    s.frames = frames;
    s.comparison.base.width = 48;
    s.comparison.base.height = 40;
    s.comparison.base.radius = 0.8f;
    s.comparison.base.voxelRes = 32;
    s.comparison.referenceSpp = 32;
    s.comparison.timingRuns = 1;
    s.comparison.variants = vct::parseMethodList(methods, "ao");
    return s;
}

const nlohmann::json& recordOf(const nlohmann::json& doc, const std::string& label) {
    for (const auto& r : doc["records"])
        if (r["label"] == label) return r;
    throw std::runtime_error("no record " + label);
}

TEST(Sequence, AStillPathLeavesDeterministicMethodsUnchangedAndReseededOnesFlicker) {
    const vct::Scene scene = boxOnFloor();
    const glm::vec3 eye(2.5f, 2.f, 3.f);
    vct::SequenceSettings s = settingsFor(pathThrough({eye, eye}, glm::vec3(0, 0.3f, 0)), 3,
                                             "vct,ssao-hemisphere,vct[vct.jitter=1]");
    s.comparison.referenceSpp = 128;
    nlohmann::json doc = vct::runSequenceComparison(scene, s);
    const nlohmann::json& v = recordOf(doc, "vct");
    const nlohmann::json& ssao = recordOf(doc, "ssao-hemisphere");
    const double noise = v["temporal"]["reference_noise_rms"].get<double>();
    const double resolution = v["temporal"]["resolution"].get<double>();
    ASSERT_GT(noise, 0.0);
    ASSERT_GT(resolution, 0.0);
    // VCT is a function of the scene and the camera: no change at all, and an instability that
    // is zero within the reference's noise (what remains is that noise's own fluctuation).
    EXPECT_EQ(v["temporal"]["change_rms"].get<double>(), 0.0);
    EXPECT_LT(v["instability"].get<double>(), 1.5 * resolution);
    EXPECT_NEAR(v["temporal"]["raw_rms"].get<double>(), noise, 0.1 * noise);
    // SSAO's kernel and noise come from the frame's seed: it changes on a still camera, well
    // beyond what the score resolves.
    EXPECT_GT(ssao["temporal"]["change_rms"].get<double>(), 0.003);
    EXPECT_GT(ssao["instability"].get<double>(), 2.0 * ssao["temporal"]["resolution"].get<double>());
    // So does VCT whose cone set turns per pixel with the frame's seed: the same voxels, a new set.
    const nlohmann::json& jittered = recordOf(doc, "vct[vct.jitter=1]");
    EXPECT_GT(jittered["temporal"]["change_rms"].get<double>(), 0.003);
    EXPECT_GT(jittered["instability"].get<double>(), 2.0 * jittered["temporal"]["resolution"].get<double>());
    // Per-frame figures for every frame, instability per frame pair.
    EXPECT_EQ(v["per_frame"]["rmse"].size(), 3u);
    EXPECT_EQ(v["per_frame"]["instability"].size(), 2u);
    EXPECT_GE(v["rmse_worst"].get<double>(), v["rmse_mean"].get<double>());
    EXPECT_GT(v["time_ms"].get<double>(), 0.0);
    EXPECT_TRUE(v["provenance"].contains("commit"));

    // With one seed for every frame SSAO keeps its pattern too.
    s.perFrameSeeds = false;
    nlohmann::json fixed = vct::runSequenceComparison(scene, s);
    EXPECT_EQ(recordOf(fixed, "ssao-hemisphere")["temporal"]["change_rms"].get<double>(), 0.0);
    EXPECT_EQ(recordOf(fixed, "vct[vct.jitter=1]")["temporal"]["change_rms"].get<double>(), 0.0);
}

TEST(Sequence, APanChangesTheReferenceByItsNoiseOnly) {
    const vct::Scene scene = boxOnFloor();
    const glm::vec3 eye(2.5f, 2.f, 3.f), side(0.12f, 0.f, -0.08f);
    vct::SequenceSettings s =
        settingsFor(pathThrough({eye, eye + 3.f * side}, glm::vec3(0, 0.3f, 0) + 1.5f * side), 4, "vct");
    s.comparison.referenceSpp = 64;
    nlohmann::json doc = vct::runSequenceComparison(scene, s);
    const nlohmann::json& ref = doc["reference"]["ao_temporal"];
    const double noise = ref["reference_noise_rms"].get<double>();
    ASSERT_GT(ref["samples"].get<double>(), 1000.0);
    // Its raw change is its noise (independent seeds per frame); beyond that, nothing moved.
    EXPECT_NEAR(ref["change_rms"].get<double>(), noise, 0.25 * noise);
    EXPECT_LT(ref["instability"].get<double>(), 1.5 * ref["resolution"].get<double>());
    // VCT's voxels are the scene's (vct.region=fit regrows them with the view, a change of its own).
    const nlohmann::json& v = recordOf(doc, "vct");
    EXPECT_EQ(v["per_frame"]["frame_ms"].size(), 4u);
    EXPECT_GT(v["temporal"]["samples"].get<double>(), 1000.0);
}

}  // namespace
