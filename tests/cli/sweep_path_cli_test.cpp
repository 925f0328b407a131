// `vct sweep` with a camera path: a tiny sweep (a project scene, 32x24, reference at 4 spp, two
// screen-space methods) of a still camera and a still path of the same view, merged; and a
// gltf: path the scene lacks, refused naming the case.
#include "support/run_vct.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace vcttest;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json readJson(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

// The Cornell box from its front camera: corners and boxes the AO radius reaches.
const json kEye = {0.0, 1.0, 3.9}, kTarget = {0.0, 1.0, 0.0};
const double kFov = 39.3;

// A spec beside a path file whose keys all hold the view kEye -> kTarget.
std::string writeSpec(const std::string& dir, const json& pathCamera) {
    json path = {{"interpolation", "catmull-rom"}, {"keys", json::array()}};
    for (int t = 0; t < 3; ++t) path["keys"].push_back({{"time", t}, {"eye", kEye}, {"target", kTarget}, {"fov", kFov}});
    fs::create_directories(dir + "/paths");
    std::ofstream(dir + "/paths/still.json") << path.dump(2);
    json spec = json::parse(R"({
        "name": "tiny-path",
        "size": [32, 24], "ref_spp": 4, "runs": 1, "radius": 0.5, "voxel_res": 32,
        "methods": [{"kind": "ao", "method": "gtao"}, {"kind": "ao", "method": "hbao"}],
        "scenes": [{"path": "scenes/cornell_box.gltf", "cameras": []}]
    })");
    spec["scenes"][0]["cameras"].push_back({{"name", "view"}, {"eye", kEye}, {"target", kTarget}, {"fov", kFov}});
    spec["scenes"][0]["cameras"].push_back(pathCamera);
    std::ofstream(dir + "/spec.json") << spec.dump(2);
    return dir + "/spec.json";
}

const json* recordOf(const json& merged, const std::string& kase, const std::string& label) {
    for (const json& r : merged["records"])
        if (r["case"] == kase && r["label"] == label) return &r;
    return nullptr;
}

}  // namespace

