// Sparse conservative voxelization: the CPU twin of shaders/voxelize/voxelize_pass.glsl and
// resolve.glsl. Each TBB thread marks the voxels its triangles overlap in its own index grid
// (Int32Tree: voxel -> slot in its array of fixed-point sums); the union of those topologies
// is the occupied set, and each occupied voxel adds up the sums of every thread. The sums are
// integers (the GPU's fixed-point scales), so the total does not depend on which thread saw
// which triangle: the grids are bit-identical for any thread count and schedule.
#include "core/errors.h"
#include "scene/texture_sampler.h"
#include "vdb/sparse_detail.h"
#include "vdb/triangle_box.h"
#include "voxelize/voxel_grid.h"

#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace vct {

namespace vdbdetail {

void ensureOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

}  // namespace vdbdetail

namespace {

using namespace vdbdetail;

// The GPU voxelizer's fixed point (voxelize_shared.h): integer weight ~ area in voxel faces x 16.
constexpr int kWeightMax = gpu::VOX_WEIGHT_MAX;
constexpr float kAlbedoScale = gpu::VOX_ALBEDO_SCALE;
constexpr float kNormalScale = gpu::VOX_NORMAL_SCALE;
constexpr float kEmissionScale = gpu::VOX_EMISSION_SCALE;
constexpr float kEmissionMax = gpu::VOX_EMISSION_MAX;

struct VoxelSums {
    uint64_t albedo[3] = {0, 0, 0};
    int64_t normal[3] = {0, 0, 0};
    uint64_t weight = 0;
    uint64_t twoSidedWeight = 0;  // of doubleSided materials
    uint64_t emission[3] = {0, 0, 0};
    uint64_t coverage = 0;  // vox_columnCoverage's fixed-point areas (edge coverage)
    uint32_t axes = 0;      // bit a: a triangle of dominant axis a crosses the voxel (edge coverage)
    uint32_t sheetLo = 0, sheetHi = 0;  // vox_sheetSpanFixed's maxima (vct.voxel.edges=sheet)
    uint32_t extent = 0;                // vox_extentBits' union (vct.voxel.edges=sheet)

