// `vct render --path --frames` and `vct compare --path` as a user meets them: numbered frames,
// a still path equal to the still render, a killed run resumed to the same frames, a manifest
// that refuses another sequence's frames, and clear errors before any output.
#include "eval/image_io.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace vcttest;
namespace fs = std::filesystem;

namespace {

std::string bytesOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string writePath(const std::string& dir, const nlohmann::json& keys, const std::string& name = "path.json") {
    const std::string file = dir + "/" + name;
    std::ofstream(file) << nlohmann::json({{"interpolation", "catmull-rom"}, {"keys", keys}}).dump(2);
    return file;
}

nlohmann::json key(double t, const std::vector<float>& eye, const std::vector<float>& target) {
    return {{"time", t}, {"eye", eye}, {"target", target}, {"fov", 50}};
}

const std::string kScene = "scenes/offscreen_overhang.gltf";
const std::string kMethods = " --size 40x32 --ao vct --voxel-res 32 --aov ao,beauty";

}  // namespace

TEST(SequenceCli, AStillPathRendersTheStillImageOnEveryFrame) {
    const std::string dir = freshTempDir("seq_still");
    const std::string path = writePath(dir, {key(0, {0, 1, 2.5f}, {0, 0.2f, 0}), key(1, {0, 1, 2.5f}, {0, 0.2f, 0})});
    auto still = runVct("render " + kScene + kMethods + " --fov 50 --eye 0,1,2.5 --target 0,0.2,0 -o " + dir + "/still.exr");
    ASSERT_EQ(still.exitCode, 0) << still.output;
    auto seq = runVct("render " + kScene + kMethods + " --path " + path + " --frames 3 -o " + dir + "/f.exr");
    ASSERT_EQ(seq.exitCode, 0) << seq.output;
    const std::string want = bytesOf(dir + "/still.exr");
    for (const char* f : {"f_0000.exr", "f_0001.exr", "f_0002.exr"}) {
        ASSERT_TRUE(fs::exists(dir + "/" + f)) << f;
        vct::Image a = vct::readImage(dir + "/still.exr"), b = vct::readImage(dir + "/" + f);
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_EQ(a.pixels, b.pixels) << f << " differs from the still render";
    }
    EXPECT_TRUE(fs::exists(dir + "/f.sequence.json"));
}

TEST(SequenceCli, AKilledRunResumesToTheSameFrames) {
    const std::string dir = freshTempDir("seq_resume");
    const std::string path = writePath(dir, {key(0, {-0.6f, 1, 2.5f}, {0, 0.2f, 0}), key(1, {0, 1.1f, 2.4f}, {0, 0.2f, 0}),
                                             key(2, {0.6f, 1, 2.5f}, {0, 0.2f, 0})});
    const std::string args = "render " + kScene + kMethods + " --path " + path + " --frames 5 --stats ";
    auto whole = runVct(args + dir + "/whole.json -o " + dir + "/whole/f.png");
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    // A run killed after frame 2: frames 0-2 whole, frame 3 a truncated temporary, no 4.
    auto cut = runVct(args + dir + "/cut.json -o " + dir + "/cut/f.png");
    ASSERT_EQ(cut.exitCode, 0) << cut.output;
    fs::remove(dir + "/cut/f_0003.png");
    fs::remove(dir + "/cut/f_0004.png");
    std::ofstream(dir + "/cut/f_0003.tmp999_0.png") << "\x89PNG truncated";
    const auto kept = fs::last_write_time(dir + "/cut/f_0001.png");
    auto resumed = runVct(args + dir + "/resumed.json -o " + dir + "/cut/f.png");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("3 already written"), std::string::npos) << resumed.output;
    for (int f = 0; f < 5; ++f) {
        const std::string name = "/f_000" + std::to_string(f) + ".png";
        EXPECT_EQ(bytesOf(dir + "/whole" + name), bytesOf(dir + "/cut" + name)) << name;
    }
    EXPECT_EQ(fs::last_write_time(dir + "/cut/f_0001.png"), kept) << "a kept frame was rendered again";
    EXPECT_FALSE(fs::exists(dir + "/cut/f_0003.tmp999_0.png")) << "the killed run's temporary is left";
    std::ifstream in(dir + "/resumed.json");
    EXPECT_EQ(nlohmann::json::parse(in)["frames"].size(), 2u) << "only frames 3 and 4 were rendered";
    // Frames along a moving path differ.
    EXPECT_NE(bytesOf(dir + "/whole/f_0000.png"), bytesOf(dir + "/whole/f_0004.png"));

    // The same -o with other settings: refused, nothing overwritten.
    auto other = runVct("render " + kScene + kMethods + " --radius 0.3 --path " + path + " --frames 5 -o " + dir +
                        "/cut/f.png");
    EXPECT_EQ(other.exitCode, 2) << other.output;
    EXPECT_NE(other.output.find("f.sequence.json"), std::string::npos) << other.output;
}

