// Writing the sparse voxels to .vdb and reading them back with OpenVDB's own reader.
#include "support/test_scenes.h"
#include "vdb/vdb_io.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace vct {
namespace {

Scene litScene() {
    Scene s;
    uint32_t floor = vcttest::addMaterial(s, glm::vec3(0.6f, 0.5f, 0.4f));
    uint32_t box = vcttest::addMaterial(s, glm::vec3(0.3f), glm::vec3(1.f, 0.5f, 0.f));
    vcttest::addQuad(s, {-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, floor);
    vcttest::addBox(s, {-0.5f, 0, -0.5f}, {0.5f, 1.f, 0.5f}, box);
    Light l;
    l.type = LightType::Point;
    l.position = glm::vec3(1.f, 2.f, 1.f);
    l.color = glm::vec3(5.f);
    s.lights.push_back(l);
    vcttest::finish(s);
    return s;
}

template <typename GridT>
void expectSameGrid(const GridT& written, const openvdb::GridBase::Ptr& readBase) {
    auto read = openvdb::gridPtrCast<GridT>(readBase);
    ASSERT_TRUE(read) << written.getName() << " has the wrong type";
    EXPECT_EQ(read->activeVoxelCount(), written.activeVoxelCount()) << written.getName();
    auto acc = read->getConstAccessor();
    size_t checked = 0;
    for (auto it = written.cbeginValueOn(); it; ++it) {
        typename GridT::ValueType v;
        ASSERT_TRUE(acc.probeValue(it.getCoord(), v)) << written.getName();
        EXPECT_EQ(v, *it) << written.getName();
        ++checked;
    }
    EXPECT_GT(checked, 0u);
    // Same index-to-world mapping.
    const openvdb::Vec3d w0 = written.indexToWorld(openvdb::Vec3d(3, 4, 5));
    const openvdb::Vec3d w1 = read->indexToWorld(openvdb::Vec3d(3, 4, 5));
    EXPECT_NEAR((w0 - w1).length(), 0.0, 1e-9);
}

TEST(VdbIo, RoundTripThroughOpenVdbReader) {
    Scene s = litScene();
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 32, true, 1.f, params);
    const std::string path =
        (std::filesystem::temp_directory_path() / ("vdb_io_test_" + std::to_string(::getpid()) + ".vdb")).string();
    writeVdb(v, path, "lit-box");
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

    // Plain OpenVDB: grids and metadata as documented.
    openvdb::io::File file(path);
    file.open();
    openvdb::MetaMap::Ptr meta = file.getMetadata();
    EXPECT_EQ(meta->metaValue<std::string>("scene"), "lit-box");
    EXPECT_FLOAT_EQ(meta->metaValue<float>("voxel_size"), v.voxelSize);
    EXPECT_EQ(meta->metaValue<int32_t>("levels"), v.levels);
    const openvdb::Vec3s bmax = meta->metaValue<openvdb::Vec3s>("bounds_max");
    EXPECT_NEAR(bmax[1], v.origin.y + v.resolution.y * v.voxelSize, 1e-5);
    expectSameGrid(*v.opacity, file.readGrid("opacity"));
    expectSameGrid(*v.albedo, file.readGrid("albedo"));
    expectSameGrid(*v.normal, file.readGrid("normal"));
    expectSameGrid(*v.emission, file.readGrid("emission"));
    expectSameGrid(*v.radiance, file.readGrid("radiance"));
    expectSameGrid(*v.opacityLevels[2], file.readGrid("opacity_L2"));
    expectSameGrid(*v.radianceLevels[3], file.readGrid("radiance_L3"));
    // A world point maps to the same voxel as in voxel units.
    auto opacity = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("opacity"));
    glm::vec3 wp(-1.7f, 0.f, 1.3f);
    glm::vec3 vp = (wp - v.origin) / v.voxelSize;
    openvdb::Coord viaTransform = opacity->transform().worldToIndexCellCentered(openvdb::Vec3d(wp.x, wp.y, wp.z));
    EXPECT_EQ(viaTransform, openvdb::Coord(int(std::floor(vp.x)), int(std::floor(vp.y)), int(std::floor(vp.z))));
    file.close();

    // Our reader: the whole scene, same counts.
    SparseVoxelScene r = readVdb(path);
    EXPECT_EQ(r.stats.activeVoxels, v.stats.activeVoxels);
    EXPECT_EQ(r.resolution, v.resolution);
    EXPECT_EQ(r.levels, v.levels);
    EXPECT_EQ(r.opacityLevels.size(), v.opacityLevels.size());
    EXPECT_EQ(r.radianceLevels.size(), v.radianceLevels.size());
    EXPECT_EQ(r.sceneName, "lit-box");
    EXPECT_EQ(r.stats.leafNodes, v.stats.leafNodes);
    std::filesystem::remove(path);
}

TEST(VdbIo, ReadErrorsNameTheFile) {
    EXPECT_THROW(readVdb("/nonexistent/dir/none.vdb"), std::runtime_error);
    const std::string path = (std::filesystem::temp_directory_path() / "vdb_io_test_garbage.vdb").string();
    { std::ofstream(path) << "not a vdb"; }
    try {
        readVdb(path);
        ADD_FAILURE() << "garbage read without error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace vct