    void add(const VoxelSums& t) {
        for (int c = 0; c < 3; ++c) {
            albedo[c] += t.albedo[c];
            normal[c] += t.normal[c];
            emission[c] += t.emission[c];
        }
        weight += t.weight;
        twoSidedWeight += t.twoSidedWeight;
        coverage += t.coverage;
        axes |= t.axes;
        sheetLo = std::max(sheetLo, t.sheetLo);
        sheetHi = std::max(sheetHi, t.sheetHi);
        extent |= t.extent;
    }
};

// One thread's share: voxel -> index into `sums`. A grid without attributes or edge coverage
// needs only which voxels are occupied (level 0's opacity is 1 on every occupied voxel):
// `slots` alone, no sums.
struct ThreadSums {
    openvdb::Int32Tree slots{-1};
    std::vector<VoxelSums> sums;
    bool attributes = true;
    bool edgeCoverage = false;
    bool sheets = false;  // vct.voxel.edges=sheet: the span of each voxel's sheet too
};

// A voxel's sums over every thread's share; `threadLeaves[k]` is thread k's leaf holding it.
VoxelSums sumsAt(const std::vector<const ThreadSums*>& threads,
                 const std::vector<const openvdb::Int32Tree::LeafNodeType*>& threadLeaves, openvdb::Index offset) {
    VoxelSums s;
    for (size_t k = 0; k < threads.size(); ++k) {
        const auto* tl = threadLeaves[k];
        if (tl && tl->isValueOn(offset)) s.add(threads[k]->sums[size_t(tl->getValue(offset))]);
    }
    return s;
}

struct Tri {
    glm::vec3 p[3];  // voxel units
    glm::vec3 n[3];
    glm::vec2 uv[3];
    glm::vec3 faceN;
    uint32_t index = 0;  // the triangle's index in the scene (its vertex colours)
    uint32_t material = 0;
    glm::ivec3 lo, hi;
    int axis = 2;
    uint32_t weight = 1;
};

// vox_loadTriangle; false when the triangle misses the grid.
bool loadTriangle(const Scene& scene, size_t t, const glm::vec3& origin, float invVoxelSize,
                  const glm::ivec3& res, Tri& tri) {
    const glm::uvec3 idx = scene.triangles[t];
    for (int k = 0; k < 3; ++k) {
        tri.p[k] = (scene.positions[idx[k]] - origin) * invVoxelSize;
        tri.n[k] = idx[k] < scene.normals.size() ? scene.normals[idx[k]] : glm::vec3(0.f);
        tri.uv[k] = idx[k] < scene.uvs.size() ? scene.uvs[idx[k]] : glm::vec2(0.f);
    }
    tri.index = uint32_t(t);
    tri.material = t < scene.triangleMaterial.size() ? scene.triangleMaterial[t] : 0u;
    tri.faceN = glm::cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
    const glm::vec3 bmin = glm::min(tri.p[0], glm::min(tri.p[1], tri.p[2]));
    const glm::vec3 bmax = glm::max(tri.p[0], glm::max(tri.p[1], tri.p[2]));
    tri.lo = glm::max(glm::ivec3(glm::floor(bmin - 0.5f * kVoxBoxGrowth)), glm::ivec3(0));
    tri.hi = glm::min(glm::ivec3(glm::floor(bmax + 0.5f * kVoxBoxGrowth)), res - 1);
    const glm::vec3 an = glm::abs(tri.faceN);
    tri.axis = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
    const float area = 0.5f * glm::length(tri.faceN);
    tri.weight = uint32_t(std::clamp(std::round(area * float(kWeightMax)), 1.f, float(kWeightMax)));
    return tri.lo.x <= tri.hi.x && tri.lo.y <= tri.hi.y && tri.lo.z <= tri.hi.z;
}

// vox_barycentrics: of the plane point nearest to q, clamped into the triangle.
glm::vec3 barycentrics(const Tri& tri, const glm::vec3& q) {
    const glm::vec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], d = q - tri.p[0];
    const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const float d1 = glm::dot(d, e1), d2 = glm::dot(d, e2);
    const float det = d11 * d22 - d12 * d12;
    if (!(det > 0.f)) return glm::vec3(1.f / 3.f);
    const float v = (d22 * d1 - d12 * d2) / det, w = (d11 * d2 - d12 * d1) / det;
    glm::vec3 b = glm::max(glm::vec3(1.f - v - w, v, w), glm::vec3(0.f));
    return b / (b.x + b.y + b.z);
}

