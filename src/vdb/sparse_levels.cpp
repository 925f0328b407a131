// Coarser levels of the sparse voxels (the CPU twin of shaders/voxelize/mip_iso.glsl and
// mip_aniso.glsl with mip_common.glsl's child ranges) and buildSparseVoxels, which runs the
// whole pipeline.
//
// A level-k voxel is active when any of its children is; its value is the mean of its
// children over the full child block (2 per axis, 3 at the last voxel of an axis whose finer
// size is odd, 1 where the finer size is already 1), with empty children counting as 0.
// Opacity and premultiplied radiance average alike, so the box filter is exact. Each parent
// sums its children in a fixed order: the levels are deterministic.
#include "vdb/sparse_detail.h"
#include "cone/cone_bounce.h"
#include "cone/cone_settings.h"
#include "vdb/sparse_cone.h"
#include "core/errors.h"
#include "voxelize/opacity_depth.h"
#include "voxelize/voxel_settings.h"

#include <openvdb/tools/Prune.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

namespace vct {

namespace vdbdetail {

openvdb::math::Transform::Ptr levelTransform(const SparseVoxelScene& voxels, int level) {
    const glm::ivec3 size = voxels.levelSize(level);
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    for (int a = 0; a < 3; ++a) {
        const double spacing = double(voxels.voxelSize) * double(voxels.resolution[a]) / double(size[a]);
        m(a, a) = spacing;
        m(3, a) = double(voxels.origin[a]) + 0.5 * spacing;  // row-vector convention: translation in row 3
    }
    return openvdb::math::Transform::createLinearTransform(m);
}

}  // namespace vdbdetail

namespace {

using namespace vdbdetail;

// The child block [lo, hi] of parent v (mip_childRange).
void childRange(const openvdb::Coord& v, const glm::ivec3& src, const glm::ivec3& dst, openvdb::Coord& lo,
                openvdb::Coord& hi) {
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(2 * v[a], src[a] - 1);
        hi[a] = v[a] == dst[a] - 1 ? src[a] - 1 : std::min(2 * v[a] + 1, src[a] - 1);
    }
}

// Level `level` from level - 1.
void buildLevel(SparseVoxelScene& voxels, int level) {
    const glm::ivec3 src = voxels.levelSize(level - 1), dst = voxels.levelSize(level);
    const openvdb::FloatTree& childOpacity = voxels.opacityLevels[size_t(level - 1)]->tree();
    const bool hasRadiance = voxels.injected();

    // Parent topology: every active child marks its parent.
    openvdb::MaskTree topology(false);
    {
        openvdb::tree::ValueAccessor<openvdb::MaskTree> acc(topology);
        for (auto leaf = childOpacity.cbeginLeaf(); leaf; ++leaf)
            for (auto it = leaf->cbeginValueOn(); it; ++it) {
                const openvdb::Coord c = it.getCoord();
                acc.setValueOn(openvdb::Coord(std::min(c.x() >> 1, dst.x - 1), std::min(c.y() >> 1, dst.y - 1),
                                              std::min(c.z() >> 1, dst.z - 1)));
            }
    }
    auto opacity = std::make_shared<openvdb::FloatTree>(topology, 0.f, 0.f, openvdb::TopologyCopy());
    std::shared_ptr<openvdb::Vec3STree> radiance, normal;
    if (hasRadiance) {
        radiance = std::make_shared<openvdb::Vec3STree>(topology, openvdb::Vec3s(0.f), openvdb::Vec3s(0.f),
                                                        openvdb::TopologyCopy());
        normal = std::make_shared<openvdb::Vec3STree>(topology, openvdb::Vec3s(0.f), openvdb::Vec3s(0.f),
                                                      openvdb::TopologyCopy());
    }
    openvdb::tree::LeafManager<openvdb::FloatTree> opacityLeaves(*opacity);
    std::unique_ptr<openvdb::tree::LeafManager<openvdb::Vec3STree>> radianceLeaves, normalLeaves;
    if (hasRadiance) {
        radianceLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::Vec3STree>>(*radiance);
        normalLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::Vec3STree>>(*normal);
    }
    const openvdb::Vec3STree* childRadiance =
        hasRadiance ? &voxels.radianceLevels[size_t(level - 1)]->tree() : nullptr;
    const openvdb::Vec3STree* childNormal = hasRadiance ? &voxels.normalLevels[size_t(level - 1)]->tree() : nullptr;

    tbb::parallel_for(tbb::blocked_range<size_t>(0, opacityLeaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
        ConstAcc<openvdb::FloatTree> opAcc(childOpacity);
        std::unique_ptr<ConstAcc<openvdb::Vec3STree>> radAcc, norAcc;
        if (childRadiance) radAcc = std::make_unique<ConstAcc<openvdb::Vec3STree>>(*childRadiance);
        if (childNormal) norAcc = std::make_unique<ConstAcc<openvdb::Vec3STree>>(*childNormal);
        for (size_t li = r.begin(); li != r.end(); ++li) {
            auto& opLeaf = opacityLeaves.leaf(li);
            for (auto it = opLeaf.beginValueOn(); it; ++it) {
                openvdb::Coord lo, hi;
                childRange(it.getCoord(), src, dst, lo, hi);
                float a = 0.f;
                openvdb::Vec3s c(0.f), nsum(0.f);
                for (int z = lo.z(); z <= hi.z(); ++z)
                    for (int y = lo.y(); y <= hi.y(); ++y)
                        for (int x = lo.x(); x <= hi.x(); ++x) {
                            const openvdb::Coord ijk(x, y, z);
                            a += opAcc.getValue(ijk);
                            if (radAcc) c += radAcc->getValue(ijk);
                            if (norAcc) nsum += norAcc->getValue(ijk);
                        }
                const openvdb::Coord n = hi - lo + openvdb::Coord(1);
                const float inv = 1.f / float(n.x() * n.y() * n.z());
                it.setValue(a * inv);
                if (radianceLeaves) radianceLeaves->leaf(li).setValueOnly(it.pos(), c * inv);
                if (normalLeaves) normalLeaves->leaf(li).setValueOnly(it.pos(), nsum * inv);
            }
        }
    });

    auto opacityGrid = openvdb::FloatGrid::create(opacity);
    opacityGrid->setName("opacity_L" + std::to_string(level));
    opacityGrid->setGridClass(openvdb::GRID_FOG_VOLUME);
    opacityGrid->setTransform(levelTransform(voxels, level));
    voxels.opacityLevels.push_back(opacityGrid);
    if (hasRadiance) {
        auto radianceGrid = openvdb::Vec3SGrid::create(radiance);
        radianceGrid->setName("radiance_L" + std::to_string(level));
        radianceGrid->setTransform(levelTransform(voxels, level));
        voxels.radianceLevels.push_back(radianceGrid);
        auto normalGrid = openvdb::Vec3SGrid::create(normal);
        normalGrid->setName("normal_L" + std::to_string(level));
        normalGrid->setTransform(levelTransform(voxels, level));
        voxels.normalLevels.push_back(normalGrid);
    }
}

// Directional level `level` (>= 1) for every direction d, as mip_aniso.glsl: from level 0's
// opacity and radiance when level == 1, else from directional[d][level - 2]. The parents are
// the isotropic level's active voxels (the same topology: a parent with any child).
// With `depth` the levels hold optical depth (opacity_depth.h): what is read from a directional
// level is converted to opacity, composited as opacity, and stored as depth.
void buildDirectionalLevel(SparseVoxelScene& voxels, int level, bool depth) {
    const glm::ivec3 src = voxels.levelSize(level - 1), dst = voxels.levelSize(level);
    const bool hasRadiance = voxels.injected();
    const openvdb::FloatTree& parents = voxels.opacityLevels[size_t(level)]->tree();
    for (int d = 0; d < 6; ++d) {
        const int a = d / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const bool forward = d % 2 == 0;
        const SparseVoxelScene::DirectionalLevel* from =
            level == 1 ? nullptr : &voxels.directional[size_t(d)][size_t(level - 2)];
        const openvdb::FloatTree& srcOpacity = from ? from->opacity->tree() : voxels.opacityLevels[0]->tree();
        const openvdb::Vec3STree* srcRadiance =
            !hasRadiance ? nullptr : from ? &from->radiance->tree() : &voxels.radianceLevels[0]->tree();

        auto opacity = std::make_shared<openvdb::FloatTree>(parents, 0.f, 0.f, openvdb::TopologyCopy());
        std::shared_ptr<openvdb::Vec3STree> radiance;
        if (hasRadiance)
            radiance = std::make_shared<openvdb::Vec3STree>(parents, openvdb::Vec3s(0.f), openvdb::Vec3s(0.f),
                                                            openvdb::TopologyCopy());
        openvdb::tree::LeafManager<openvdb::FloatTree> opacityLeaves(*opacity);
        std::unique_ptr<openvdb::tree::LeafManager<openvdb::Vec3STree>> radianceLeaves;
        if (radiance) radianceLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::Vec3STree>>(*radiance);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, opacityLeaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
            ConstAcc<openvdb::FloatTree> opAcc(srcOpacity);
            std::unique_ptr<ConstAcc<openvdb::Vec3STree>> radAcc;
            if (srcRadiance) radAcc = std::make_unique<ConstAcc<openvdb::Vec3STree>>(*srcRadiance);
            for (size_t li = r.begin(); li != r.end(); ++li) {
                auto& opLeaf = opacityLeaves.leaf(li);
                for (auto it = opLeaf.beginValueOn(); it; ++it) {
                    openvdb::Coord lo, hi;
                    childRange(it.getCoord(), src, dst, lo, hi);
                    // Premultiplied (radiance, alpha) summed over the lines along axis a.
                    glm::vec4 sum(0.f);
                    const int count = hi[a] - lo[a] + 1;
                    for (int j = lo[c]; j <= hi[c]; ++j)
                        for (int i = lo[b]; i <= hi[b]; ++i) {
                            glm::vec4 acc(0.f);
                            for (int k = 0; k < count; ++k) {
                                openvdb::Coord p;
                                p[a] = forward ? lo[a] + k : hi[a] - k;
                                p[b] = i;
                                p[c] = j;
                                glm::vec4 v(0.f, 0.f, 0.f, opAcc.getValue(p));
                                if (radAcc) {
                                    const openvdb::Vec3s L = radAcc->getValue(p);
                                    v = glm::vec4(L[0], L[1], L[2], v.w);
                                }
                                if (depth && from) v = gpu::vox_alphaFromDepth(v);
                                acc += (1.f - acc.w) * v;
                            }
                            sum += acc;
                        }
                    const float lines = float((hi[b] - lo[b] + 1) * (hi[c] - lo[c] + 1));
                    glm::vec4 mean = sum / lines;
                    if (depth) mean = gpu::vox_depthFromAlpha(mean);
                    it.setValue(mean.w);
                    if (radianceLeaves)
                        radianceLeaves->leaf(li).setValueOnly(it.pos(), openvdb::Vec3s(mean.x, mean.y, mean.z));
                }
            }
        });
        SparseVoxelScene::DirectionalLevel out;
        out.opacity = openvdb::FloatGrid::create(opacity);
        out.opacity->setName("opacity_dir" + std::to_string(d) + "_L" + std::to_string(level));
        out.opacity->setGridClass(openvdb::GRID_FOG_VOLUME);
        out.opacity->setTransform(levelTransform(voxels, level));
        if (radiance) {
            out.radiance = openvdb::Vec3SGrid::create(radiance);
            out.radiance->setName("radiance_dir" + std::to_string(d) + "_L" + std::to_string(level));
            out.radiance->setTransform(levelTransform(voxels, level));
        }
        voxels.directional[size_t(d)].push_back(out);
    }
}

