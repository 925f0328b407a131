// Result provenance (eval/provenance.h): the scene hash against SHA-256's published test
// vectors, and every setting of a method resolved to its default or the record's value.
#include "eval/provenance.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace vct;

TEST(Provenance, SceneHashIsSha256) {
    const std::string dir = vcttest::freshTempDir("provenance");
    // FIPS 180-2's examples: "abc" and the empty message.
    std::ofstream(dir + "/abc.txt", std::ios::binary) << "abc";
    std::ofstream(dir + "/empty.txt", std::ios::binary);
    EXPECT_EQ(fileSha256(dir + "/abc.txt"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(fileSha256(dir + "/empty.txt"), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_THROW(fileSha256(dir + "/missing.gltf"), std::runtime_error);
    const nlohmann::json p = runProvenance(dir + "/abc.txt", 7);
    EXPECT_EQ(p["scene_sha256"], "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(p["seed"], 7);
    EXPECT_FALSE(p["commit"].get<std::string>().empty());
    EXPECT_TRUE(runProvenance("", 0)["scene_sha256"].is_null()) << "a scene without a file";
}

TEST(Provenance, EverySettingResolved) {
    ParamMap params;
    params.set("gtao.slices=7");
    const nlohmann::json p = resolvedParams(MethodKind::AO, "gtao", params);
    EXPECT_EQ(p["gtao.slices"], "7");
    ASSERT_TRUE(p.contains("gtao.steps"));
    EXPECT_FALSE(p["gtao.steps"].get<std::string>().empty()) << "the default, resolved";
    const nlohmann::json v = resolvedParams(MethodKind::AO, "vct", ParamMap());
    EXPECT_EQ(v["vct.cones"], "6");
    EXPECT_EQ(v["vct.lanes"], "1");
    EXPECT_TRUE(resolvedParams(MethodKind::AO, "no-such-method", ParamMap()).empty());
}

// A preset's keys are recorded with the values it gave them, a key given on its own with its own.
TEST(Provenance, PresetsRecordTheValuesTheyGive) {
    ParamMap low;
    low.set("gtao.preset=low");
    const nlohmann::json g = resolvedParams(MethodKind::AO, "gtao", low);
    EXPECT_EQ(g["gtao.slices"], "1");  // XeGTAO's low: 1 slice of 2 steps a side
    EXPECT_EQ(g["gtao.steps"], "2");
    ParamMap converge;
    converge.set("vct.preset=converge");
    converge.set("vct.sharpen=2");
    for (MethodKind kind : {MethodKind::AO, MethodKind::GI}) {
        const nlohmann::json v = resolvedParams(kind, "vct", converge);
        EXPECT_EQ(v["vct.preset"], "converge");
        EXPECT_EQ(v["vct.lanes"], "0");
        EXPECT_EQ(v["vct.lanes-base"], "16");
        EXPECT_EQ(v["vct.aim"], "1");
        EXPECT_EQ(v["vct.level-bias"], "-2");
        EXPECT_EQ(v["vct.grid"], "cube");
        EXPECT_EQ(v["vct.fit-reach"], "lanes");
        EXPECT_EQ(v["vct.voxel.edges"], "sheet");
        EXPECT_EQ(v["vct.sharpen"], "2");
        EXPECT_EQ(v["vct.cones"], "6");
    }
    EXPECT_EQ(resolvedParams(MethodKind::AO, "vct", ParamMap())["vct.sharpen"], "1");
}
