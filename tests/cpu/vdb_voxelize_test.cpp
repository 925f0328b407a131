// Sparse voxelization, injection and levels (src/vdb) against an independent double-precision
// overlap test, closed forms, and an independent dense implementation of the level rule.
#include "core/errors.h"
#include "support/test_scenes.h"
#include "vdb/sparse_voxels.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace vct {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Key = std::tuple<int, int, int>;

std::set<Key> activeSet(const openvdb::FloatGrid& g) {
    std::set<Key> s;
    for (auto it = g.cbeginValueOn(); it; ++it) {
        openvdb::CoordBBox box = it.getBoundingBox();  // tiles cover several voxels
        for (auto c = box.begin(); c; ++c) s.insert({(*c).x(), (*c).y(), (*c).z()});
    }
    return s;
}

// True when no axis among the box normals, the triangle normal and the nine edge x axis
// cross products separates the triangle from the cube of half-size h centred at c (double).
bool overlapsExact(const std::array<glm::dvec3, 3>& tri, glm::dvec3 c, double h) {
    std::array<glm::dvec3, 3> v = {tri[0] - c, tri[1] - c, tri[2] - c};
    auto separated = [&](glm::dvec3 axis) {
        double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
        double r = h * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    const glm::dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    std::vector<glm::dvec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, glm::cross(e[0], e[1])};
    for (const auto& ei : e)
        for (glm::dvec3 a : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)}) axes.push_back(glm::cross(ei, a));
    for (const auto& a : axes)
        if (glm::dot(a, a) > 0.0 && separated(a)) return false;
    return true;
}

void addTriangle(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t m) {
    glm::vec3 n = glm::cross(b - a, c - a);
    n = glm::length(n) > 0.f ? glm::normalize(n) : glm::vec3(0, 1, 0);
    uint32_t base = uint32_t(s.positions.size());
    for (glm::vec3 p : {a, b, c}) {
        s.positions.push_back(p);
        s.normals.push_back(n);
        s.uvs.push_back(glm::vec2(0.f));
    }
    s.triangles.push_back({base, base + 1, base + 2});
    s.triangleMaterial.push_back(m);
    s.triangleOffscreen.push_back(0);
}

// Thin, sub-voxel, axis-aligned and random triangles inside [0, 10]^3.
Scene awkwardTriangles(uint32_t seed) {
    Scene s;
    uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.5f, 9.5f), small(-0.05f, 0.05f);
    for (int i = 0; i < 40; ++i) {
        glm::vec3 a(u(rng), u(rng), u(rng));
        switch (i % 4) {
        case 0: addTriangle(s, a, glm::vec3(u(rng), u(rng), u(rng)), glm::vec3(u(rng), u(rng), u(rng)), m); break;
        case 1: addTriangle(s, a, a + glm::vec3(small(rng), small(rng), small(rng)), a + glm::vec3(small(rng), small(rng), small(rng)), m); break;  // sub-voxel
        case 2: addTriangle(s, a, glm::vec3(u(rng), a.y, a.z), glm::vec3(a.x, a.y, u(rng)), m); break;  // axis-aligned (y plane)
        default: addTriangle(s, a, glm::vec3(u(rng), u(rng), u(rng)), a + glm::vec3(1e-3f, 0.f, 0.f), m); break;  // sliver
        }
    }
    s.bounds.expand(glm::vec3(0.f));
    s.bounds.expand(glm::vec3(10.f));
    return s;
}

