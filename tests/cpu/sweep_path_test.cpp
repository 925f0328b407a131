// Sweep cameras that are camera paths: the spec entry {"path", "frames", "frame_seeds", "name"},
// its defaults, where its file is looked up, the errors naming the field, and how the merged
// table takes a sequence comparison's records (the runs themselves: tests/cli/sweep_path_cli_test.cpp).
#include "eval/sweep.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <tuple>

using namespace vct;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

void writeFile(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

// A path file of `keys` keys, the eye moving along x.
std::string pathFile(int keys) {
    json doc = {{"interpolation", "linear"}, {"keys", json::array()}};
    for (int i = 0; i < keys; ++i)
        doc["keys"].push_back({{"time", i}, {"eye", {0.1 * i, 1, 3}}, {"target", {0, 0.5, 0}}, {"fov", 50}});
    return doc.dump();
}

// A spec directory with paths/walk.json (3 keys) beside the spec, and a repository holding
// paths/walk.json (2 keys: the one beside the spec must win) and paths/repo_only.json.
struct PathDirs {
    SweepPaths paths;
    fs::path specDir, repoDir;
};

PathDirs makeDirs(const std::string& name) {
    PathDirs d;
    const fs::path root = vcttest::freshTempDir(name);
    d.specDir = root / "specs";
    d.repoDir = root / "repo";
    writeFile(d.specDir / "paths" / "walk.json", pathFile(3));
    writeFile(d.repoDir / "paths" / "walk.json", pathFile(2));
    writeFile(d.repoDir / "paths" / "repo_only.json", pathFile(4));
    writeFile(d.specDir / "paths" / "broken.json",
              R"({"keys": [{"time": 0, "eye": [0, 1], "target": [0, 0, 0]}]})");
    d.paths.specDir = d.specDir.string();
    d.paths.repoDir = d.repoDir.string();
    d.paths.sharedDir = (root / "shared").string();
    return d;
}

// A spec of one scene whose cameras are a still one and then `camera`.
json specWithCamera(const json& camera) {
    json spec = json::parse(R"({"methods": [{"method": "gtao"}],
                                "scenes": [{"path": "scenes/a.gltf", "cameras": ["front"]}]})");
    spec["scenes"][0]["cameras"].push_back(camera);
    return spec;
}