// vox_accumulate: adds the triangle's fixed-point attributes at voxel v, and with edge coverage
// `coverage`, its column's covered area in fixed point, and its dominant axis; with sheets the
// span `sheetZ` of its plane over that area and the extent bits `across` of that area.
void accumulate(const Scene& scene, const Tri& tri, const glm::ivec3& v, ThreadSums& ts,
                openvdb::tree::ValueAccessor<openvdb::Int32Tree>& acc, uint32_t coverage, glm::vec2 sheetZ,
                uint32_t across) {
    const glm::vec3 b = barycentrics(tri, glm::vec3(v) + 0.5f);
    const glm::vec2 uv = b.x * tri.uv[0] + b.y * tri.uv[1] + b.z * tri.uv[2];
    const glm::vec4 color = vertexColorAt(scene, tri.index, b);
    if (tri.material < scene.materials.size()) {
        const Material& m = scene.materials[tri.material];
        if (m.alphaMask && materialAlpha(scene, tri.material, uv, color) < m.alphaCutoff) return;
    }
    const openvdb::Coord ijk(v.x, v.y, v.z);
    if (!ts.attributes && !ts.edgeCoverage) {
        acc.setValueOn(ijk, 0);
        return;
    }
    int32_t slot = -1;
    if (!acc.probeValue(ijk, slot)) {
        slot = int32_t(ts.sums.size());
        ts.sums.emplace_back();
        acc.setValueOn(ijk, slot);
    }
    VoxelSums& s = ts.sums[size_t(slot)];
    if (ts.edgeCoverage) {
        s.coverage += coverage;
        s.axes |= 1u << tri.axis;
        if (ts.sheets && coverage > 0u) {
            const glm::uvec2 span = gpu::vox_sheetSpanFixed(sheetZ, float(v[tri.axis]));
            s.sheetLo = std::max(s.sheetLo, span.x);
            s.sheetHi = std::max(s.sheetHi, span.y);
            s.extent |= gpu::vox_triangleExtentBits(across, sheetZ, float(v[tri.axis]), tri.axis);
        }
    }
    if (!ts.attributes) return;
    const glm::vec3 albedo =
        tri.material < scene.materials.size() ? materialAlbedo(scene, tri.material, uv, color) : glm::vec3(1.f);
    const glm::vec3 emission = tri.material < scene.materials.size()
                                   ? materialEmission(scene, tri.material, uv)
                                   : glm::vec3(0.f);
    const bool doubleSided = tri.material < scene.materials.size() && scene.materials[tri.material].doubleSided;
    glm::vec3 n = b.x * tri.n[0] + b.y * tri.n[1] + b.z * tri.n[2];
    const float len = glm::length(n), faceLen = glm::length(tri.faceN);
    n = len > 1e-6f ? n / len : (faceLen > 0.f ? tri.faceN / faceLen : glm::vec3(0.f));
    const uint64_t w = tri.weight;
    for (int c = 0; c < 3; ++c) {
        s.albedo[c] += uint64_t(std::round(std::clamp(albedo[c], 0.f, 1.f) * kAlbedoScale)) * w;
        s.normal[c] += int64_t(std::round(std::clamp(n[c], -1.f, 1.f) * kNormalScale)) * int64_t(w);
        const float e = std::clamp(emission[c], 0.f, kEmissionMax);
        if (e > 0.f) s.emission[c] += uint64_t(e * float(w) * kEmissionScale);
    }
    s.weight += w;
    if (doubleSided) s.twoSidedWeight += w;
}

// vox_column: the candidate run of one column of the dominant-axis projection.
void voxelizeColumn(const Scene& scene, const Tri& tri, int i, int j, ThreadSums& ts,
                    openvdb::tree::ValueAccessor<openvdb::Int32Tree>& acc) {
    const int d = tri.axis, a = (d + 1) % 3, b = (d + 2) % 3;
    int kLo = tri.lo[d], kHi = tri.hi[d];
    const glm::vec3& n = tri.faceN;
    if (std::abs(n[d]) > 0.f) {
        const float c = glm::dot(n, tri.p[0]);
        const float g = kVoxBoxGrowth;
        float zMin = 3.4e38f, zMax = -3.4e38f;
        for (int k = 0; k < 4; ++k) {
            const float pa = float(i) + ((k & 1) != 0 ? 1.f + g : -g);
            const float pb = float(j) + ((k & 2) != 0 ? 1.f + g : -g);
            const float z = (c - n[a] * pa - n[b] * pb) / n[d];
            zMin = std::min(zMin, z);
            zMax = std::max(zMax, z);
        }
        kLo = std::max(kLo, int(std::floor(zMin)) - 1);
        kHi = std::min(kHi, int(std::floor(zMax)) + 1);
    }
    // vox_columnCut: the column's covered area, and with sheets the plane's span over it and the
    // extent bits of that part across the axis.
    const glm::vec4 plane = ts.sheets ? glm::vec4(n[a], n[b], n[d], glm::dot(n, tri.p[0])) : glm::vec4(0.f);
    gpu::VoxColumnCut cut{};
    if (ts.edgeCoverage)
        cut = gpu::vox_columnCut(glm::vec2(tri.p[0][a], tri.p[0][b]), glm::vec2(tri.p[1][a], tri.p[1][b]),
                                 glm::vec2(tri.p[2][a], tri.p[2][b]), glm::vec2(float(i), float(j)), plane);
    const uint32_t coverage = ts.edgeCoverage ? gpu::vox_coverageFixed(cut.area) : 0u;
    const glm::vec2 sheetZ(cut.zMin, cut.zMax);
    const uint32_t across = ts.sheets ? gpu::vox_extentBits(cut.boxLo.x, cut.boxHi.x, a) |
                                            gpu::vox_extentBits(cut.boxLo.y, cut.boxHi.y, b)
                                      : 0u;
    for (int k = kLo; k <= kHi; ++k) {
        glm::ivec3 v;
        v[a] = i;
        v[b] = j;
        v[d] = k;
        if (triangleOverlapsVoxel(tri.p, tri.faceN, glm::vec3(v) + 0.5f))
            accumulate(scene, tri, v, ts, acc, coverage, sheetZ, across);
    }
}