TEST(VdbVoxelize, NoHolesAgainstExactOverlap) {
    for (uint32_t seed : {1u, 2u}) {
        Scene s = awkwardTriangles(seed);
        SparseVoxelScene v = voxelizeSparse(s, 48);
        std::set<Key> marked = activeSet(*v.opacity);
        // Every voxel that a triangle overlaps with margin must be marked; every marked voxel must
        // overlap some triangle within a small growth (conservative, not loose).
        std::set<Key> must, may;
        for (size_t t = 0; t < s.triangles.size(); ++t) {
            std::array<glm::dvec3, 3> tri;
            glm::dvec3 lo(1e30), hi(-1e30);
            for (int k = 0; k < 3; ++k) {
                tri[k] = (glm::dvec3(s.positions[s.triangles[t][k]]) - glm::dvec3(v.origin)) / double(v.voxelSize);
                lo = glm::min(lo, tri[k]);
                hi = glm::max(hi, tri[k]);
            }
            for (int z = int(std::floor(lo.z)) - 1; z <= int(std::floor(hi.z)) + 1; ++z)
                for (int y = int(std::floor(lo.y)) - 1; y <= int(std::floor(hi.y)) + 1; ++y)
                    for (int x = int(std::floor(lo.x)) - 1; x <= int(std::floor(hi.x)) + 1; ++x) {
                        glm::dvec3 c(x + 0.5, y + 0.5, z + 0.5);
                        if (overlapsExact(tri, c, 0.5 - 1e-4)) must.insert({x, y, z});
                        if (overlapsExact(tri, c, 0.5 + 1e-3)) may.insert({x, y, z});
                    }
        }
        size_t missing = 0, extra = 0;
        for (const Key& k : must) missing += marked.count(k) == 0;
        for (const Key& k : marked) extra += may.count(k) == 0;
        EXPECT_EQ(missing, 0u) << "seed " << seed << ": " << must.size() << " voxels required";
        EXPECT_EQ(extra, 0u) << "seed " << seed;
        EXPECT_EQ(v.stats.activeVoxels, marked.size());
        EXPECT_GE(marked.size(), must.size());
    }
}

Scene floorAndBox() {
    Scene s;
    uint32_t floor = vcttest::addMaterial(s, glm::vec3(0.2f, 0.5f, 0.8f));
    uint32_t box = vcttest::addMaterial(s, glm::vec3(0.7f), glm::vec3(0.f, 0.f, 3.f));
    vcttest::addQuad(s, {-4, 0, -4}, {0, 0, 8}, {8, 0, 0}, floor);  // normal +y
    vcttest::addBox(s, {-1, 0, -1}, {1, 1.5f, 1}, box);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
    sun.color = glm::vec3(2.f);
    s.lights.push_back(sun);
    vcttest::finish(s);
    return s;
}

// Bitwise equality of two grids' active sets and values.
template <typename GridT>
bool sameBits(const GridT& a, const GridT& b) {
    if (a.activeVoxelCount() != b.activeVoxelCount()) return false;
    auto acc = b.getConstAccessor();
    for (auto it = a.cbeginValueOn(); it; ++it) {
        typename GridT::ValueType vb;
        if (!it.isVoxelValue() || !acc.probeValue(it.getCoord(), vb)) return false;
        typename GridT::ValueType va = *it;
        if (std::memcmp(&va, &vb, sizeof(va)) != 0) return false;
    }
    return true;
}

bool sameScene(const SparseVoxelScene& a, const SparseVoxelScene& b) {
    bool same = sameBits(*a.albedo, *b.albedo) && sameBits(*a.normal, *b.normal) &&
                sameBits(*a.emission, *b.emission) && a.opacityLevels.size() == b.opacityLevels.size() &&
                a.radianceLevels.size() == b.radianceLevels.size();
    for (size_t k = 0; same && k < a.opacityLevels.size(); ++k) same = sameBits(*a.opacityLevels[k], *b.opacityLevels[k]);
    for (size_t k = 0; same && k < a.radianceLevels.size(); ++k)
        same = sameBits(*a.radianceLevels[k], *b.radianceLevels[k]);
    return same;
}

TEST(VdbVoxelize, DeterministicAcrossRunsAndThreadCounts) {
    Scene s = floorAndBox();
    // Many overlapping triangles so that threads share voxels.
    Scene t = awkwardTriangles(7);
    ParamMap params;
    auto build = [&](const Scene& sc, int threads) {
        tbb::task_arena arena(threads);
        SparseVoxelScene v;
        arena.execute([&] { v = buildSparseVoxels(sc, 64, true, 1.f, params); });
        return v;
    };
    for (const Scene* sc : {&s, &t}) {
        SparseVoxelScene a = build(*sc, 2), b = build(*sc, 2), c = build(*sc, 1);
        EXPECT_GT(a.stats.activeVoxels, 100u);
        EXPECT_TRUE(sameScene(a, b)) << "two runs differ";
        EXPECT_TRUE(sameScene(a, c)) << "1 vs 2 threads differ";
    }
}