std::string parseError(const json& spec, const SweepPaths& paths) {
    try {
        parseSweepSpec(spec, paths);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SweepPath, APathCameraAndItsDefaults) {
    const PathDirs d = makeDirs("sweep_path_parse");
    json spec = specWithCamera({{"path", "paths/walk.json"}, {"frames", 12}});
    spec["scenes"][0]["cameras"].push_back(
        {{"path", "paths/repo_only.json"}, {"frames", 1}, {"frame_seeds", "fixed"}, {"label", "slow"}});
    spec["scenes"][0]["cameras"].push_back({{"path", "gltf:orbit"}, {"frames", 10000}, {"name", "spin"}});
    spec["scenes"][0]["cameras"].push_back({{"path", "gltf:orbit"}, {"frames", 5}, {"frame_seeds", "per-frame"}});
    const SweepSpec s = parseSweepSpec(spec, d.paths);
    const auto& cams = s.scenes[0].cameras;
    ASSERT_EQ(cams.size(), 5u);
    EXPECT_FALSE(cams[0].isPath());

    // Defaults: the file's stem as label, per-frame seeds; the file beside the spec wins over
    // the repository's, and is read while parsing.
    ASSERT_TRUE(cams[1].isPath());
    EXPECT_EQ(cams[1].label, "walk");
    EXPECT_EQ(cams[1].path.entry, "paths/walk.json");
    EXPECT_EQ(cams[1].path.frames, 12);
    EXPECT_TRUE(cams[1].path.perFrameSeeds);
    EXPECT_TRUE(cams[1].path.animation.empty());
    EXPECT_EQ(cams[1].path.file.keys.size(), 3u) << "the repository's walk.json (2 keys) was read";
    EXPECT_EQ(fs::path(cams[1].path.file.source), d.specDir / "paths" / "walk.json");

    // Found in the repository when not beside the spec; a given label and fixed seeds.
    EXPECT_EQ(cams[2].label, "slow");
    EXPECT_EQ(cams[2].path.file.keys.size(), 4u);
    EXPECT_FALSE(cams[2].path.perFrameSeeds);
    EXPECT_EQ(cams[2].path.frames, 1);

    // gltf:NAME: the scene's camera animation, resolved when the scene loads.
    EXPECT_EQ(cams[3].label, "spin");
    EXPECT_EQ(cams[3].path.animation, "orbit");
    EXPECT_TRUE(cams[3].path.file.keys.empty());
    EXPECT_EQ(cams[3].path.frames, 10000);
    EXPECT_EQ(cams[4].label, "orbit");
    EXPECT_TRUE(cams[4].path.perFrameSeeds);

    // Path cameras take their place in the case order and ids like any camera.
    const auto cases = enumerateSweepCases(s);
    std::vector<std::string> ids;
    for (const auto& c : cases) ids.push_back(c.id);
    const std::vector<std::string> expected = {"a__front__r1", "a__walk__r1", "a__slow__r1", "a__spin__r1",
                                               "a__orbit__r1"};
    EXPECT_EQ(ids, expected);

    // case.json says what the case runs.
    const json walk = caseJson(s, cases[1])["camera"];
    EXPECT_EQ(walk["label"], "walk");
    EXPECT_EQ(walk["path"], "paths/walk.json");
    EXPECT_EQ(fs::path(walk["path_file"].get<std::string>()), d.specDir / "paths" / "walk.json");
    EXPECT_EQ(walk["frames"], 12);
    EXPECT_EQ(walk["frame_seeds"], "per-frame");
    EXPECT_FALSE(walk.contains("name_or_index"));
    const json spin = caseJson(s, cases[3])["camera"];
    EXPECT_EQ(spin["path"], "gltf:orbit");
    EXPECT_FALSE(spin.contains("path_file"));
    EXPECT_EQ(caseJson(s, cases[2])["camera"]["frame_seeds"], "fixed");
    // A still camera's case.json is as it was.
    const json front = caseJson(s, cases[0])["camera"];
    EXPECT_EQ(front, json({{"label", "front"}, {"name_or_index", "front"}}));
}

TEST(SweepPath, ErrorsNameTheField) {
    const PathDirs d = makeDirs("sweep_path_errors");
    struct Bad {
        json camera;
        std::vector<std::string> expect;  // each must appear in the message
    };
    const std::string at = "scenes[0].cameras[1].";
    const Bad cases[] = {
        {{{"path", "paths/walk.json"}}, {at + "frames", "required"}},
        {{{"path", "paths/walk.json"}, {"frames", 0}}, {at + "frames", "[1, 10000]"}},
        {{{"path", "paths/walk.json"}, {"frames", 10001}}, {at + "frames", "[1, 10000]"}},
        {{{"path", "paths/walk.json"}, {"frames", 2.5}}, {at + "frames", "integer"}},
        {{{"path", "paths/walk.json"}, {"frames", "3"}}, {at + "frames"}},
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"frame_seeds", "sometimes"}},
         {at + "frame_seeds", "per-frame", "fixed"}},
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"frame_seeds", false}}, {at + "frame_seeds"}},
        {{{"path", "paths/nowhere.json"}, {"frames", 3}}, {at + "path", "no such file", "nowhere.json"}},
        {{{"path", "paths/broken.json"}, {"frames", 3}}, {at + "path", "broken.json", "keys[0].eye"}},
        {{{"path", ""}, {"frames", 3}}, {at + "path"}},
        {{{"path", 7}, {"frames", 3}}, {at + "path"}},
        {{{"path", "gltf:"}, {"frames", 3}}, {at + "path", "gltf:"}},
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"eye", {0, 1, 2}}}, {at + "eye", "unknown field"}},
        {{{"frames", 3}, {"eye", {0, 1, 2}}, {"target", {0, 0, 0}}}, {at + "path", "frames"}},
        {{{"frame_seeds", "fixed"}, {"eye", {0, 1, 2}}, {"target", {0, 0, 0}}}, {at + "path", "frame_seeds"}},
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"name", "a"}, {"label", "b"}}, {at + "label"}},
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"label", ""}}, {at + "label"}},
        // Two paths of one file make the same case id.
        {{{"path", "paths/walk.json"}, {"frames", 3}, {"name", "front"}}, {"a__front__r1"}},
    };
    for (const Bad& b : cases) {
        const std::string msg = parseError(specWithCamera(b.camera), d.paths);
        ASSERT_FALSE(msg.empty()) << b.camera.dump() << " was accepted";
        for (const std::string& e : b.expect)
            EXPECT_NE(msg.find(e), std::string::npos) << b.camera.dump() << " gave: '" << msg << "'";
    }
    EXPECT_EQ(parseError(specWithCamera({{"path", "paths/walk.json"}, {"frames", 3}}), d.paths), "");

    // Through the file: the spec's own name leads the message.
    const fs::path specFile = d.specDir / "spec.json";
    writeFile(specFile, specWithCamera({{"path", "paths/walk.json"}, {"frames", 0}}).dump());
    try {
        loadSweepSpec(specFile.string());
        FAIL() << "frames 0 accepted";
    } catch (const std::invalid_argument& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(specFile.string() + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find("scenes[0].cameras[1].frames"), std::string::npos) << msg;
    }
}