TEST(SequenceCli, BadPathsAreClearErrorsBeforeAnyOutput) {
    const std::string dir = freshTempDir("seq_errors");
    std::ofstream(dir + "/bad.json") << R"({"keys": [{"time": 0, "eye": [0, 1], "target": [0, 0, 0]}]})";
    auto bad = runVct("render " + kScene + " --size 16 --path " + dir + "/bad.json --frames 2 -o " + dir + "/x/f.png");
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_NE(bad.output.find("bad.json: keys[0].eye"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir + "/x"));
    auto missing = runVct("render " + kScene + " --size 16 --path " + dir + "/none.json --frames 2 -o " + dir + "/f.png");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("--path"), std::string::npos) << missing.output;
    auto alone = runVct("render " + kScene + " --size 16 --frames 2 -o " + dir + "/f.png");
    EXPECT_EQ(alone.exitCode, 2) << alone.output;
    auto anim = runVct("render " + kScene + " --size 16 --path gltf:nothing --frames 2 -o " + dir + "/f.png");
    EXPECT_EQ(anim.exitCode, 2) << anim.output;
    EXPECT_NE(anim.output.find("nothing"), std::string::npos) << anim.output;
    // A path that names an animation the scene does not have.
    const std::string named = dir + "/named.json";
    std::ofstream(named) << R"({"animation": "nope", "keys": [{"time": 0, "eye": [0, 1, 3], "target": [0, 0, 0]}]})";
    auto nope = runVct("render " + kScene + " --size 16 --path " + named + " --frames 2 -o " + dir + "/n/f.png");
    EXPECT_EQ(nope.exitCode, 2) << nope.output;
    EXPECT_NE(nope.output.find("animation 'nope' moves no camera, light or object"), std::string::npos) << nope.output;
    EXPECT_FALSE(fs::exists(dir + "/n"));
}

TEST(SequenceCli, CompareAlongAPathWritesPerFrameRecords) {
    const std::string dir = freshTempDir("seq_compare");
    const std::string path = writePath(dir, {key(0, {-0.3f, 1, 2.5f}, {0, 0.2f, 0}), key(1, {0.3f, 1, 2.5f}, {0, 0.2f, 0})});
    auto r = runVct("compare " + kScene + " --size 32x24 --voxel-res 32 --methods vct,gtao --ref-spp 16 --runs 1 --path " +
                    path + " --frames 3 -o " + dir + "/out");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("instability"), std::string::npos) << r.output;
    std::ifstream in(dir + "/out/results.json");
    nlohmann::json doc = nlohmann::json::parse(in);
    EXPECT_EQ(doc["frames"], 3);
    ASSERT_EQ(doc["records"].size(), 2u);
    for (const auto& rec : doc["records"]) {
        EXPECT_EQ(rec["per_frame"]["rmse"].size(), 3u);
        EXPECT_TRUE(rec["temporal"].contains("instability"));
        EXPECT_TRUE(fs::exists(dir + "/out/" + rec["frames_dir"].get<std::string>() + "/0002.png"));
    }
    EXPECT_TRUE(fs::exists(dir + "/out/frames/reference_ao/0000.png"));
    EXPECT_TRUE(fs::exists(dir + "/out/results.csv"));
}

TEST(SequenceCli, AMovingLightRerunsInjectionOnlyAndThePlanSaysSo) {
    const std::string dir = freshTempDir("seq_light");
    auto r = runVct("render scenes/cornell_moving_light.gltf --size 24 --gi vct --voxel-res 16 --sky 0 --explain "
                    "--path scenes/paths/cornell_light_sweep.json --frames 3 --stats " + dir + "/s.json -o " + dir +
                    "/f.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("lights move with animation 'light_sweep'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("the voxels themselves are kept"), std::string::npos) << r.output;
    // The light moves: the frames differ.
    EXPECT_NE(bytesOf(dir + "/f_0000.png"), bytesOf(dir + "/f_0002.png"));
}

TEST(SequenceCli, AMovingObjectRebuildsItsSceneAndThePlanSaysSo) {
    const std::string dir = freshTempDir("seq_object");
    auto r = runVct("render scenes/cornell_moving_box.gltf --size 24 --ao vct --voxel-res 16 --radius 0.5 --explain "
                    "--path scenes/paths/cornell_box_slide.json --frames 3 --stats " + dir + "/s.json -o " + dir +
                    "/f.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("objects move with animation 'box_slide'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("rebuilt in full"), std::string::npos) << r.output;
    EXPECT_NE(bytesOf(dir + "/f_0000.png"), bytesOf(dir + "/f_0002.png")) << "the box moved but the frames did not";
    auto info = runVct("info scenes/cornell_moving_box.gltf");
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("object animations: 0 'box_slide' (node"), std::string::npos) << info.output;
}
