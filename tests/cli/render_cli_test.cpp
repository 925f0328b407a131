// The `vct render` contract as a user meets it: images, --stats, --explain, exit codes and
// no partial output on bad input.
#include "eval/image_io.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

using namespace vcttest;
namespace fs = std::filesystem;

namespace {

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

}  // namespace

TEST(RenderCli, CornellBoxRegionsAreDistinct) {
    std::string dir = freshTempDir("cornell");
    std::string exr = dir + "/cb.exr";
    auto r = runVct("render scenes/cornell_box.gltf --size 128 --sky 0 --aov beauty,direct,emission,albedo -o " + exr);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    vct::Image img = vct::readImage(exr);
    auto names = vct::channelNamesOf(exr);
    ASSERT_EQ(img.channels, 12) << "beauty RGB + direct, emission, albedo RGB";
    auto channel = [&](const std::string& name) {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return int(i);
        ADD_FAILURE() << "no channel " << name;
        return 0;
    };
    const int er = channel("emission.R"), dr = channel("direct.R"), ar = channel("albedo.R"), ag = channel("albedo.G");
    // Classify pixels by what the G-buffer says they are, then compare their radiance.
    double emissive = 0, lit = 0, shadow = 0;
    int nEmissive = 0, nLit = 0, nShadow = 0;
    double redWall = 0, greenWall = 0;
    int nRed = 0, nGreen = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            float e = img.at(x, y, er), d = img.at(x, y, dr);
            float a = img.at(x, y, ar), g = img.at(x, y, ag);
            if (e > 0.5f) { emissive += img.at(x, y, channel("R")); ++nEmissive; continue; }
            if (a > 0.3f && a > 3.f * g) { redWall += img.at(x, y, channel("R")); ++nRed; }
            if (g > 0.3f && g > 2.f * a) { greenWall += img.at(x, y, channel("G")); ++nGreen; }
            if (y > img.height * 3 / 4 && a > 0.5f && g > 0.5f) {  // white floor near the bottom
                if (d > 0.05f) { lit += d; ++nLit; } else { shadow += d; ++nShadow; }
            }
        }
    ASSERT_GT(nEmissive, 10);
    ASSERT_GT(nLit, 100);
    ASSERT_GT(nShadow, 20) << "the boxes cast shadows on the floor";
    ASSERT_GT(nRed, 100);
    ASSERT_GT(nGreen, 100);
    EXPECT_GT(emissive / nEmissive, 2.0 * lit / nLit) << "the emissive ceiling is the brightest region";
    EXPECT_LT(shadow / nShadow, 0.2 * lit / nLit) << "shadowed floor is much darker than lit floor";
    EXPECT_GT(redWall / nRed, 0.05);
    EXPECT_GT(greenWall / nGreen, 0.05);
}

