// vct.preset: what each table reads from it (cone/cone_settings.cpp, vct/vct_settings.cpp,
// voxelize/voxel_settings.cpp), that a key given on its own wins over it, and the requests it
// cannot serve refused with a message naming the preset.
#include "cone/cone_settings.h"
#include "core/errors.h"
#include "vct/vct_settings.h"
#include "voxelize/voxel_settings.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace vct {
namespace {

ParamMap params(std::initializer_list<const char*> kv) {
    ParamMap p;
    for (const char* s : kv) p.set(s);
    return p;
}

// The message of the UsageError reading every table of `p` throws; empty when none does.
std::string usageErrorOf(const ParamMap& p) {
    try {
        (void)readConeSettings(p);
        (void)vctSettings().read(p);
        (void)voxelSettings().read(p);
    } catch (const UsageError& e) {
        return e.what();
    }
    return {};
}

TEST(VctPreset, ConvergeSetsTheLanesMarchOverSheets) {
    const ParamMap p = params({"vct.preset=converge"});
    const ConeSettings cone = readConeSettings(p);
    EXPECT_EQ(cone.lanes, 0);
    EXPECT_EQ(cone.lanesBase, 16);
    EXPECT_EQ(cone.sharpen, 4.f);
    EXPECT_TRUE(cone.aim);
    EXPECT_EQ(cone.levelBias, -2.f);
    const VctSettings vs = vctSettings().read(p);
    EXPECT_EQ(vs.grid, "cube");
    EXPECT_EQ(vs.fitReach, "lanes");
    EXPECT_EQ(voxelSettings().read(p).edges, VoxelEdges::Sheet);
    // What it leaves alone keeps its default: the cone set, the offset, the levels' encoding.
    const ConeSettings plain;
    EXPECT_EQ(cone.coneCount, plain.coneCount);
    EXPECT_EQ(cone.offsetVoxels, plain.offsetVoxels);
    EXPECT_EQ(cone.opacity, plain.opacity);
    EXPECT_TRUE(p.unusedKeys().empty());

    // Without it, or with "default", every key reads its own default.
    for (const ParamMap& q : {ParamMap{}, params({"vct.preset=default"})}) {
        const ConeSettings c = readConeSettings(q);
        EXPECT_EQ(c.lanes, plain.lanes);
        EXPECT_EQ(c.lanesBase, plain.lanesBase);
        EXPECT_EQ(c.sharpen, plain.sharpen);
        EXPECT_EQ(c.aim, plain.aim);
        EXPECT_EQ(c.levelBias, plain.levelBias);
        EXPECT_EQ(vctSettings().read(q).grid, "fit");
        EXPECT_EQ(vctSettings().read(q).fitReach, "cones");
        EXPECT_EQ(voxelSettings().read(q).edges, VoxelEdges::Occupied);
    }
}

TEST(VctPreset, AKeyGivenOnItsOwnWins) {
    const ParamMap p = params({"vct.preset=converge", "vct.sharpen=2", "vct.aim=0", "vct.level-bias=-1",
                               "vct.grid=fit", "vct.voxel.edges=coverage", "vct.cones=16"});
    const ConeSettings cone = readConeSettings(p);
    EXPECT_EQ(cone.sharpen, 2.f);
    EXPECT_FALSE(cone.aim);
    EXPECT_EQ(cone.levelBias, -1.f);
    EXPECT_EQ(cone.coneCount, 16);
    EXPECT_EQ(cone.lanes, 0);  // the preset's, not given
    EXPECT_EQ(vctSettings().read(p).grid, "fit");
    EXPECT_EQ(voxelSettings().read(p).edges, VoxelEdges::Coverage);

    // Lanes given on their own keep auto's default base (the base only counts auto's lanes).
    const ConeSettings fixed = readConeSettings(params({"vct.preset=converge", "vct.lanes=4"}));
    EXPECT_EQ(fixed.lanes, 4);
    EXPECT_EQ(fixed.lanesBase, ConeSettings{}.lanesBase);
    EXPECT_EQ(usageErrorOf(params({"vct.preset=converge", "vct.lanes=4"})), "");

    // A whole-scene region has nothing to fit: the region's reach stays the cones'.
    const VctSettings scene = vctSettings().read(params({"vct.preset=converge", "vct.region=scene"}));
    EXPECT_EQ(scene.fitReach, "cones");
    EXPECT_EQ(scene.grid, "cube");
}

TEST(VctPreset, WhatItCannotServeIsRefusedNamingIt) {
    EXPECT_NE(usageErrorOf(params({"vct.preset=converge", "vct.clipmap.levels=2"})).find("vct.preset=converge"),
              std::string::npos);
    const std::string iso = usageErrorOf(params({"vct.preset=converge", "vct.aniso=0"}));
    EXPECT_NE(iso.find("vct.preset=converge"), std::string::npos) << iso;
    EXPECT_NE(iso.find("vct.sharpen=1"), std::string::npos) << iso;
    EXPECT_EQ(usageErrorOf(params({"vct.preset=converge", "vct.aniso=0", "vct.sharpen=1"})), "");
    const std::string bad = usageErrorOf(params({"vct.preset=fast"}));
    EXPECT_NE(bad.find("vct.preset=fast"), std::string::npos) << bad;
    EXPECT_NE(bad.find("default|converge"), std::string::npos) << bad;
}

}  // namespace
}  // namespace vct