// AO's sparse grid keeps opacity alone (SparseBuildOptions::attributes): the same opacity
// and directional levels bit for bit as a grid with attributes, no albedo, normal or
// emission, and less memory.
TEST(VdbVoxelize, AnAoGridKeepsOpacityAlone) {
    // With a quad whose alpha-masked material is cut away everywhere: the grid without
    // attributes still applies the alpha test when it marks voxels.
    Scene s = floorAndBox();
    const size_t unmasked = voxelizeSparse(s, 48).stats.activeVoxels;
    const uint32_t cut = vcttest::addMaterial(s, glm::vec3(0.5f));
    s.materials[cut].alphaMask = true;
    s.materials[cut].alphaCutoff = 0.5f;
    s.materials[cut].baseColorFactor.a = 0.2f;
    vcttest::addQuad(s, {-0.5f, 0.6f, -0.5f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, cut);  // inside the box
    vcttest::finish(s);
    SparseBuildOptions options;
    options.anisotropic = true;
    const SparseVoxelScene full = buildSparseVoxels(s, 48, false, 0.f, ParamMap(), options);
    options.attributes = false;
    const SparseVoxelScene ao = buildSparseVoxels(s, 48, false, 0.f, ParamMap(), options);
    EXPECT_TRUE(full.albedo && full.normal && full.emission);
    EXPECT_FALSE(ao.albedo || ao.normal || ao.emission);
    ASSERT_EQ(ao.opacityLevels.size(), full.opacityLevels.size());
    for (size_t k = 0; k < ao.opacityLevels.size(); ++k)
        EXPECT_TRUE(sameBits(*ao.opacityLevels[k], *full.opacityLevels[k])) << "level " << k;
    for (size_t axis = 0; axis < ao.directional.size(); ++axis) {
        ASSERT_EQ(ao.directional[axis].size(), full.directional[axis].size());
        ASSERT_FALSE(ao.directional[axis].empty());
        for (size_t k = 0; k < ao.directional[axis].size(); ++k)
            EXPECT_TRUE(sameBits(*ao.directional[axis][k].opacity, *full.directional[axis][k].opacity))
                << "axis " << axis << " level " << k;
    }
    EXPECT_GT(ao.stats.activeVoxels, 100u);
    EXPECT_EQ(ao.opacity->activeVoxelCount(), unmasked);
    EXPECT_LT(ao.stats.memoryBytes, full.stats.memoryBytes);
}

// A quad as two triangles, corners in order.
void addQuadCorners(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t m) {
    addTriangle(s, a, b, c, m);
    addTriangle(s, a, c, d, m);
}

// Length of [lo, hi] inside [k, k + 1].
double overlap(double lo, double hi, int k) { return std::max(0.0, std::min(hi, k + 1.0) - std::max(lo, double(k))); }

// vct.voxel.edges=coverage: a level-0 voxel of a flat sheet holds the share of its column the
// sheet covers, the product of the rectangle's overlaps with the column's two sides (a closed
// form independent of the voxelizer's clipping); a sloped sheet's voxels over wholly covered
// columns stay 1 (no gap opens along a sheet that crosses voxels diagonally); by default every
// occupied voxel is 1.
TEST(VdbVoxelize, EdgeCoverageHoldsTheShareOfTheColumnASheetCovers) {
    Scene s;
    const uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    const double x0 = 2.3, x1 = 7.6, z0 = 3.45, z1 = 6.2, y = 4.5;  // flat sheet
    addQuadCorners(s, glm::vec3(x0, y, z0), glm::vec3(x1, y, z0), glm::vec3(x1, y, z1), glm::vec3(x0, y, z1), m);
    const float sz0 = 7.3f, sz1 = 9.1f;  // sloped sheet: y from 1 to 3 across x, dominant axis y
    addQuadCorners(s, glm::vec3(2.3f, 1.f, sz0), glm::vec3(2.3f, 1.f, sz1), glm::vec3(7.6f, 3.f, sz1),
                   glm::vec3(7.6f, 3.f, sz0), m);
    s.bounds.expand(glm::vec3(0.f));
    s.bounds.expand(glm::vec3(10.f));
    for (bool attributes : {true, false}) {
        const SparseVoxelScene v = voxelizeSparse(s, s.bounds, 24, false, attributes, true);
        const SparseVoxelScene occupied = voxelizeSparse(s, s.bounds, 24, false, attributes, false);
        EXPECT_EQ(activeSet(*v.opacity), activeSet(*occupied.opacity)) << "the same voxels are occupied";
        for (auto it = occupied.opacity->cbeginValueOn(); it; ++it) EXPECT_EQ(*it, 1.f);
        const glm::dvec3 o(v.origin);
        const double inv = 1.0 / double(v.voxelSize);
        const double ylo = (y - o.y) * inv;
        int flat = 0, partial = 0, slopedFull = 0;
        double maxErr = 0.0;
        for (auto it = v.opacity->cbeginValueOn(); it; ++it) {
            const openvdb::Coord c = it.getCoord();
            if (double(c.y()) <= ylo + 1.0 && double(c.y()) + 1.0 >= ylo - 1.0 && c.z() < int((sz0 - o.z) * inv) - 1) {
                const double want = overlap((x0 - o.x) * inv, (x1 - o.x) * inv, c.x()) *
                                    overlap((z0 - o.z) * inv, (z1 - o.z) * inv, c.z());
                maxErr = std::max(maxErr, std::abs(double(*it) - want));
                ++flat;
                partial += want > 0.01 && want < 0.99;
            } else if (c.z() >= int((sz0 - o.z) * inv) + 1 && c.z() + 1 <= int((sz1 - o.z) * inv) &&
                       c.x() >= int((2.3 - o.x) * inv) + 1 && c.x() + 1 <= int((7.6 - o.x) * inv)) {
                EXPECT_EQ(*it, 1.f) << "sloped sheet, voxel " << c;
                ++slopedFull;
            }
        }
        EXPECT_GE(flat, 80);
        EXPECT_GE(partial, 30) << "the flat sheet's rim voxels";
        EXPECT_GE(slopedFull, 40);
        // Steps of 1/1024 and float clipping.
        EXPECT_LE(maxErr, 0.5 / 1024.0 + 1e-5) << (attributes ? "lit grid" : "AO grid");
    }
}

// Where sheets of two dominant axes cross one voxel (a ceiling's edge on a wall) the voxel
// stays opaque: the two sheets' shares, each of its own axis, would leave a gap the closed
// corner does not have. Without the wall the same voxel holds the ceiling's share alone.
TEST(VdbVoxelize, EdgeCoverageKeepsVoxelsWhereSheetsOfTwoAxesMeetOpaque) {
    auto build = [](bool wall) {
        Scene s;
        const uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
        addQuadCorners(s, glm::vec3(1.5f, 4.3f, 1.5f), glm::vec3(5.3f, 4.3f, 1.5f), glm::vec3(5.3f, 4.3f, 8.5f),
                       glm::vec3(1.5f, 4.3f, 8.5f), m);
        if (wall)
            addQuadCorners(s, glm::vec3(5.3f, 0.5f, 1.5f), glm::vec3(5.3f, 4.3f, 1.5f), glm::vec3(5.3f, 4.3f, 8.5f),
                           glm::vec3(5.3f, 0.5f, 8.5f), m);
        s.bounds.expand(glm::vec3(0.f));
        s.bounds.expand(glm::vec3(10.f));
        return voxelizeSparse(s, s.bounds, 12, false, false, true);
    };
    const SparseVoxelScene closed = build(true), open = build(false);
    ASSERT_FLOAT_EQ(closed.voxelSize, 1.f);
    const glm::vec3 o = closed.origin;
    const openvdb::Coord corner(int(std::floor(5.3f - o.x)), int(std::floor(4.3f - o.y)), int(std::floor(5.f - o.z)));
    const double share = (5.3 - o.x) - std::floor(5.3 - o.x);
    EXPECT_NEAR(open.opacity->tree().getValue(corner), share, 1e-3) << "the ceiling's share alone";
    EXPECT_EQ(closed.opacity->tree().getValue(corner), 1.f) << "ceiling meets wall";
    // The ceiling's other rim, with no wall under it, keeps its share (0.5 of its voxel).
    const openvdb::Coord rim(int(std::floor(1.5f - o.x)), corner.y(), corner.z());
    EXPECT_NEAR(closed.opacity->tree().getValue(rim), 0.5, 1e-3);
}

// vct.voxel.edges=sheet: a voxel its sheets cross along one dominant axis holds their span along
// it inside the voxel (vox_sheetSpanFixed, rounded outwards to 1/1024): a flat sheet's own height
// in its voxel, a sloped sheet's rise over the column; the opacity is the coverage's.
TEST(VdbVoxelize, SheetsHoldTheSpanOfTheirSurfaceInTheVoxel) {
    Scene s;
    const uint32_t m = vcttest::addMaterial(s, glm::vec3(0.5f));
    const float y = 4.37f;  // flat sheet, dominant axis y
    addQuadCorners(s, glm::vec3(2.3f, y, 3.45f), glm::vec3(7.6f, y, 3.45f), glm::vec3(7.6f, y, 6.2f),
                   glm::vec3(2.3f, y, 6.2f), m);
    // Sloped sheet: y = 1 + 2 (x - 2.3) / 5.3 over z in [7.3, 9.1], dominant axis y.
    addQuadCorners(s, glm::vec3(2.3f, 1.f, 7.3f), glm::vec3(2.3f, 1.f, 9.1f), glm::vec3(7.6f, 3.f, 9.1f),
                   glm::vec3(7.6f, 3.f, 7.3f), m);
    s.bounds.expand(glm::vec3(0.f));
    s.bounds.expand(glm::vec3(10.f));
    const SparseVoxelScene v = voxelizeSparse(s, s.bounds, 24, false, false, true, true);
    const SparseVoxelScene coverage = voxelizeSparse(s, s.bounds, 24, false, false, true, false);
    ASSERT_TRUE(v.sheet);
    EXPECT_FALSE(coverage.sheet) << "coverage alone keeps no spans";
    EXPECT_EQ(activeSet(*v.opacity), activeSet(*coverage.opacity));
    for (auto it = v.opacity->cbeginValueOn(); it; ++it)
        EXPECT_EQ(*it, coverage.opacity->tree().getValue(it.getCoord())) << it.getCoord();
    const glm::dvec3 o(v.origin);
    const double inv = 1.0 / double(v.voxelSize), step = 1.0 / 1024.0;
    auto clamp01 = [](double x) { return std::clamp(x, 0.0, 1.0); };
    int flat = 0, sloped = 0;
    for (auto it = v.sheet->cbeginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        const openvdb::Vec3s t = *it;  // lo, hi, axis
        ASSERT_EQ(t[2], 1.f) << "dominant axis y, voxel " << c;
        ASSERT_LE(t[0], t[1]) << c;
        const double x0 = c.x(), x1 = c.x() + 1.0;
        const double zMid = (c.z() + 0.5) / inv + o.z;
        if (zMid > 3.6 && zMid < 6.0 && (x0 / inv + o.x) > 2.4 && (x1 / inv + o.x) < 7.5) {
            const double here = clamp01((y - o.y) * inv - c.y());
            EXPECT_LE(t[0], here + 1e-6) << c;
            EXPECT_GE(t[1], here - 1e-6) << c;
            EXPECT_LE(t[1] - t[0], 2.0 * step + 1e-6) << "a flat sheet's span is its height, voxel " << c;
            ++flat;
        } else if (zMid > 7.5 && zMid < 8.9 && (x0 / inv + o.x) > 2.4 && (x1 / inv + o.x) < 7.5) {
            auto planeY = [&](double xv) { return (1.0 + 2.0 * ((xv / inv + o.x) - 2.3) / 5.3 - o.y) * inv - c.y(); };
            const double lo = clamp01(planeY(x0)), hi = clamp01(planeY(x1));
            if (lo >= hi) continue;  // the plane leaves this voxel over the column: a neighbour's
            EXPECT_NEAR(t[0], lo, step + 1e-4) << "sloped sheet, voxel " << c;
            EXPECT_NEAR(t[1], hi, step + 1e-4) << "sloped sheet, voxel " << c;
            ++sloped;
        }
    }
    EXPECT_GE(flat, 40);
    EXPECT_GE(sloped, 40);
}

TEST(VdbVoxelize, AveragesMatchQuantizedMaterial) {
    Scene s = floorAndBox();
    SparseVoxelScene v = voxelizeSparse(s, 32);
    // A floor voxel far from the box: only the floor overlaps it.
    glm::vec3 p = (glm::vec3(-3.3f, 0.f, -3.3f) - v.origin) / v.voxelSize;
    openvdb::Coord ijk(int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z)));
    ASSERT_TRUE(v.opacity->tree().isValueOn(ijk));
    EXPECT_EQ(v.opacity->tree().getValue(ijk), 1.f);
    openvdb::Vec3s a = v.albedo->tree().getValue(ijk), n = v.normal->tree().getValue(ijk);
    // 12-bit fixed point of the GPU path: round(x * 4095) / 4095.
    for (int c = 0; c < 3; ++c) {
        double expected = std::round(double(glm::vec3(0.2f, 0.5f, 0.8f)[c]) * 4095.0) / 4095.0;
        EXPECT_NEAR(a[c], expected, 1e-6);
    }
    EXPECT_NEAR(n[1], 1.f, 1e-6);
    EXPECT_NEAR(std::abs(n[0]) + std::abs(n[2]), 0.f, 1e-6);
    EXPECT_EQ(v.emission->tree().getValue(ijk), openvdb::Vec3s(0.f));
    // A voxel on the box top (emissive): emission 3 in blue.
    glm::vec3 q = (glm::vec3(0.1f, 1.5f, 0.1f) - v.origin) / v.voxelSize;
    openvdb::Coord top(int(std::floor(q.x)), int(std::floor(q.y)), int(std::floor(q.z)));
    ASSERT_TRUE(v.opacity->tree().isValueOn(top));
    EXPECT_NEAR(v.emission->tree().getValue(top)[2], 3.f, 1e-3);
}

