// `vct sweep` and `vct merge` as a user meets them: a tiny sweep (two project scenes x two
// radii, 64x64, 16 spp, screen-space methods) interrupted and resumed, and sharded then
// merged, must give the records of one uninterrupted run (timings aside: they differ run to run).
#include "support/run_vct.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>

using namespace vcttest;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json readJson(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

// Fields that measure time (or depend on it, like the Pareto flags) or name a directory.
json withoutTiming(const json& j) {
    if (j.is_array()) {
        json out = json::array();
        for (const json& x : j) out.push_back(withoutTiming(x));
        return out;
    }
    if (!j.is_object()) return j;
    json out = json::object();
    for (auto it = j.begin(); it != j.end(); ++it) {
        const std::string& k = it.key();
        const bool timing = k == "time_ms" || k == "passes" || k == "pareto" || k == "pareto_roi" ||
                            (k.size() > 3 && k.compare(k.size() - 3, 3, "_ms") == 0);
        if (timing || k == "images") continue;
        out[k] = withoutTiming(it.value());
    }
    return out;
}

std::string writeTinySpec(const std::string& dir) {
    const std::string path = dir + "/tiny.json";
    std::ofstream(path) << R"({
        "name": "tiny",
        "size": 64, "ref_spp": 16, "runs": 1, "radius": [0.5, 0.25],
        "methods": [
            {"kind": "ao", "method": "gtao", "grid": {"gtao.preset": ["low", "high"]}},
            {"kind": "ao", "method": "hbao", "params": {"blur": 0}}
        ],
        "scenes": ["scenes/offscreen_overhang.gltf", "scenes/wall_base.gltf", "${shared}/no_such_scene.glb"]
    })";
    return path;
}

const std::vector<std::string> kCases = {"offscreen_overhang__default__r0.5", "offscreen_overhang__default__r0.25",
                                         "wall_base__default__r0.5", "wall_base__default__r0.25"};

json mergeOf(const std::vector<std::string>& dirs, const std::string& out) {
    std::string args = "merge";
    for (const auto& d : dirs) args += " " + d;
    auto r = runVct(args + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(out + "/results.csv"));
    return readJson(out + "/results.json");
}

}  // namespace

TEST(SweepCli, ResumedAndShardedSweepsEqualOneRun) {
    const std::string tmp = freshTempDir("sweep_cli");
    const std::string spec = writeTinySpec(tmp);

    // One uninterrupted run. The absent shared scene's cases are skipped with a message.
    const std::string full = tmp + "/full";
    auto r = runVct("sweep " + spec + " -o " + full);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("no_such_scene__default__r0.5: skipped, scene file"), std::string::npos) << r.output;
    for (const auto& id : kCases) {
        EXPECT_TRUE(fs::exists(full + "/cases/" + id + "/results.json")) << id;
        EXPECT_TRUE(fs::exists(full + "/cases/" + id + "/case.json")) << id;
    }
    const json fullMerged = mergeOf({full}, tmp + "/merged_full");
    ASSERT_EQ(fullMerged["records"].size(), 12u) << "4 cases x 3 variants";

    // "Interrupted": only shard 0 ran; the full sweep in the same directory must skip its
    // cases (log line, untouched results.json) and run the others.
    const std::string resumed = tmp + "/resumed";
    r = runVct("sweep " + spec + " -o " + resumed + " --shard 0/2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::map<std::string, fs::file_time_type> before;
    for (const auto& id : kCases) {
        const fs::path p = resumed + "/cases/" + id + "/results.json";
        const bool inShard0 = id == kCases[0] || id == kCases[2];  // case indices 0 and 2
        EXPECT_EQ(fs::exists(p), inShard0) << id;
        if (inShard0) before[id] = fs::last_write_time(p);
    }
    r = runVct("sweep " + spec + " -o " + resumed);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const auto& id : kCases) {
        const bool done = before.count(id) != 0;
        EXPECT_EQ(r.output.find(id + ": skipped, done already") != std::string::npos, done) << id << "\n" << r.output;
        EXPECT_EQ(r.output.find(id + ": ran 3 variants") != std::string::npos, !done) << id << "\n" << r.output;
        if (done) {
            EXPECT_EQ(fs::last_write_time(resumed + "/cases/" + id + "/results.json"), before[id]) << id;
        }
    }
    const json resumedMerged = mergeOf({resumed}, tmp + "/merged_resumed");
    EXPECT_EQ(withoutTiming(resumedMerged["records"]), withoutTiming(fullMerged["records"]));

    // Two shards in two directories, merged.
    r = runVct("sweep " + spec + " -o " + tmp + "/s0 --shard 0/2 --no-images");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runVct("sweep " + spec + " -o " + tmp + "/s1 --shard 1/2 --no-images");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const json shardMerged = mergeOf({tmp + "/s0", tmp + "/s1"}, tmp + "/merged_shards");
    EXPECT_EQ(withoutTiming(shardMerged["records"]), withoutTiming(fullMerged["records"]));

    // The merged records carry the case columns, and each (case, kind) group has a front.
    std::map<std::string, int> frontSize;
    for (const json& rec : fullMerged["records"]) {
        EXPECT_TRUE(rec["scene"] == "offscreen_overhang" || rec["scene"] == "wall_base") << rec["scene"];
        EXPECT_EQ(rec["camera"], "default");
        EXPECT_EQ(rec["width"], 64);
        EXPECT_EQ(rec["ref_spp"], 16);
        EXPECT_GT(rec["ref_stderr"].get<double>(), 0.0);
        frontSize[rec["case"].get<std::string>()] += rec["pareto"].get<bool>();
    }
    EXPECT_EQ(frontSize.size(), 4u);
    for (const auto& [id, n] : frontSize) EXPECT_GE(n, 1) << id;
    EXPECT_EQ(fullMerged["records"][0]["case"], kCases[0]);
    EXPECT_EQ(fullMerged["records"][3]["case"], kCases[1]);
}

TEST(SweepCli, BadInputIsAUsageErrorNamingTheField) {
    const std::string tmp = freshTempDir("sweep_cli_bad");
    std::ofstream(tmp + "/bad.json") << R"({"scenes": ["scenes/wall_base.gltf"],
        "methods": [{"method": "gtao", "grid": {"gtao.preset": ["low", "extreme"]}}], "ref_spp": -3})";
    auto r = runVct("sweep " + tmp + "/bad.json -o " + tmp + "/out");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("ref_spp"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(tmp + "/out")) << "nothing written for a bad spec";

    const std::string spec = writeTinySpec(tmp);
    r = runVct("sweep " + spec + " -o " + tmp + "/out --shard 2/2");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--shard"), std::string::npos) << r.output;

    r = runVct("merge " + tmp + "/nothing_here -o " + tmp + "/m");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("nothing_here"), std::string::npos) << r.output;
}