TEST(RenderCli, PngIsWrittenAndStatsHaveTheContractFields) {
    std::string dir = freshTempDir("stats");
    auto r = runVct("render scenes/cornell_box.gltf --size 64x48 -o " + dir + "/a.png --stats " + dir + "/s.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    vct::Image png = vct::readImage(dir + "/a.png");
    EXPECT_EQ(png.width, 64);
    EXPECT_EQ(png.height, 48);
    auto j = readJson(dir + "/s.json");
    for (const char* key : {"passes", "total_ms", "width", "height", "gl_renderer", "cores", "passes_run",
                            "passes_skipped", "scene"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["width"], 64);
    EXPECT_EQ(j["height"], 48);
    EXPECT_GT(j["scene"]["triangles"].get<int>(), 10);
    EXPECT_GE(j["scene"]["lights"].get<int>(), 1);
    // The process's peak memory: at least the 64x48 render's own targets, and far below a
    // gigabyte for a box of 32 triangles.
    ASSERT_TRUE(j.contains("peak_rss_bytes"));
    EXPECT_GT(j["peak_rss_bytes"].get<double>(), 4.0 * 1024 * 1024);
    EXPECT_LT(j["peak_rss_bytes"].get<double>(), 1024.0 * 1024 * 1024);
    ASSERT_FALSE(j["passes"].empty());
    for (const auto& p : j["passes"]) {
        EXPECT_TRUE(p.contains("name"));
        EXPECT_GE(p["wall_ms"].get<double>(), 0.0);
        EXPECT_TRUE(p.contains("gpu_ms"));
    }
    // A fresh process builds the programs its passes use: their time is in total_ms, not in
    // the passes' nor in frame_ms, which is total_ms less the scene's static passes and them.
    const double buildMs = j["program_build_ms"].get<double>();
    EXPECT_GT(buildMs, 0.0);
    double staticMs = 0.0, passMs = 0.0;
    for (const auto& p : j["passes"]) {
        passMs += p["wall_ms"].get<double>();
        if (p["reruns"] == "when_scene_changes") staticMs += p["wall_ms"].get<double>();
    }
    EXPECT_NEAR(j["frame_ms"].get<double>(), j["total_ms"].get<double>() - staticMs - buildMs, 1e-6);
    EXPECT_LE(passMs + buildMs, j["total_ms"].get<double>() + 1e-6);
    // The per-frame passes' GPU time: a number where every one has gpu_ms, else null.
    ASSERT_TRUE(j.contains("frame_gpu_ms"));
    bool allTimed = false;
    double gpuSum = 0.0;
    for (const auto& p : j["passes"])
        if (p["reruns"] == "every_frame") {
            allTimed = !p["gpu_ms"].is_null();
            if (!allTimed) break;
            gpuSum += p["gpu_ms"].get<double>();
        }
    if (allTimed) EXPECT_NEAR(j["frame_gpu_ms"].get<double>(), gpuSum, 1e-9);
    else EXPECT_TRUE(j["frame_gpu_ms"].is_null());
    for (const auto& s : j["passes_skipped"]) {
        EXPECT_TRUE(s.contains("pass"));
        EXPECT_FALSE(s["reason"].get<std::string>().empty());
    }
}

TEST(RenderCli, DepthAloneRunsOnlyTheGBufferPass) {
    std::string dir = freshTempDir("depth");
    auto r = runVct("render scenes/cornell_box.gltf --size 32 --ao gtao --aov depth -o " + dir + "/d.exr --stats " +
                    dir + "/s.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto j = readJson(dir + "/s.json");
    EXPECT_EQ(j["passes_run"], nlohmann::json::array({"gbuffer"}));
    vct::Image d = vct::readImage(dir + "/d.exr");
    EXPECT_EQ(d.channels, 1);
}

TEST(RenderCli, ExplainPrintsRunAndSkippedPasses) {
    std::string dir = freshTempDir("explain");
    auto r = runVct("render scenes/cornell_box.gltf --size 32 --explain -o " + dir + "/x.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("passes to run:"), std::string::npos);
    EXPECT_NE(r.output.find("passes left out:"), std::string::npos);
    EXPECT_NE(r.output.find("voxelize: no method reads voxels"), std::string::npos) << r.output;
    // Injection says its lights may take several dispatches where there is more than one.
    const std::string split = "lights over as many dispatches as the loop budget needs";
    auto one = runVct("render scenes/cornell_box.gltf --size 16 --gi vct --voxel-res 16 --explain -o " + dir + "/c.png");
    ASSERT_EQ(one.exitCode, 0) << one.output;
    EXPECT_NE(one.output.find("inject: direct light"), std::string::npos) << one.output;
    EXPECT_EQ(one.output.find(split), std::string::npos) << one.output;
    auto two = runVct("render scenes/default.gltf --size 16 --gi vct --voxel-res 16 --explain -o " + dir + "/d.png");
    ASSERT_EQ(two.exitCode, 0) << two.output;
    EXPECT_NE(two.output.find("2 " + split), std::string::npos) << two.output;
    // The cone passes' line says what their cones do beyond the set (`args` -> `says`), and not
    // what they do not (`unsaid`).
    auto explainCones = [&](const std::string& args, const std::string& says, const std::string& unsaid,
                            const std::string& png) {
        auto r = runVct("render scenes/cornell_box.gltf --size 16 --ao vct " + args + " --explain -o " + dir + "/" + png);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
        if (!unsaid.empty()) {
            EXPECT_EQ(r.output.find(unsaid), std::string::npos) << r.output;
        }
    };
    // The directional levels sharpened; cones aimed at their rays' points at R; levels tapered
    // to what remains of R near its end; a footprint's level moved; how many lanes auto marches
    // when its base resolution moves: (32 / 16)^2 at 32^3; the caps' parts below the plane
    // mirrored.
    explainCones("--voxel-res 16 --param vct.sharpen=4", "sharpened along their axis (vct.sharpen=4)", "(vct.aim)",
                 "s.png");
    explainCones("--voxel-res 16 --param vct.aim=1", "rays' points at the maximum distance (vct.aim)",
                 "(vct.end-taper)", "a.png");
    explainCones("--voxel-res 16 --param vct.end-taper=1",
                 "no further than the maximum distance near its end (vct.end-taper)", "(vct.aim)", "t.png");
    explainCones("--voxel-res 16 --param vct.level-bias=-1",
                 "sampling the level log2(footprint) - 1 (vct.level-bias=-1)", "(vct.end-taper)", "b.png");
    explainCones("--voxel-res 32 --param vct.lanes=0 --param vct.lanes-base=16",
                 "each marched as 4 lanes (vct.lanes=auto at 32^3 with vct.lanes-base=16)", "", "l.png");
    explainCones("--voxel-res 16 --param vct.below-plane=mirror", "reflected above it (vct.below-plane=mirror)",
                 "(vct.aim)", "m.png");
    // The voxelize pass's line says when level 0 holds the columns' coverage.
    explainCones("--voxel-res 16 --param vct.voxel.edges=coverage",
                 "the share of its column its sheets cover (vct.voxel.edges=coverage)", "(vct.aim)", "e.png");
    explainCones("--voxel-res 16", "voxelize: world-space occupancy", "(vct.voxel.edges=coverage)", "o.png");
    explainCones("--voxel-res 16 --param vct.voxel.edges=sheet",
                 "where in it they lie, the pixels' AO and GI cones meet them there, and an AO lane meeting a "
                 "sheet near the maximum distance is closed by its share that meets it before "
                 "(vct.voxel.edges=sheet)",
                 "(vct.voxel.edges=coverage)", "s.png");
}

TEST(RenderCli, BadInputFailsCleanlyWithoutOutput) {
    std::string dir = freshTempDir("bad");
    const std::string out = dir + "/never.png";
    struct Case { std::string args; int code; std::string says; };
    std::ofstream(dir + "/broken.gltf") << "{ \"asset\": {\"version\": \"2.0\"}, \"meshes\": [ ";
    const Case cases[] = {
        {"render " + dir + "/missing.gltf -o " + out, 1, "missing.gltf"},
        {"render " + dir + "/broken.gltf -o " + out, 1, "broken.gltf"},
        {"render scenes/cornell_box.gltf --ao nonsense -o " + out, 2, "--ao"},
        {"render scenes/cornell_box.gltf --gi magic -o " + out, 2, "--gi"},
        {"render scenes/cornell_box.gltf --size 0 -o " + out, 2, "--size"},
        {"render scenes/cornell_box.gltf --size 12xq -o " + out, 2, "--size"},
        {"render scenes/cornell_box.gltf --radius -1 -o " + out, 2, "--radius"},
        {"render scenes/cornell_box.gltf --eye 1,2 --target 0,0,0 -o " + out, 2, "1,2"},
        {"render scenes/cornell_box.gltf --camera nope -o " + out, 2, "nope"},
        {"render scenes/cornell_box.gltf --param gtao.slices=3 -o " + out, 2, "gtao.slices"},
        {"render scenes/cornell_box.gltf --param novalue -o " + out, 2, "novalue"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.sharpen=4 --param vct.aniso=0 -o " + out, 2,
         "vct.sharpen"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.sharpen=4 --param vct.clipmap.levels=3 -o " + out, 2,
         "vct.sharpen"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.grid-shift=0.5 --param vct.clipmap.levels=3 -o " + out,
         2, "vct.grid-shift"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.lanes-base=16 -o " + out, 2, "needs vct.lanes=0"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.level-bias=-3 -o " + out, 2, "vct.level-bias"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.lanes=0 --param vct.lanes-base=2 -o " + out, 2,
         "vct.lanes-base"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.grid-shift=1.5 -o " + out, 2, "vct.grid-shift"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.fit-reach=far -o " + out, 2, "vct.fit-reach"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.below-plane=sky -o " + out, 2, "vct.below-plane"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.fit-reach=lanes --param vct.region=scene -o " + out, 2,
         "vct.region=scene fits none"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.preset=fast -o " + out, 2, "default|converge"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.preset=converge --param vct.clipmap.levels=3 -o " + out,
         2, "vct.preset=converge"},
        {"render scenes/cornell_box.gltf --ao vct --param vct.preset=converge --param vct.aniso=0 -o " + out, 2,
         "add --param vct.sharpen=1"},
        {"render scenes/cornell_box.gltf --aov bogus -o " + out, 2, "bogus"},
        {"render scenes/cornell_box.gltf -o " + dir + "/x.tiff", 2, "x.tiff"},
        {"render scenes/cornell_box.gltf --frobnicate -o " + out, 2, "frobnicate"},
        {"render", 2, "scene"},
    };
    for (const auto& c : cases) {
        auto r = runVct(c.args);
        EXPECT_EQ(r.exitCode, c.code) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.args;
    }
    // No temporary files left behind either.
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_TRUE(e.path().filename() == "broken.gltf") << e.path();
}

TEST(RenderCli, HelpOnEverySubcommand) {
    for (const char* sub : {"render", "info"}) {
        auto r = runVct(std::string(sub) + " --help");
        EXPECT_EQ(r.exitCode, 0) << sub;
        EXPECT_NE(r.output.find("--"), std::string::npos) << sub;
    }
    auto r = runVct("render --help-params");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.output.find("gtao."), std::string::npos) << r.output;
}

TEST(RenderCli, InfoPrintsRendererAndCounts) {
    auto r = runVct("info scenes/cornell_box.gltf");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gl_renderer:"), std::string::npos);
    EXPECT_NE(r.output.find("triangles: 36\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("materials: 4 (alpha-masked: 0)\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("vertex colours: no\n"), std::string::npos) << r.output;

    // One triangle with red, green and blue corners and an alpha-masked material.
    const std::string dir = freshTempDir("info_colours");
    const std::string path = dir + "/coloured.gltf";
    std::ofstream(path) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}], "materials": [{"alphaMode": "MASK"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "material": 0}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3,
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "type": "VEC3", "count": 3}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
        "buffers": [{"byteLength": 72, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/"}]})";
    r = runVct("info " + path);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("materials: 1 (alpha-masked: 1)\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("vertex colours: yes\n"), std::string::npos) << r.output;
}

TEST(RenderCli, SponzaRendersTextured) {
    const std::string sponza = sharedScenesDir() + "/mcguire_sponza.glb";
    if (!fs::exists(sponza)) GTEST_SKIP() << "third-party scene not found: " << sponza << " (set VCT_SHARED_SCENES)";
    std::string dir = freshTempDir("sponza");
    auto r = runVct("render " + sponza + " --size 64 --eye -10,2,0 --target 10,4,0 --fov 60 --aov albedo -o " + dir +
                    "/a.exr");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    vct::Image a = vct::readImage(dir + "/a.exr");
    // Textured: many distinct albedo values (an untextured render has one per material).
    std::set<int> distinct;
    for (size_t i = 0; i < a.pixels.size(); i += 3) distinct.insert(int(a.pixels[i] * 1000.f));
    EXPECT_GT(distinct.size(), 60u);
}

// The baselines reach every list through the registry alone: --ao / --gi, --help-params (each
// key with its default and range) and compare's default methods (every AO method but the
// reference).
TEST(RenderCli, BaselinesAreListedEverywhere) {
    auto help = runVct("render --help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    for (const char* name : {"vbao", "rtao-denoised", "ssil", "pt-denoised"})
        EXPECT_NE(help.output.find(name), std::string::npos) << name << "\n" << help.output;
    auto params = runVct("render --help-params");
    ASSERT_EQ(params.exitCode, 0) << params.output;
    for (const char* key : {"vbao.slices", "vbao.steps", "vbao.thickness", "vbao.radius-multiplier",
                            "vbao.sample-power", "ssil.slices", "ssil.steps", "ssil.thickness", "ssil.extent",
                            "ssil.filter", "atrous.iterations", "atrous.sigma-depth", "atrous.sigma-normal",
                            "atrous.sigma-albedo", "rtao-denoised.spp", "pt-denoised.spp", "pt-denoised.bounces"})
        EXPECT_NE(params.output.find(key), std::string::npos) << key;
    auto compare = runVct("compare --help");
    ASSERT_EQ(compare.exitCode, 0) << compare.output;
    const size_t list = compare.output.find("ssao-crytek,");
    ASSERT_NE(list, std::string::npos) << compare.output;
    const std::string defaults = compare.output.substr(list, compare.output.find_first_of(" \n]", list) - list);
    for (const char* name : {"gtao", "vbao", "vct", "rtao-denoised"})
        EXPECT_NE(("," + defaults + ",").find(std::string(",") + name + ","), std::string::npos) << name << ": " << defaults;
    EXPECT_EQ(("," + defaults + ",").find(",reference,"), std::string::npos) << defaults;
}