void voxelizeTriangle(const Scene& scene, const Tri& tri, ThreadSums& ts,
                      openvdb::tree::ValueAccessor<openvdb::Int32Tree>& acc) {
    const int d = tri.axis, a = (d + 1) % 3, b = (d + 2) % 3;
    for (int j = tri.lo[b]; j <= tri.hi[b]; ++j)
        for (int i = tri.lo[a]; i <= tri.hi[a]; ++i) voxelizeColumn(scene, tri, i, j, ts, acc);
}

void checkScene(const Scene& scene) {
    for (size_t i = 0; i < scene.positions.size(); ++i) {
        const glm::vec3& p = scene.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::runtime_error("voxelizeSparse: vertex " + std::to_string(i) + " is not finite");
    }
    for (size_t t = 0; t < scene.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (scene.triangles[t][k] >= scene.positions.size())
                throw std::runtime_error("voxelizeSparse: triangle " + std::to_string(t) +
                                         " indexes a missing vertex");
    for (const Material& m : scene.materials)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(m.emissiveFactor[c]))
                throw std::runtime_error("voxelizeSparse: material '" + m.name + "' emission is not finite");
}

}  // namespace

SparseVoxelScene voxelizeSparse(const Scene& scene, int voxelRes) {
    return voxelizeSparse(scene, scene.bounds, voxelRes);
}