size_t product(const glm::ivec3& v) { return size_t(v.x) * size_t(v.y) * size_t(v.z); }

}  // namespace

void buildSparseLevels(SparseVoxelScene& voxels, bool anisotropic, bool depthLevels) {
    if (!voxels.opacity) throw InternalError("buildSparseLevels", "the scene is not voxelized");
    if (anisotropic && voxels.levels < 2)
        throw InternalError("buildSparseLevels", "voxel grid too small for directional levels");
    const auto t0 = std::chrono::steady_clock::now();
    voxels.opacityLevels.resize(1);
    if (voxels.injected()) voxels.radianceLevels.resize(1);
    voxels.normalLevels.clear();
    if (voxels.injected()) voxels.normalLevels = {voxels.facing()};
    for (auto& levels : voxels.directional) levels.clear();
    for (int level = 1; level < voxels.levels; ++level) {
        buildLevel(voxels, level);
        if (anisotropic) buildDirectionalLevel(voxels, level, depthLevels);
    }
    voxels.depthLevels = anisotropic && depthLevels;
    voxels.stats.levelsSeconds = secondsSince(t0);
    updateSparseMemoryStats(voxels);
}

void updateSparseMemoryStats(SparseVoxelScene& voxels) {
    SparseVoxelStats& s = voxels.stats;
    s.activeVoxels = voxels.opacity ? size_t(voxels.opacity->activeVoxelCount()) : 0;
    s.leafNodes = voxels.opacity ? size_t(voxels.opacity->tree().leafCount()) : 0;
    s.memoryBytes = 0;
    for (const auto& g : voxels.opacityLevels) s.memoryBytes += size_t(g->memUsage());
    for (const auto& g : voxels.radianceLevels) s.memoryBytes += size_t(g->memUsage());
    for (size_t k = 1; k < voxels.normalLevels.size(); ++k) s.memoryBytes += size_t(voxels.normalLevels[k]->memUsage());
    for (const auto& levels : voxels.directional)
        for (const auto& l : levels) {
            s.memoryBytes += size_t(l.opacity->memUsage());
            if (l.radiance) s.memoryBytes += size_t(l.radiance->memUsage());
        }
    for (const auto* g : {&voxels.albedo, &voxels.normal, &voxels.emission, &voxels.facingNormal})
        if (*g) s.memoryBytes += size_t((*g)->memUsage());
    if (voxels.twoSided) s.memoryBytes += size_t(voxels.twoSided->memUsage());
    if (voxels.sheet) s.memoryBytes += size_t(voxels.sheet->memUsage());
    if (voxels.sheetExtent) s.memoryBytes += size_t(voxels.sheetExtent->memUsage());
    // Dense equivalent of the same channels in float32: per level, opacity (4 B) and radiance
    // (12 B) when held; level 0 also albedo, normal and emission (12 B each), and with two-sided
    // voxels their share (4 B) and, once injected, the facing normals (12 B).
    const int maxRes = std::max(voxels.resolution.x, std::max(voxels.resolution.y, voxels.resolution.z));
    s.denseBytes = s.denseCubeBytes = 0;
    for (int level = 0; level < int(voxels.opacityLevels.size()); ++level) {
        size_t perVoxel = 4 + (level < int(voxels.radianceLevels.size()) ? 12 : 0) +
                          (level > 0 && level < int(voxels.normalLevels.size()) ? 12 : 0);
        if (level == 0)
            perVoxel += (voxels.albedo ? 12 : 0) + (voxels.normal ? 12 : 0) + (voxels.emission ? 12 : 0) +
                        (voxels.twoSided ? 4 : 0) + (voxels.facingNormal ? 12 : 0) + (voxels.sheet ? 16 : 0);
        s.denseBytes += product(voxels.levelSize(level)) * perVoxel;
        s.denseCubeBytes += product(glm::ivec3(std::max(maxRes >> level, 1))) * perVoxel;
    }
}

