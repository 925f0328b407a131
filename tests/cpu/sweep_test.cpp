// Sweep specs, case enumeration, sharding and merging: everything of `vct sweep` / `vct
// merge` that needs no GL (the runs themselves are covered by tests/cli/sweep_cli_test.cpp).
#include "eval/sweep.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

using namespace vct;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

SweepPaths testPaths() {
    SweepPaths p;
    p.specDir = "/nonexistent/specs";
    p.repoDir = "/repo";
    p.sharedDir = "/shared/scenes";
    return p;
}

json minimalSpec() {
    return json::parse(R"({
        "scenes": ["scenes/a.gltf"],
        "methods": [{"kind": "ao", "method": "gtao"}]
    })");
}

// The message of the std::invalid_argument that parsing `spec` throws ("" if none).
std::string parseError(const json& spec) {
    try {
        parseSweepSpec(spec, testPaths());
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

void writeFile(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

}  // namespace

TEST(SweepSpec, ErrorsNameTheField) {
    struct Bad {
        const char* patch;  // JSON merge patch applied to the minimal spec
        const char* field;  // must appear in the message
    };
    const Bad cases[] = {
        {R"({"radius": -1})", "radius"},
        {R"({"radius": [0.5, "x"]})", "radius[1]"},
        {R"({"size": "12q"})", "size"},
        {R"({"ref_spp": 0})", "ref_spp"},
        {R"({"runs": 1.5})", "runs"},
        {R"({"voxel_res": 2})", "voxel_res"},
        {R"({"sizes": 64})", "sizes"},
        {R"({"scenes": []})", "scenes"},
        {R"({"scenes": [42]})", "scenes[0]"},
        {R"({"scenes": ["a.gltf", {"path": "b.gltf", "radius": 0}]})", "scenes[1].radius"},
        {R"({"scenes": [{"path": "b.gltf", "cameras": [{"eye": [0, 1]}]}]})", "scenes[0].cameras[0].eye"},
        {R"({"scenes": [{"path": "b.gltf", "cameras": [{"eye": [0, 1, 2]}]}]})", "scenes[0].cameras[0].target"},
        {R"({"scenes": [{"path": "b.gltf", "camera": "x"}]})", "scenes[0].camera"},
        {R"({"methods": [{"method": "gtao"}, {"method": "nope"}]})", "methods[1].method"},
        {R"({"methods": [{"kind": "light", "method": "gtao"}]})", "methods[0].kind"},
        {R"({"methods": [{"method": "gtao", "grid": {"gtao.nothing": [1, 2]}}]})", "methods[0].grid.gtao.nothing"},
        {R"({"methods": [{"method": "gtao", "grid": {"gtao.preset": []}}]})", "methods[0].grid.gtao.preset"},
        {R"({"methods": [{"method": "gtao", "grid": {"gtao.preset": [{}]}}]})", "methods[0].grid.gtao.preset[0]"},
        {R"({"methods": [{"method": "gtao", "params": {"blur": 0}, "grid": {"blur": [0, 1]}}]})",
         "methods[0].grid.blur"},
        {R"({"methods": [{"method": "gtao"}, {"method": "gtao"}]})", "methods[1]"},
        {R"({"params": {"gtao.slicez": 2}})", "params.gtao.slicez"},
        {R"({"scenes": ["a/x.gltf", "b/x.gltf"]})", "x__default__r1"},
    };
    for (const Bad& b : cases) {
        json spec = minimalSpec();
        spec.merge_patch(json::parse(b.patch));
        const std::string msg = parseError(spec);
        EXPECT_NE(msg.find(b.field), std::string::npos) << "patch " << b.patch << " gave: '" << msg << "'";
    }
    EXPECT_EQ(parseError(minimalSpec()), "");
}

TEST(SweepSpec, GridIsTheCartesianProductInSortedKeyOrder) {
    auto v = expandMethodGrid("ao", "hbao", {{"blur", "0"}},
                              {{"hbao.directions", {"4", "8"}}, {"hbao.steps", {"2", "4", "8"}}});
    ASSERT_EQ(v.size(), 6u);
    EXPECT_EQ(v[0].label(), "hbao[blur=0;hbao.directions=4;hbao.steps=2]");
    EXPECT_EQ(v[1].label(), "hbao[blur=0;hbao.directions=4;hbao.steps=4]");
    EXPECT_EQ(v[5].label(), "hbao[blur=0;hbao.directions=8;hbao.steps=8]");
    std::set<std::string> labels;
    for (const auto& x : v) labels.insert(x.label());
    EXPECT_EQ(labels.size(), 6u);

    // Through the JSON: keys given out of order, numbers and bools become --param text.
    json spec = json::parse(R"({
        "scenes": ["a.gltf"],
        "methods": [{"method": "hbao", "grid": {"hbao.steps": [2, 4], "hbao.directions": 4, "blur": [true, false]}},
                    {"method": "gtao"}]
    })");
    SweepSpec s = parseSweepSpec(spec, testPaths());
    ASSERT_EQ(s.scenes[0].variants.size(), 5u);
    EXPECT_EQ(s.scenes[0].variants[0].label(), "hbao[blur=1;hbao.directions=4;hbao.steps=2]");
    EXPECT_EQ(s.scenes[0].variants[3].label(), "hbao[blur=0;hbao.directions=4;hbao.steps=4]");
    EXPECT_EQ(s.scenes[0].variants[4].label(), "gtao");
}

TEST(SweepSpec, ScenePathsResolveAgainstSpecRepoAndShared) {
    SweepPaths p = testPaths();
    EXPECT_EQ(resolveScenePath("${shared}/mcguire_sponza.glb", p), "/shared/scenes/mcguire_sponza.glb");
    EXPECT_EQ(resolveScenePath("scenes/a.gltf", p), "/repo/scenes/a.gltf");
    EXPECT_EQ(resolveScenePath("/abs/b.glb", p), "/abs/b.glb");
    // A file beside the spec wins over the repository's.
    const std::string dir = vcttest::freshTempDir("sweep_paths");
    writeFile(fs::path(dir) / "scenes" / "a.gltf", "{}");
    p.specDir = dir;
    EXPECT_EQ(resolveScenePath("scenes/a.gltf", p), (fs::path(dir) / "scenes" / "a.gltf").string());
    EXPECT_THROW(resolveScenePath("x/${shared}/a.glb", p), std::invalid_argument);
}

TEST(SweepCases, OrderIsScenesThenCamerasThenRadii) {
    json spec = json::parse(R"({
        "radius": [0.5, 1],
        "methods": [{"method": "gtao"}],
        "scenes": [
            {"path": "scenes/b.gltf", "cameras": ["front", 2, {"name": "low", "eye": [0, 1, 2], "target": [0, 0, 0]}]},
            {"path": "${shared}/a.glb", "radius": 0.25},
            "scenes/c d.gltf"
        ]
    })");
    SweepSpec s = parseSweepSpec(spec, testPaths());
    auto cases = enumerateSweepCases(s);
    std::vector<std::string> ids;
    for (const auto& c : cases) ids.push_back(c.id);
    const std::vector<std::string> expected = {
        "b__front__r0.5", "b__front__r1", "b__cam2__r0.5", "b__cam2__r1", "b__low__r0.5", "b__low__r1",
        "a__default__r0.25", "c_d__default__r0.5", "c_d__default__r1"};
    EXPECT_EQ(ids, expected);
    for (size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(cases[i].index, i);
    EXPECT_EQ(cases[2].camera.nameOrIndex, "2");
    EXPECT_TRUE(cases[4].camera.hasEye);
    EXPECT_FLOAT_EQ(cases[6].radius, 0.25f);
    EXPECT_EQ(s.scenes[cases[6].scene].path, "/shared/scenes/a.glb");
    // Parsing again gives the same order.
    auto again = enumerateSweepCases(parseSweepSpec(spec, testPaths()));
    ASSERT_EQ(again.size(), cases.size());
    for (size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(again[i].id, cases[i].id);
}

TEST(SweepCases, ShardsPartitionTheCases) {
    json spec = json::parse(R"({"radius": [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7], "methods": [{"method": "hbao"}],
                                "scenes": ["a.gltf", "b.gltf"]})");
    SweepSpec s = parseSweepSpec(spec, testPaths());
    auto all = enumerateSweepCases(s);
    ASSERT_EQ(all.size(), 14u);
    for (int n = 1; n <= 5; ++n) {
        std::multiset<std::string> seen;
        for (int i = 0; i < n; ++i) {
            auto part = casesOfShard(all, parseShard(std::to_string(i) + "/" + std::to_string(n)));
            for (const auto& c : part) {
                EXPECT_EQ(int(c.index % n), i);
                seen.insert(c.id);
            }
        }
        EXPECT_EQ(seen.size(), all.size()) << "N=" << n;
        for (const auto& c : all) EXPECT_EQ(seen.count(c.id), 1u) << c.id << " N=" << n;
    }
    for (const char* bad : {"2/2", "-1/2", "0/0", "1", "a/b", "1/2x"}) EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
}

TEST(SweepMerge, ParetoFrontIsTheNonDominatedSet) {
    // (time_ms, rmse) in one group; C is dominated by B, E by A (equal time, worse error).
    json recs = json::array();
    auto add = [&](const char* label, double t, double e, const char* kase = "k", const char* kind = "ao") {
        recs.push_back({{"label", label}, {"case", kase}, {"kind", kind}, {"time_ms", t}, {"rmse", e}, {"roi_rmse", nullptr}});
    };
    add("A", 1, 0.5);
    add("B", 2, 0.3);
    add("C", 3, 0.4);
    add("D", 0.5, 0.9);
    add("E", 1, 0.6);
    add("F", 3, 0.4, "other");  // alone in its group
    add("G", 9, 0.1, "k", "gi");  // other kind: not compared with the AO records
    markParetoFronts(recs);
    const std::vector<bool> expected = {true, true, false, true, false, true, true};
    for (size_t i = 0; i < recs.size(); ++i) {
        EXPECT_EQ(recs[i]["pareto"].get<bool>(), expected[i]) << recs[i]["label"];
        EXPECT_TRUE(recs[i]["pareto_roi"].is_null());
    }
}

TEST(SweepMerge, CombinesShardDirectoriesInCaseOrder) {
    const fs::path root = vcttest::freshTempDir("sweep_merge");
    // Case documents shaped like runComparison's, in two "shard" directories.
    auto writeCase = [&](const std::string& dir, const std::string& id, int index, double t0) {
        json results = {{"scene", "scenes/" + id + ".gltf"}, {"radius", 0.5}, {"width", 64}, {"height", 64},
                        {"gl_renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"},
                        {"reference", {{"spp", 16}, {"ao_rms_pixel_stderr", 0.01}}},
                        {"records", json::array()}};
        results["records"].push_back({{"label", "gtao"}, {"kind", "ao"}, {"method", "gtao"}, {"params", json::object()},
                                      {"time_ms", t0}, {"rmse", 0.2}, {"roi_rmse", 0.4}, {"nonroi_rmse", 0.1},
                                      {"images", {{"png", "ao_gtao.png"}}}});
        results["records"].push_back({{"label", "hbao[hbao.steps=2]"}, {"kind", "ao"}, {"method", "hbao"},
                                      {"params", {{"hbao.steps", "2"}}}, {"time_ms", t0 * 2}, {"rmse", 0.1},
                                      {"roi_rmse", 0.5}, {"nonroi_rmse", 0.05}});
        const fs::path c = root / dir / "cases" / id;
        writeFile(c / "results.json", results.dump());
        writeFile(c / "case.json", json{{"id", id}, {"index", index}, {"scene", id}, {"camera", {{"label", "default"}}}}.dump());
    };
    writeCase("s0", "beta", 0, 10);
    writeCase("s1", "alpha", 1, 20);
    writeCase("s0", "gamma", 2, 30);
    fs::create_directories(root / "s1" / "cases" / "unfinished");  // no results.json: left out with a warning
    writeCase("s1", "beta", 0, 99);                               // duplicate of s0's: the first directory wins

    std::vector<std::string> warnings;
    json merged = mergeSweepResults({(root / "s0").string(), (root / "s1").string()},
                                    [&](const std::string& w) { warnings.push_back(w); });
    ASSERT_EQ(merged["cases"].size(), 3u);
    EXPECT_EQ(merged["cases"][0]["case"]["id"], "beta");
    EXPECT_EQ(merged["cases"][1]["case"]["id"], "alpha");
    EXPECT_EQ(merged["cases"][2]["case"]["id"], "gamma");
    ASSERT_EQ(merged["records"].size(), 6u);
    const json& r0 = merged["records"][0];
    EXPECT_EQ(r0["case"], "beta");
    EXPECT_EQ(r0["scene"], "beta");
    EXPECT_EQ(r0["camera"], "default");
    EXPECT_DOUBLE_EQ(r0["time_ms"].get<double>(), 10.0) << "the first directory's copy of a duplicate case";
    EXPECT_DOUBLE_EQ(r0["ref_stderr"].get<double>(), 0.01);
    EXPECT_EQ(r0["ref_spp"], 16);
    EXPECT_EQ(r0["gl_renderer"], "llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_EQ(fs::path(r0["images"]["png"].get<std::string>()), root / "s0" / "cases" / "beta" / "ao_gtao.png");
    // Two records per case: the faster is on both fronts only where it is also better there.
    EXPECT_TRUE(r0["pareto"].get<bool>());
    EXPECT_TRUE(merged["records"][1]["pareto"].get<bool>());  // slower but lower rmse
    EXPECT_TRUE(r0["pareto_roi"].get<bool>());
    EXPECT_FALSE(merged["records"][1]["pareto_roi"].get<bool>());  // slower and higher roi_rmse
    bool warnedUnfinished = false, warnedDuplicate = false;
    for (const auto& w : warnings) {
        warnedUnfinished |= w.find("unfinished") != std::string::npos;
        warnedDuplicate |= w.find("beta") != std::string::npos;
    }
    EXPECT_TRUE(warnedUnfinished);
    EXPECT_TRUE(warnedDuplicate);

    // CSV: a header and one line per record; the renderer (with commas) is quoted.
    const std::string csv = mergedCsv(merged);
    EXPECT_EQ(csv.rfind("case,scene,camera,radius,width,height,kind,method,label,params,time_ms", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
    EXPECT_NE(csv.find(",\"llvmpipe (LLVM 15.0.6, 256 bits)\"\n"), std::string::npos);
    EXPECT_NE(csv.find("hbao.steps=2"), std::string::npos);

    EXPECT_THROW(mergeSweepResults({(root / "nothing").string()}), std::invalid_argument);
}