SparseVoxelScene voxelizeSparse(const Scene& scene, const Bounds3& region, int voxelRes, bool lit, bool attributes,
                                bool edgeCoverage, bool sheets) {
    ensureOpenVdb();
    edgeCoverage = edgeCoverage || sheets;  // sheets are read where coverage sets the opacity
    checkScene(scene);
    attributes = attributes || lit;  // injection reads them
    const auto t0 = std::chrono::steady_clock::now();
    const VoxelGrid layout = makeGridLayout(region, voxelRes);
    SparseVoxelScene out;
    out.resolution = layout.resolution;
    out.voxelSize = layout.voxelSize;
    out.origin = layout.origin;
    out.levels = layout.levels;
    out.voxelFromWorld = layout.voxelFromWorld;
    out.worldFromVoxel = layout.worldFromVoxel;
    out.sceneName = scene.path;

    // Per-thread marking and fixed-point sums.
    const float invVoxelSize = 1.f / layout.voxelSize;
    tbb::enumerable_thread_specific<std::unique_ptr<ThreadSums>> perThread;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, scene.triangles.size(), 64),
                      [&](const tbb::blocked_range<size_t>& r) {
                          std::unique_ptr<ThreadSums>& ts = perThread.local();
                          if (!ts) {
                              ts = std::make_unique<ThreadSums>();
                              ts->attributes = attributes;
                              ts->edgeCoverage = edgeCoverage;
                              ts->sheets = sheets;
                          }
                          openvdb::tree::ValueAccessor<openvdb::Int32Tree> acc(ts->slots);
                          Tri tri;
                          for (size_t t = r.begin(); t != r.end(); ++t)
                              if (loadTriangle(scene, t, out.origin, invVoxelSize, out.resolution, tri))
                                  voxelizeTriangle(scene, tri, *ts, acc);
                      });
    std::vector<const ThreadSums*> threads;
    for (const auto& ts : perThread)
        if (ts) threads.push_back(ts.get());

    // The occupied set: union of every thread's topology (order independent).
    openvdb::MaskTree topology(false);
    for (const ThreadSums* ts : threads) topology.topologyUnion(ts->slots);

    auto opacity = std::make_shared<openvdb::FloatTree>(topology, 0.f, 1.f, openvdb::TopologyCopy());
    auto makeGrid = [&](auto tree, const char* name) {
        using TreeT = typename decltype(tree)::element_type;
        auto grid = openvdb::Grid<TreeT>::create(tree);
        grid->setName(name);
        grid->setTransform(levelTransform(out, 0));
        return grid;
    };
    out.opacity = makeGrid(opacity, "opacity");
    out.opacity->setGridClass(openvdb::GRID_FOG_VOLUME);
    out.opacityLevels = {out.opacity};
    openvdb::tree::LeafManager<openvdb::FloatTree> opacityLeaves(*opacity);
    auto threadLeavesAt = [&](const openvdb::Coord& origin) {
        std::vector<const openvdb::Int32Tree::LeafNodeType*> leaves(threads.size());
        for (size_t k = 0; k < threads.size(); ++k) leaves[k] = threads[k]->slots.probeConstLeaf(origin);
        return leaves;
    };
    if (edgeCoverage) {
        // Level 0's opacity (resolve.glsl): each voxel's coverage sum and axis bits, then
        // vox_edgeOpacity of the voxel's and its neighbours' sums along its axis.
        openvdb::UInt32Tree coverage(topology, 0u, openvdb::TopologyCopy());
        openvdb::UInt32Tree axes(topology, 0u, openvdb::TopologyCopy());
        // vct.voxel.edges=sheet: (lo, hi, axis) of vox_sheetTexel where the voxel holds a sheet,
        // inactive elsewhere.
        // And every occupied voxel's extent bits (vox_extentBits).
        std::shared_ptr<openvdb::Vec3STree> sheet;
        std::unique_ptr<openvdb::tree::LeafManager<openvdb::Vec3STree>> sheetLeaves;
        std::unique_ptr<openvdb::tree::LeafManager<openvdb::UInt32Tree>> extentLeaves;
        if (sheets) {
            sheet = std::make_shared<openvdb::Vec3STree>(topology, openvdb::Vec3s(0.f), openvdb::TopologyCopy());
            sheetLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::Vec3STree>>(*sheet);
            out.sheetExtent = std::make_shared<openvdb::UInt32Tree>(topology, 0u, openvdb::TopologyCopy());
            extentLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::UInt32Tree>>(*out.sheetExtent);
        }
        openvdb::tree::LeafManager<openvdb::UInt32Tree> coverageLeaves(coverage), axesLeaves(axes);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, coverageLeaves.leafCount()),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t li = r.begin(); li != r.end(); ++li) {
                                  auto& leaf = coverageLeaves.leaf(li);
                                  auto& axesLeaf = axesLeaves.leaf(li);
                                  const auto leaves = threadLeavesAt(leaf.origin());
                                  for (auto it = leaf.beginValueOn(); it; ++it) {
                                      const VoxelSums s = sumsAt(threads, leaves, it.pos());
                                      it.setValue(uint32_t(std::min<uint64_t>(s.coverage, UINT32_MAX)));
                                      axesLeaf.setValueOnly(it.pos(), s.axes);
                                      if (!sheetLeaves) continue;
                                      extentLeaves->leaf(li).setValueOnly(it.pos(), s.extent);
                                      const glm::vec4 texel = gpu::vox_sheetTexel(0.f, s.axes, s.sheetLo, s.sheetHi);
                                      auto& sheetLeaf = sheetLeaves->leaf(li);
                                      if (texel.w >= 0.f)
                                          sheetLeaf.setValueOnly(it.pos(), openvdb::Vec3s(texel.y, texel.z, texel.w));
                                      else
                                          sheetLeaf.setValueOff(it.pos(), openvdb::Vec3s(0.f));
                                  }
                              }
                          });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, opacityLeaves.leafCount()),
                          [&](const tbb::blocked_range<size_t>& r) {
                              openvdb::tree::ValueAccessor<const openvdb::UInt32Tree> at(coverage);
                              for (size_t li = r.begin(); li != r.end(); ++li) {
                                  auto& leaf = opacityLeaves.leaf(li);
                                  const auto& axesLeaf = axesLeaves.leaf(li);
                                  for (auto it = leaf.beginValueOn(); it; ++it) {
                                      const uint32_t a = axesLeaf.getValue(it.pos());
                                      const openvdb::Coord c = it.getCoord();
                                      openvdb::Coord along(0, 0, 0);
                                      if (a != 0u) along[gpu::vox_singleAxis(a)] = 1;
                                      it.setValue(gpu::vox_edgeOpacity(a, at.getValue(c - along), at.getValue(c),
                                                                       at.getValue(c + along)));
                                  }
                              }
                          });
        if (sheet) out.sheet = makeGrid(sheet, "sheet");
    }
    if (!attributes) {
        // Opacity alone: the occupied set is the whole answer.
        out.stats.voxelizeSeconds = secondsSince(t0);
        updateSparseMemoryStats(out);
        return out;
    }
    const openvdb::Vec3s zero(0.f);
    auto albedo = std::make_shared<openvdb::Vec3STree>(topology, zero, zero, openvdb::TopologyCopy());
    auto normal = std::make_shared<openvdb::Vec3STree>(topology, zero, zero, openvdb::TopologyCopy());
    auto emission = std::make_shared<openvdb::Vec3STree>(topology, zero, zero, openvdb::TopologyCopy());
    // The doubleSided share of each voxel's weight (resolve.glsl's two-sided texture), only for
    // lit voxels of a scene with a doubleSided material.
    const bool twoSided = lit && std::any_of(scene.materials.begin(), scene.materials.end(),
                                             [](const Material& m) { return m.doubleSided; });
    std::shared_ptr<openvdb::FloatTree> twoSidedShare;
    std::unique_ptr<openvdb::tree::LeafManager<openvdb::FloatTree>> twoSidedLeaves;
    if (twoSided) {
        twoSidedShare = std::make_shared<openvdb::FloatTree>(topology, 0.f, 0.f, openvdb::TopologyCopy());
        twoSidedLeaves = std::make_unique<openvdb::tree::LeafManager<openvdb::FloatTree>>(*twoSidedShare);
    }
    openvdb::tree::LeafManager<openvdb::Vec3STree> albedoLeaves(*albedo), normalLeaves(*normal),
        emissionLeaves(*emission);

    // Resolve (resolve.glsl): weighted averages from the summed fixed-point values.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, opacityLeaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t li = r.begin(); li != r.end(); ++li) {
            const auto& opLeaf = opacityLeaves.leaf(li);
            auto& alLeaf = albedoLeaves.leaf(li);
            auto& nrLeaf = normalLeaves.leaf(li);
            auto& emLeaf = emissionLeaves.leaf(li);
            if (alLeaf.origin() != opLeaf.origin() || emLeaf.origin() != opLeaf.origin())
                throw InternalError("voxelizeSparse", "leaf order differs between grids of one topology");
            const auto threadLeaves = threadLeavesAt(opLeaf.origin());
            for (auto it = opLeaf.cbeginValueOn(); it; ++it) {
                const openvdb::Index offset = it.pos();
                const VoxelSums s = sumsAt(threads, threadLeaves, offset);
                const float weight = float(s.weight);
                openvdb::Vec3s a, n, e;
                for (int c = 0; c < 3; ++c) {
                    a[c] = float(s.albedo[c]) / (weight * kAlbedoScale);
                    n[c] = float(s.normal[c]);
                    e[c] = float(double(s.emission[c])) / (weight * kEmissionScale);
                }
                // Normals that cancel (both faces of a thin wall in one voxel) are stored as zero:
                // injection then treats the voxel as facing every light.
                const float len = n.length();
                n = len > 1e-3f * weight * kNormalScale ? n / len : zero;
                alLeaf.setValueOnly(offset, a);
                nrLeaf.setValueOnly(offset, n);
                emLeaf.setValueOnly(offset, e);
                if (twoSidedLeaves) twoSidedLeaves->leaf(li).setValueOnly(offset, float(s.twoSidedWeight) / weight);
            }
        }
    });

    out.albedo = makeGrid(albedo, "albedo");
    out.normal = makeGrid(normal, "normal");
    out.normal->setVectorType(openvdb::VEC_COVARIANT_NORMALIZE);
    out.emission = makeGrid(emission, "emission");
    if (twoSided) out.twoSided = makeGrid(twoSidedShare, "two_sided");
    out.stats.voxelizeSeconds = secondsSince(t0);
    updateSparseMemoryStats(out);
    return out;
}

}  // namespace vct