TEST(SweepPathCli, APathCaseJoinsTheMergedTableBesideTheStillCase) {
    const std::string tmp = freshTempDir("sweep_path_cli");
    const std::string spec =
        writeSpec(tmp, {{"path", "paths/still.json"}, {"frames", 3}, {"frame_seeds", "fixed"}});
    const std::string out = tmp + "/out";
    auto r = runVct("sweep " + spec + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string stillId = "cornell_box__view__r0.5", pathId = "cornell_box__still__r0.5";
    EXPECT_NE(r.output.find(stillId + ": ran 2 variants in"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(pathId + ": ran 2 variants over 3 frames"), std::string::npos) << r.output;
    const json caseInfo = readJson(out + "/cases/" + pathId + "/case.json");
    EXPECT_EQ(caseInfo["camera"]["frames"], 3);
    EXPECT_EQ(caseInfo["camera"]["frame_seeds"], "fixed");

    r = runVct("merge " + out + " -o " + tmp + "/merged");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const json merged = readJson(tmp + "/merged/results.json");
    ASSERT_EQ(merged["records"].size(), 4u) << "2 cases x 2 variants";

    for (const char* label : {"gtao", "hbao"}) {
        SCOPED_TRACE(label);
        const json* p = recordOf(merged, pathId, label);
        const json* s = recordOf(merged, stillId, label);
        ASSERT_TRUE(p && s);
        // The path case: the sequence fields, and the still ones it shares.
        EXPECT_EQ((*p)["frames"], 3);
        EXPECT_EQ((*p)["camera"], "still");
        EXPECT_EQ((*p)["frame_seeds"], "fixed");
        EXPECT_NE((*p)["camera_path"].get<std::string>().find("still.json"), std::string::npos);
        ASSERT_TRUE((*p)["instability"].is_number());
        ASSERT_TRUE((*p)["rmse"].is_number());
        EXPECT_EQ((*p)["rmse"], (*p)["rmse_mean"]);
        EXPECT_GE((*p)["rmse_worst"].get<double>(), (*p)["rmse"].get<double>() * (1 - 1e-12));
        EXPECT_EQ((*p)["per_frame"]["rmse"].size(), 3u);
        // The frames' images, under the case's directory.
        const fs::path frames = (*p)["frames_dir"].get<std::string>();
        EXPECT_EQ(frames.parent_path().parent_path(), fs::path(out + "/cases/" + pathId));
        EXPECT_TRUE(fs::exists(frames / "0002.png")) << frames;
        EXPECT_GT((*p)["time_ms"].get<double>(), 0.0);
        EXPECT_GT((*p)["frame_ms"].get<double>(), 0.0);
        EXPECT_TRUE((*p)["provenance"].contains("commit"));
        EXPECT_EQ((*p)["provenance"]["params"], (*s)["provenance"]["params"]);
        EXPECT_EQ((*p)["width"], 32);
        EXPECT_EQ((*p)["height"], 24);
        EXPECT_EQ((*p)["ref_spp"], 4);
        EXPECT_TRUE((*p)["pareto"].is_boolean());
        // A deterministic method on a still path with one seed: the same image every frame, so
        // what the score reports is the reference's noise, zero within its resolution.
        const json& temporal = (*p)["temporal"];
        EXPECT_EQ(temporal["change_rms"].get<double>(), 0.0);
        EXPECT_GT(temporal["resolution"].get<double>(), 0.0);
        EXPECT_LE((*p)["instability"].get<double>(), temporal["resolution"].get<double>());
        // Frame 0 of a still path is the still case: same camera, seed and reference.
        EXPECT_NEAR((*p)["per_frame"]["rmse"][0].get<double>(), (*s)["rmse"].get<double>(), 1e-9);

        // The still case keeps its usual fields and gains none of the sequence's.
        EXPECT_EQ((*s)["camera"], "view");
        for (const char* key : {"rmse", "mae", "psnr", "ssim", "time_ms", "frame_ms", "ref_stderr"})
            EXPECT_TRUE((*s)[key].is_number()) << key;
        for (const char* key : {"frames", "instability", "camera_path", "rmse_worst"})
            EXPECT_FALSE(s->contains(key)) << key;
    }

    // The CSV: the still columns first, then the sequence's.
    std::ifstream csvIn(tmp + "/merged/results.csv");
    std::string header;
    std::getline(csvIn, header);
    EXPECT_EQ(header.rfind("case,scene,camera,radius,width,height,kind,method,label,params,time_ms", 0), 0u) << header;
    EXPECT_NE(header.find(",gl_renderer,frames,rmse_worst,instability,camera_path,frame_seeds"), std::string::npos)
        << header;

    // Resuming: both cases are done, the path case's results stay as they are.
    const fs::path pathResults = out + "/cases/" + pathId + "/results.json";
    const auto before = fs::last_write_time(pathResults);
    r = runVct("sweep " + spec + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(pathId + ": skipped, done already"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(stillId + ": skipped, done already"), std::string::npos) << r.output;
    EXPECT_EQ(fs::last_write_time(pathResults), before);
}

TEST(SweepPathCli, BadPathsAreUsageErrorsNamingTheFieldOrTheCase) {
    const std::string tmp = freshTempDir("sweep_path_cli_bad");
    // Out of range: refused before anything is written.
    std::string spec = writeSpec(tmp, {{"path", "paths/still.json"}, {"frames", 0}});
    auto r = runVct("sweep " + spec + " -o " + tmp + "/out");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("scenes[0].cameras[1].frames"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(tmp + "/out"));

    // A camera animation the scene lacks: known once the scene loads, so the case is named.
    spec = writeSpec(tmp, {{"path", "gltf:nothing"}, {"frames", 2}});
    r = runVct("sweep " + spec + " -o " + tmp + "/out2 --no-images");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("case cornell_box__nothing__r0.5"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("nothing"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(tmp + "/out2/cases/cornell_box__nothing__r0.5/results.json"));
}