// A lit, unshadowed floor voxel: L = albedo / pi * E, E = lux * cos; the same at two resolutions.
TEST(VdbVoxelize, InjectedRadianceIsResolutionIndependent) {
    Scene s = floorAndBox();
    const glm::vec3 toSun = -s.lights[0].direction;
    for (int res : {32, 64}) {
        ParamMap params;
        params.set("vct.bounces", "0");  // direct light alone: no gather, not even the emitters'
        params.set("vct.bounce.emitters", "0");
        SparseVoxelScene v = buildSparseVoxels(s, res, true, 1.f, params);
        glm::vec3 p = (glm::vec3(-3.3f, 0.f, -3.3f) - v.origin) / v.voxelSize;
        openvdb::Coord ijk(int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z)));
        openvdb::Vec3s L = v.radiance->tree().getValue(ijk), a = v.albedo->tree().getValue(ijk);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(L[c], a[c] / kPi * 2.0 * toSun.y, 1e-4) << "res " << res;
        // In the box's shadow (the sun comes from -x, -z, above): only the floor, unlit.
        glm::vec3 sh = (glm::vec3(1.2f, 0.f, 1.1f) - v.origin) / v.voxelSize;
        openvdb::Coord sij(int(std::floor(sh.x)), int(std::floor(sh.y)), int(std::floor(sh.z)));
        ASSERT_TRUE(v.opacity->tree().isValueOn(sij));
        EXPECT_EQ(v.radiance->tree().getValue(sij), openvdb::Vec3s(0.f)) << "res " << res;
        EXPECT_GT(v.stats.memoryBytes, 0u);
        EXPECT_GT(v.stats.denseBytes, 0u);
    }
}

