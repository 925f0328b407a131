#include "vdb/vdb_io.h"

#include "core/errors.h"
#include "vdb/sparse_detail.h"

#include <glm/gtc/matrix_transform.hpp>
#include <openvdb/io/File.h>

#include <cstdio>
#include <stdexcept>

namespace vct {

namespace {

using namespace vdbdetail;

openvdb::Vec3s toVdb(const glm::vec3& v) { return openvdb::Vec3s(v.x, v.y, v.z); }
glm::vec3 fromVdb(const openvdb::Vec3s& v) { return glm::vec3(v[0], v[1], v[2]); }

template <typename GridT>
typename GridT::Ptr readTyped(openvdb::io::File& file, const std::string& name, const std::string& path) {
    if (!file.hasGrid(name)) throw std::runtime_error("readVdb: " + path + " has no grid '" + name + "'");
    auto grid = openvdb::gridPtrCast<GridT>(file.readGrid(name));
    if (!grid) throw std::runtime_error("readVdb: grid '" + name + "' in " + path + " has an unexpected type");
    return grid;
}

}  // namespace

void writeVdb(const SparseVoxelScene& voxels, const std::string& path, const std::string& sceneName) {
    ensureOpenVdb();
    if (!voxels.opacity || !voxels.albedo || !voxels.normal || !voxels.emission)
        throw InternalError("writeVdb", "the sparse voxels are incomplete (voxelize first)");
    openvdb::GridPtrVec grids;
    auto add = [&](const openvdb::GridBase::Ptr& g, int level) {
        g->insertMeta("level", openvdb::Int32Metadata(level));
        grids.push_back(g);
    };
    add(voxels.opacity, 0);
    add(voxels.albedo, 0);
    add(voxels.normal, 0);
    add(voxels.emission, 0);
    if (voxels.radiance) add(voxels.radiance, 0);
    for (size_t k = 1; k < voxels.opacityLevels.size(); ++k) add(voxels.opacityLevels[k], int(k));
    for (size_t k = 1; k < voxels.radianceLevels.size(); ++k) add(voxels.radianceLevels[k], int(k));
    for (size_t k = 1; k < voxels.normalLevels.size(); ++k) add(voxels.normalLevels[k], int(k));

    openvdb::MetaMap meta;
    meta.insertMeta("scene", openvdb::StringMetadata(sceneName));
    meta.insertMeta("generator", openvdb::StringMetadata("vct sparse voxelizer (src/vdb)"));
    meta.insertMeta("voxel_size", openvdb::FloatMetadata(voxels.voxelSize));
    meta.insertMeta("origin", openvdb::Vec3SMetadata(toVdb(voxels.origin)));
    meta.insertMeta("resolution", openvdb::Vec3IMetadata(
                                      openvdb::Vec3i(voxels.resolution.x, voxels.resolution.y, voxels.resolution.z)));
    meta.insertMeta("levels", openvdb::Int32Metadata(voxels.levels));
    meta.insertMeta("bounds_min", openvdb::Vec3SMetadata(toVdb(voxels.origin)));
    meta.insertMeta("bounds_max", openvdb::Vec3SMetadata(
                                      toVdb(voxels.origin + glm::vec3(voxels.resolution) * voxels.voxelSize)));

    const std::string tmp = path + ".tmp";
    try {
        openvdb::io::File file(tmp);
        file.write(grids, meta);
        file.close();
    } catch (const openvdb::Exception& e) {
        std::remove(tmp.c_str());
        throw std::runtime_error("writeVdb: cannot write " + tmp + ": " + e.what());
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error("writeVdb: cannot rename " + tmp + " to " + path);
    }
}

SparseVoxelScene readVdb(const std::string& path) {
    ensureOpenVdb();
    openvdb::io::File file(path);
    try {
        file.open();
    } catch (const openvdb::Exception& e) {
        throw std::runtime_error("readVdb: cannot open " + path + ": " + e.what());
    }
    openvdb::MetaMap::Ptr meta = file.getMetadata();
    auto need = [&](const std::string& key) {
        if (!(*meta)[key]) throw std::runtime_error("readVdb: " + path + " lacks metadata '" + key + "'");
    };
    for (const char* k : {"voxel_size", "origin", "resolution", "levels"}) need(k);
    SparseVoxelScene v;
    v.voxelSize = meta->metaValue<float>("voxel_size");
    v.origin = fromVdb(meta->metaValue<openvdb::Vec3s>("origin"));
    const openvdb::Vec3i res = meta->metaValue<openvdb::Vec3i>("resolution");
    v.resolution = glm::ivec3(res[0], res[1], res[2]);
    v.levels = meta->metaValue<int32_t>("levels");
    if ((*meta)["scene"]) v.sceneName = meta->metaValue<std::string>("scene");
    if (!(v.voxelSize > 0.f) || v.levels < 1 || v.resolution.x < 1 || v.resolution.y < 1 || v.resolution.z < 1)
        throw std::runtime_error("readVdb: " + path + " has an invalid grid layout");
    v.voxelFromWorld = glm::scale(glm::mat4(1.f), glm::vec3(1.f / v.voxelSize)) *
                       glm::translate(glm::mat4(1.f), -v.origin);
    v.worldFromVoxel = glm::inverse(v.voxelFromWorld);

    v.opacity = readTyped<openvdb::FloatGrid>(file, "opacity", path);
    v.albedo = readTyped<openvdb::Vec3SGrid>(file, "albedo", path);
    v.normal = readTyped<openvdb::Vec3SGrid>(file, "normal", path);
    v.emission = readTyped<openvdb::Vec3SGrid>(file, "emission", path);
    if (file.hasGrid("radiance")) v.radiance = readTyped<openvdb::Vec3SGrid>(file, "radiance", path);
    v.opacityLevels = {v.opacity};
    if (v.radiance) v.radianceLevels = {v.radiance};
    if (v.radiance) v.normalLevels = {v.normal};
    for (int k = 1; k < v.levels; ++k) {
        const std::string suffix = "_L" + std::to_string(k);
        if (!file.hasGrid("opacity" + suffix)) break;  // a file written before its levels were built
        v.opacityLevels.push_back(readTyped<openvdb::FloatGrid>(file, "opacity" + suffix, path));
        if (v.radiance) v.radianceLevels.push_back(readTyped<openvdb::Vec3SGrid>(file, "radiance" + suffix, path));
        if (v.radiance) v.normalLevels.push_back(readTyped<openvdb::Vec3SGrid>(file, "normal" + suffix, path));
    }
    file.close();
    updateSparseMemoryStats(v);
    return v;
}

}  // namespace vct