TEST(SweepPath, MergedRecordsOfAPathCaseShareTheStillColumns) {
    const fs::path root = vcttest::freshTempDir("sweep_path_merge");
    // A still case and a path case, shaped as runComparison and runSequenceComparison write them.
    const fs::path still = root / "cases" / "a__front__r1";
    json stillResults = {{"scene", "/repo/scenes/a.gltf"}, {"radius", 1.0}, {"width", 32}, {"height", 24},
                         {"gl_renderer", "llvmpipe"}, {"reference", {{"spp", 4}, {"ao_rms_pixel_stderr", 0.02}}},
                         {"records", {{{"label", "gtao"}, {"kind", "ao"}, {"method", "gtao"}, {"params", json::object()},
                                       {"time_ms", 2.0}, {"frame_ms", 1.0}, {"rmse", 0.1}, {"ssim", 0.9}}}}};
    writeFile(still / "results.json", stillResults.dump());
    writeFile(still / "case.json", json{{"id", "a__front__r1"}, {"index", 0}, {"scene", "a"},
                                        {"camera", {{"label", "front"}}}}.dump());
    const fs::path walk = root / "cases" / "a__walk__r1";
    json walkResults = {{"scene", "/repo/scenes/a.gltf"}, {"radius", 1.0}, {"width", 32}, {"height", 24},
                        {"gl_renderer", "llvmpipe"}, {"frames", 3}, {"per_frame_seeds", false},
                        {"path", {{"source", "/specs/paths/walk.json"}, {"keys", json::array()}}},
                        {"reference", {{"spp", 4}}}, {"records", json::array()}};
    for (auto [label, t, e] : {std::tuple{"gtao", 3.0, 0.2}, std::tuple{"hbao", 4.0, 0.3}})
        walkResults["records"].push_back({{"label", label}, {"kind", "ao"}, {"method", label},
                                          {"params", json::object()}, {"time_ms", t}, {"frame_ms", 1.5},
                                          {"rmse_mean", e}, {"rmse_worst", 2 * e}, {"instability", 0.01},
                                          {"frames_dir", std::string("frames/") + label}});
    writeFile(walk / "results.json", walkResults.dump());
    writeFile(walk / "case.json", json{{"id", "a__walk__r1"}, {"index", 1}, {"scene", "a"},
                                       {"camera", {{"label", "walk"}, {"path", "paths/walk.json"}}}}.dump());

    const json merged = mergeSweepResults({root.string()});
    ASSERT_EQ(merged["records"].size(), 3u);
    const json& s = merged["records"][0];
    EXPECT_EQ(s["camera"], "front");
    EXPECT_FALSE(s.contains("frames")) << "a still record gains no sequence fields";
    EXPECT_FALSE(s.contains("camera_path"));
    const json& g = merged["records"][1];
    EXPECT_EQ(g["case"], "a__walk__r1");
    EXPECT_EQ(g["camera"], "walk");
    EXPECT_DOUBLE_EQ(g["rmse"].get<double>(), 0.2);
    EXPECT_DOUBLE_EQ(g["rmse_worst"].get<double>(), 0.4);
    EXPECT_EQ(g["frames"], 3);
    EXPECT_EQ(g["camera_path"], "/specs/paths/walk.json");
    EXPECT_EQ(g["frame_seeds"], "fixed");
    EXPECT_EQ(g["ref_spp"], 4);
    EXPECT_EQ(fs::path(g["frames_dir"].get<std::string>()), walk / "frames" / "gtao");
    // Fronts within the path case: hbao is slower and worse than gtao.
    EXPECT_TRUE(g["pareto"].get<bool>());
    EXPECT_FALSE(merged["records"][2]["pareto"].get<bool>());

    // The CSV: the still header as it always was, then the sequence columns.
    const std::string stillHeader =
        "case,scene,camera,radius,width,height,kind,method,label,params,time_ms,frame_ms,rmse,mae,bias,max_abs,psnr,"
        "ssim,roi_rmse,nonroi_rmse,ref_spp,ref_stderr,pareto,pareto_roi,samples_per_pixel,fetches_per_pixel,"
        "rays_per_pixel,voxel_bytes,gl_renderer";
    const std::string csv = mergedCsv(merged);
    EXPECT_EQ(csv.substr(0, csv.find('\n')), stillHeader + ",frames,rmse_worst,instability,camera_path,frame_seeds");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
    EXPECT_NE(csv.find(",llvmpipe,3,0.4,0.01,/specs/paths/walk.json,fixed\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",llvmpipe,,,,,\n"), std::string::npos) << "the still record's sequence cells are empty\n" << csv;

    // Without a path case the table keeps exactly its still columns.
    fs::remove_all(walk);
    const std::string stillCsv = mergedCsv(mergeSweepResults({root.string()}));
    EXPECT_EQ(stillCsv.substr(0, stillCsv.find('\n')), stillHeader);
}