// Bounces only add light: each voxel's radiance is its direct light plus albedo times what it
// gathers (>= 0), the shadowed floor beside the box receives light from the box's lit faces
// and the sunlit floor, and a second bounce adds less than the first (albedo < 1).
TEST(VdbVoxelize, BouncesAddLightThatShrinksWithEachBounce) {
    Scene s = floorAndBox();
    std::vector<SparseVoxelScene> v;
    for (const char* bounces : {"0", "1", "2"}) {
        ParamMap params;
        params.set("vct.bounces", bounces);
        params.set("vct.bounce.emitters", "0");  // the lights' bounces alone (the box top emits)
        v.push_back(buildSparseVoxels(s, 32, true, 0.f, params));
    }
    double total[3] = {0, 0, 0};
    for (int b = 0; b < 3; ++b)
        for (auto it = v[size_t(b)].radiance->tree().cbeginValueOn(); it; ++it) {
            const openvdb::Vec3s L = *it;
            total[b] += L[0] + L[1] + L[2];
            if (b == 0) continue;
            const openvdb::Vec3s L0 = v[0].radiance->tree().getValue(it.getCoord());
            for (int c = 0; c < 3; ++c) ASSERT_GE(L[c], L0[c] - 1e-6f);
        }
    glm::vec3 sh = (glm::vec3(1.2f, 0.f, 1.1f) - v[0].origin) / v[0].voxelSize;
    const openvdb::Coord shadowed(int(std::floor(sh.x)), int(std::floor(sh.y)), int(std::floor(sh.z)));
    EXPECT_EQ(v[0].radiance->tree().getValue(shadowed), openvdb::Vec3s(0.f));
    EXPECT_GT(v[1].radiance->tree().getValue(shadowed)[0], 0.f);
    EXPECT_GT(total[1], total[0]);
    EXPECT_GT(total[2], total[1]);
    EXPECT_LT(total[2] - total[1], total[1] - total[0]);
}