SparseVoxelScene buildSparseVoxels(const Scene& scene, int voxelRes, bool inject, float sky,
                                   const ParamMap& params) {
    return buildSparseVoxels(scene, voxelRes, inject, sky, params, SparseBuildOptions{});
}

SparseVoxelScene buildSparseVoxels(const Scene& scene, int voxelRes, bool inject, float sky,
                                   const ParamMap& params, const SparseBuildOptions& options) {
    if (!std::isfinite(sky) || sky < 0.f)
        throw InternalError("buildSparseVoxels", "sky radiance must be finite and >= 0");
    // The GPU path's keys, read for parity (the sparse grids always hold float32).
    const VoxelSettings voxelOptions = voxelSettings().read(params);
    const float offset = voxelOptions.injectOffset;
    const BounceSettings bounce = bounceSettings().read(params);
    SparseVoxelScene voxels = voxelizeSparse(scene, options.region.empty() ? scene.bounds : options.region,
                                             voxelRes, inject, options.attributes,
                                             voxelOptions.edges != VoxelEdges::Occupied,
                                             voxelOptions.edges == VoxelEdges::Sheet);
    if (inject) {
        injectSparseRadiance(voxels, scene, offset);
        // The bounces trace with the pixel cones' settings, as the GPU path's.
        const auto t0 = std::chrono::steady_clock::now();
        traceSparseBounces(voxels, sky, readConeSettings(params), bounce, options.anisotropic);
        voxels.stats.bounceSeconds = secondsSince(t0);
    }
    buildSparseLevels(voxels, options.anisotropic, options.depthLevels);
    // Collapse constant blocks into tiles (tolerance 0: values are kept exactly).
    for (auto& g : voxels.opacityLevels) openvdb::tools::prune(g->tree());
    for (auto& g : voxels.radianceLevels) openvdb::tools::prune(g->tree());
    for (auto& levels : voxels.directional)
        for (auto& l : levels) {
            openvdb::tools::prune(l.opacity->tree());
            if (l.radiance) openvdb::tools::prune(l.radiance->tree());
        }
    for (auto* g : {&voxels.albedo, &voxels.normal, &voxels.emission})
        if (*g) openvdb::tools::prune((*g)->tree());
    if (voxels.twoSided) openvdb::tools::prune(voxels.twoSided->tree());
    if (voxels.sheet) openvdb::tools::prune(voxels.sheet->tree());
    if (voxels.sheetExtent) openvdb::tools::prune(*voxels.sheetExtent);
    updateSparseMemoryStats(voxels);
    return voxels;
}

}  // namespace vct