// Emitters light the voxels one reflection deep, as a light does: a floor of albedo 0.5 under
// an emitting plate (radiance 1, facing down, black) of half-side a = 4 at height h = 0.5, no
// lights, no sky, no bounces. Injection alone leaves the floor black; the emitters' gather
// gives it albedo * F, F = (2 / pi) (2 X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2))) = 0.987 the
// plate's view factor from the floor's centre (X = a / h). The plate is a one-voxel sheet:
// opacity levels pass up to 13.5% of a cone through it (docs/convergence.md), hence the
// tolerance below.
TEST(VdbVoxelize, EmittersLightTheVoxelsOneReflectionDeep) {
    Scene s;
    const float albedo = 0.5f, a = 4.f, h = 0.5f;
    const uint32_t floor = vcttest::addMaterial(s, glm::vec3(albedo));
    const uint32_t glow = vcttest::addMaterial(s, glm::vec3(0.f), glm::vec3(1.f));
    vcttest::addQuad(s, {-a, 0, -a}, {0, 0, 2 * a}, {2 * a, 0, 0}, floor);  // +y
    vcttest::addQuad(s, {-a, h, -a}, {2 * a, 0, 0}, {0, 0, 2 * a}, glow);   // -y
    vcttest::finish(s);
    const double X = a / h, q = std::sqrt(1.0 + X * X);
    const double F = 2.0 / kPi * 2.0 * X / q * std::atan(X / q);
    for (const char* emitters : {"0", "1"}) {
        ParamMap params;
        params.set("vct.bounces", "0");
        params.set("vct.bounce.emitters", emitters);
        const SparseVoxelScene v = buildSparseVoxels(s, 64, true, 0.f, params);
        const glm::vec3 p = (glm::vec3(0.f, 0.01f, 0.f) - v.origin) / v.voxelSize;
        const openvdb::Coord ijk(int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z)));
        ASSERT_TRUE(v.opacity->tree().isValueOn(ijk));
        const float alpha = v.opacity->tree().getValue(ijk);
        const openvdb::Vec3s L = v.radiance->tree().getValue(ijk) / alpha;
        for (int c = 0; c < 3; ++c) {
            if (emitters[0] == '0')
                EXPECT_EQ(L[c], 0.f);
            else
                EXPECT_NEAR(L[c], albedo * F, 0.15 * albedo * F) << "F " << F;
        }
        std::printf("[emitters %s] floor voxel radiance %.4f, albedo * F %.4f\n", emitters, L[0], albedo * F);
    }
}

// Levels against an independent dense box filter with GL's child ranges.
TEST(VdbVoxelize, LevelsMatchDenseBoxFilter) {
    Scene s = floorAndBox();
    ParamMap params;
    SparseVoxelScene v = buildSparseVoxels(s, 24, true, 1.f, params);  // non-power-of-two sizes
    ASSERT_EQ(int(v.opacityLevels.size()), v.levels);
    glm::ivec3 size = v.resolution;
    auto idx = [](glm::ivec3 sz, int x, int y, int z) { return (size_t(z) * sz.y + y) * sz.x + x; };
    std::vector<float> dense(size_t(size.x) * size.y * size.z, 0.f);
    std::vector<glm::vec3> denseL(dense.size(), glm::vec3(0.f));
    auto opAcc = v.opacity->getConstAccessor();
    auto rAcc = v.radiance->getConstAccessor();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                dense[idx(size, x, y, z)] = opAcc.getValue({x, y, z});
                auto r = rAcc.getValue({x, y, z});
                denseL[idx(size, x, y, z)] = glm::vec3(r[0], r[1], r[2]);
            }
    for (int level = 1; level < v.levels; ++level) {
        glm::ivec3 dst = glm::max(size / 2, glm::ivec3(1));
        std::vector<float> next(size_t(dst.x) * dst.y * dst.z);
        std::vector<glm::vec3> nextL(next.size());
        for (int z = 0; z < dst.z; ++z)
            for (int y = 0; y < dst.y; ++y)
                for (int x = 0; x < dst.x; ++x) {
                    glm::ivec3 p(x, y, z), lo, hi;
                    for (int a = 0; a < 3; ++a) {
                        lo[a] = std::min(2 * p[a], size[a] - 1);
                        hi[a] = p[a] == dst[a] - 1 ? size[a] - 1 : std::min(2 * p[a] + 1, size[a] - 1);
                    }
                    double sum = 0;
                    glm::dvec3 sumL(0.0);
                    for (int cz = lo.z; cz <= hi.z; ++cz)
                        for (int cy = lo.y; cy <= hi.y; ++cy)
                            for (int cx = lo.x; cx <= hi.x; ++cx) {
                                sum += dense[idx(size, cx, cy, cz)];
                                sumL += glm::dvec3(denseL[idx(size, cx, cy, cz)]);
                            }
                    glm::ivec3 n = hi - lo + 1;
                    next[idx(dst, x, y, z)] = float(sum / (n.x * n.y * n.z));
                    nextL[idx(dst, x, y, z)] = glm::vec3(sumL / double(n.x * n.y * n.z));
                }
        dense.swap(next);
        denseL.swap(nextL);
        size = dst;
        ASSERT_EQ(v.levelSize(level), size);
        auto acc = v.opacityLevels[size_t(level)]->getConstAccessor();
        auto racc = v.radianceLevels[size_t(level)]->getConstAccessor();
        double maxErr = 0, maxErrL = 0;
        size_t nonzero = 0;
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    float d = dense[idx(size, x, y, z)];
                    nonzero += d > 0.f;
                    EXPECT_EQ(acc.isValueOn({x, y, z}), d > 0.f);
                    maxErr = std::max(maxErr, double(std::abs(acc.getValue({x, y, z}) - d)));
                    auto r = racc.getValue({x, y, z});
                    maxErrL = std::max(maxErrL, double(glm::length(glm::vec3(r[0], r[1], r[2]) - denseL[idx(size, x, y, z)])));
                }
        EXPECT_LT(maxErr, 1e-5) << "level " << level;
        EXPECT_LT(maxErrL, 1e-4) << "level " << level;
        EXPECT_GT(nonzero, 0u);
    }
    EXPECT_EQ(std::max(size.x, std::max(size.y, size.z)), 1);  // the top level is one voxel along the longest axis
}

TEST(VdbVoxelize, RejectsBadInput) {
    Scene s = floorAndBox();
    ParamMap params;
    EXPECT_THROW(buildSparseVoxels(s, 2, false, 1.f, params), InternalError);
    EXPECT_THROW(buildSparseVoxels(s, 32, true, -1.f, params), InternalError);
    ParamMap bounces;
    bounces.set("vct.bounces", "9");  // outside [0, 8]
    EXPECT_THROW(buildSparseVoxels(s, 32, true, 1.f, bounces), UsageError);
    Scene bad = s;
    bad.positions[0].x = std::nanf("");
    EXPECT_THROW(voxelizeSparse(bad, 32), std::runtime_error);
}

}  // namespace
}  // namespace vct
