// The sparse CPU path (src/vdb) against the dense GPU path (src/voxelize + src/cone) on the
// same scene (a floor, two boxes, a point light), the same layout and parameters, and the same
// G-buffer: the occupied voxel sets, the level-0 attributes and radiance, and the AO and
// indirect images must agree. The dense path stores half floats (R16F / RGBA16F) and samples
// with the GPU's texture units; the sparse path holds float32 and samples with
// tools::BoxSampler, so the images agree to a stated RMSE, not bit for bit.
#include "cone/cone_bounce.h"
#include "cone/cone_settings.h"
#include "cone/cone_trace.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "raster/gbuffer_pass.h"
#include "core/gpu_scene.h"
#include "core/view.h"
#include "support/test_scenes.h"
#include "support/filter_precision.h"
#include "vdb/sparse_cone.h"
#include "voxelize/voxelize.h"
#include "voxelize/voxelize_shared.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vct {
namespace {

Scene boxesScene() {
    Scene s;
    uint32_t floor = vcttest::addMaterial(s, glm::vec3(0.7f, 0.65f, 0.6f));
    uint32_t red = vcttest::addMaterial(s, glm::vec3(0.8f, 0.15f, 0.1f));
    uint32_t glow = vcttest::addMaterial(s, glm::vec3(0.3f), glm::vec3(0.f, 0.5f, 1.f));
    vcttest::addQuad(s, {-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, floor);  // +y
    vcttest::addBox(s, {-1.5f, 0, -1.f}, {-0.3f, 1.4f, 0.5f}, red);
    vcttest::addBox(s, {0.6f, 0, 0.2f}, {1.4f, 0.6f, 1.1f}, glow);
    vcttest::addQuad(s, {-3, 0, -3}, {6, 0, 0}, {0, 2.5f, 0}, floor);  // back wall, +z
    Light l;
    l.type = LightType::Point;
    l.position = glm::vec3(0.5f, 2.2f, 1.5f);
    l.color = glm::vec3(6.f);
    s.lights.push_back(l);
    Camera cam;
    cam.eye = glm::vec3(0.5f, 2.4f, 4.5f);
    cam.target = glm::vec3(0.f, 0.3f, 0.f);
    cam.yfov = 0.9f;
    s.cameras.push_back(cam);
    vcttest::finish(s);
    return s;
}

// Both paths built with the same parameters: isotropic levels and no bounces (the base
// case), or the GPU path's defaults, directional levels and vct.bounces bounces.
struct Fixture {
    Scene scene = boxesScene();
    GpuScene gpu;
    VoxelGrid grid;
    SparseVoxelScene sparse;
    ParamMap params;
    PassTimer timer;
    float sky = 0.5f;
    int res = 64;

    // emitters: vct.bounce.emitters (off: the voxels hold what injection put there, with no bounces)
    Fixture(bool anisotropic, int bounces, bool emitters = true) {
        GlContext& gl = GlContext::shared();
        gpu = uploadScene(scene);
        params.set("vct.aniso", anisotropic ? "1" : "0");
        params.set("vct.bounces", std::to_string(bounces));
        params.set("vct.bounce.emitters", emitters ? "1" : "0");
        const ConeSettings cone = readConeSettings(params);
        grid = voxelizeScene(gpu, scene.bounds, res, params, timer);
        injectRadiance(grid, gpu, scene, params, timer);
        traceVoxelBounces(grid, sky, cone, params, timer);
        buildMips(grid, anisotropic, timer);
        gl.checkErrors("vdb_vs_gl: dense grid");
        SparseBuildOptions options;
        options.anisotropic = anisotropic;
        sparse = buildSparseVoxels(scene, res, true, sky, params, options);
    }
};

Fixture& fixture() {
    static Fixture f(false, 0, false);
    return f;
}

std::vector<float> readLevel0(const GlTexture& t, glm::ivec3 size, int channels) {
    std::vector<float> data(size_t(size.x) * size.y * size.z * channels);
    glGetTextureImage(t.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT, GLsizei(data.size() * sizeof(float)),
                      data.data());
    return data;
}

TEST(VdbVsGl, SameLayoutOccupancyAndRadiance) {
    Fixture& f = fixture();
    ASSERT_EQ(f.sparse.resolution, f.grid.resolution);
    ASSERT_EQ(f.sparse.levels, f.grid.levels);
    ASSERT_FLOAT_EQ(f.sparse.voxelSize, f.grid.voxelSize);
    const glm::ivec3 r = f.grid.resolution;
    std::vector<float> opacity = readLevel0(f.grid.opacity, r, 1);
    std::vector<float> albedo = readLevel0(f.grid.albedo, r, 4);
    std::vector<float> radiance = readLevel0(f.grid.radiance, r, 4);
    GlContext::shared().checkErrors("vdb_vs_gl: readback");
    auto opAcc = f.sparse.opacity->getConstAccessor();
    auto alAcc = f.sparse.albedo->getConstAccessor();
    auto raAcc = f.sparse.radiance->getConstAccessor();
    size_t gpuOccupied = 0, onlyGpu = 0, onlySparse = 0, both = 0;
    double maxAlbedoErr = 0.0, maxRadianceRelErr = 0.0;
    for (int z = 0; z < r.z; ++z)
        for (int y = 0; y < r.y; ++y)
            for (int x = 0; x < r.x; ++x) {
                const size_t i = (size_t(z) * r.y + y) * r.x + x;
                const bool g = opacity[i] > 0.f, s = opAcc.isValueOn({x, y, z});
                gpuOccupied += g;
                onlyGpu += g && !s;
                onlySparse += s && !g;
                if (!(g && s)) continue;
                ++both;
                const openvdb::Vec3s a = alAcc.getValue({x, y, z}), L = raAcc.getValue({x, y, z});
                for (int c = 0; c < 3; ++c) {
                    maxAlbedoErr = std::max(maxAlbedoErr, double(std::abs(a[c] - albedo[4 * i + c])));
                    const double rel = std::abs(L[c] - radiance[4 * i + c]) / std::max(1e-2, double(std::abs(L[c])));
                    maxRadianceRelErr = std::max(maxRadianceRelErr, rel);
                }
            }
    std::printf("[vdb_vs_gl] occupied: gpu %zu, sparse %zu, only gpu %zu, only sparse %zu; max albedo err %.2e, "
                "max radiance rel err %.2e\n",
                gpuOccupied, f.sparse.stats.activeVoxels, onlyGpu, onlySparse, maxAlbedoErr, maxRadianceRelErr);
    EXPECT_GT(both, 1000u);
    // Same SAT in float on both sides: only rounding differences (FMA) may flip a boundary voxel.
    EXPECT_LE(onlyGpu + onlySparse, gpuOccupied / 1000);
    EXPECT_LT(maxAlbedoErr, 2e-3);       // half-float storage of the GPU albedo
    // Half floats hold ~3 decimal digits; a voxel whose shadow walk grazes an edge may differ.
    EXPECT_LT(maxRadianceRelErr, 0.01) << "radiance differs beyond half precision";
}

// Calls f(x, y, z, index) for every voxel of a grid of size r, in the order of a level read back
// with readLevel0.
template <class F>
void forEachVoxel(glm::ivec3 r, F f) {
    for (int z = 0; z < r.z; ++z)
        for (int y = 0; y < r.y; ++y)
            for (int x = 0; x < r.x; ++x) f(x, y, z, (size_t(z) * r.y + y) * r.x + x);
}

// The boxes with a tilted plate among them, whose rim crosses columns in part.
Scene boxesAndATiltedPlate() {
    Scene s = boxesScene();
    vcttest::addQuad(s, {0.3f, 1.6f, -0.4f}, {0.9f, 0.35f, 0.1f}, {-0.2f, 0.1f, 0.7f}, s.triangleMaterial[0]);
    vcttest::finish(s);
    return s;
}

// `s` voxelized at 48^3 by both voxelizers with vct.voxel.edges=`edges`, lit (with attributes)
// or for AO (opacity alone).
struct BothGrids {
    VoxelGrid dense;
    SparseVoxelScene sparse;
};
BothGrids voxelizeBoth(const Scene& s, const GpuScene& gpu, const char* edges, bool lit) {
    ParamMap params;
    params.set("vct.voxel.edges", edges);
    PassTimer timer;
    const std::string e = edges;
    BothGrids out{voxelizeScene(gpu, s.bounds, 48, params, timer, lit, lit),
                  voxelizeSparse(s, s.bounds, 48, lit, lit, e != "occupied", e == "sheet")};
    GlContext::shared().checkErrors(std::string("vdb_vs_gl: ") + edges);
    return out;
}

// vct.voxel.edges=coverage: the dense voxelizer's coverage pass and resolve give level 0 the
// values the sparse voxelizer gives, voxel by voxel (steps of 1/1024, exact in half floats), on
// the boxes scene and a tilted plate, for an AO grid (opacity alone) and a lit one.
TEST(VdbVsGl, EdgeCoverageLevelZeroMatchesTheSparseOne) {
    const Scene s = boxesAndATiltedPlate();
    GlContext& gl = GlContext::shared();  // before the upload: it makes the context current
    const GpuScene gpu = uploadScene(s);
    for (bool lit : {false, true}) {
        const BothGrids both = voxelizeBoth(s, gpu, "coverage", lit);
        const VoxelGrid& grid = both.dense;
        const SparseVoxelScene& sparse = both.sparse;
        ASSERT_EQ(sparse.resolution, grid.resolution);
        const glm::ivec3 r = grid.resolution;
        const std::vector<float> opacity = readLevel0(grid.opacity, r, 1);
        gl.checkErrors("vdb_vs_gl: edge coverage");
        auto acc = sparse.opacity->getConstAccessor();
        size_t partial = 0, full = 0, differ = 0;
        double maxDiff = 0.0;
        forEachVoxel(r, [&](int x, int y, int z, size_t i) {
            const float g = opacity[i], c = acc.getValue({x, y, z});
            partial += c > 0.f && c < 1.f;
            full += c == 1.f;
            differ += g != c;
            maxDiff = std::max(maxDiff, double(std::abs(g - c)));
        });
        std::printf("[vdb_vs_gl] edge coverage (%s): %zu partial, %zu full voxels; %zu differ, max %.4f\n",
                    lit ? "lit" : "AO", partial, full, differ, maxDiff);
        EXPECT_GT(partial, 20u) << "the tilted plate's rim";
        EXPECT_GT(full, 3000u);
        // Float clipping on both sides; a fused multiply-add may move a sum across a step.
        EXPECT_LE(differ, (partial + full) / 1000);
        EXPECT_LE(maxDiff, 1.5 / 1024.0);
    }
}

// vct.voxel.edges=sheet: the dense sheet pass (voxelize_sheets.glsl) gives level 0's sheet
// texels the sparse voxelizer gives: the same voxels hold a sheet, with the same axis and span
// (a rounding step apart at most where float clipping or a fused multiply-add moves a bound).
TEST(VdbVsGl, SheetTexelsMatchTheSparseOnes) {
    const Scene s = boxesAndATiltedPlate();
    GlContext& gl = GlContext::shared();  // before the upload: it makes the context current
    const BothGrids both = voxelizeBoth(s, uploadScene(s), "sheet", false);
    const VoxelGrid& grid = both.dense;
    const SparseVoxelScene& sparse = both.sparse;
    ASSERT_TRUE(grid.sheets);
    ASSERT_TRUE(sparse.sheet);
    const glm::ivec3 r = grid.resolution;
    const std::vector<float> texels = readLevel0(grid.sheets, r, 4);
    const std::vector<float> opacity = readLevel0(grid.opacity, r, 1);
    gl.checkErrors("vdb_vs_gl: sheets");
    auto acc = sparse.sheet->getConstAccessor();
    size_t sheets = 0, kindDiffers = 0, spanDiffers = 0;
    double maxDiff = 0.0;
    forEachVoxel(r, [&](int x, int y, int z, size_t i) {
        const glm::vec4 g(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2], texels[4 * i + 3]);
        EXPECT_EQ(g.x, opacity[i]) << "the texel's opacity is level 0's";
        openvdb::Vec3s c;
        const bool isSheet = acc.probeValue({x, y, z}, c);
        sheets += isSheet;
        if (isSheet != (g.w >= 0.f) || (isSheet && c[2] != g.w)) {
            ++kindDiffers;
            return;
        }
        if (!isSheet) return;
        const double d = std::max(std::abs(double(c[0]) - g.y), std::abs(double(c[1]) - g.z));
        spanDiffers += d > 0.0;
        maxDiff = std::max(maxDiff, d);
    });
    std::printf("[vdb_vs_gl] sheets: %zu voxels; %zu differ in kind, %zu in span, max %.5f\n", sheets, kindDiffers,
                spanDiffers, maxDiff);
    EXPECT_GT(sheets, 3000u);
    EXPECT_EQ(kindDiffers, 0u);
    EXPECT_LE(spanDiffers, sheets / 500);
    EXPECT_LE(maxDiff, 1.0 / 1024.0 + 1e-6);

    // The extent bits (vox_extentBits) of every occupied voxel, and how many hold less than the
    // whole voxel across some axis (rims, the boxes' corners).
    ASSERT_TRUE(grid.sheetExtents);
    ASSERT_TRUE(sparse.sheetExtent);
    std::vector<uint32_t> bits(size_t(r.x) * r.y * r.z);
    glGetTextureImage(grid.sheetExtents.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(bits.size() * sizeof(uint32_t)),
                      bits.data());
    gl.checkErrors("vdb_vs_gl: sheet extents");
    openvdb::tree::ValueAccessor<const openvdb::UInt32Tree> extents(*sparse.sheetExtent);
    size_t occupied = 0, partial = 0, extentDiffers = 0;
    forEachVoxel(r, [&](int x, int y, int z, size_t i) {
        if (!(opacity[i] > 0.f)) return;
        ++occupied;
        const uint32_t c = extents.getValue({x, y, z});
        extentDiffers += c != bits[i];
        for (int a = 0; a < 3; ++a) {
            const glm::vec2 e = gpu::vox_extentSpan(c, a);
            if (e.y - e.x < 1.f) {
                ++partial;
                break;
            }
        }
    });
    std::printf("[vdb_vs_gl] sheet extents: %zu occupied voxels, %zu not whole across, %zu differ\n", occupied,
                partial, extentDiffers);
    EXPECT_GT(partial, occupied / 2) << "a sheet's voxels hold it along its axis";
    EXPECT_LE(extentDiffers, occupied / 500);
}

struct Images {
    std::vector<float> gpuAo, cpuAo;
    std::vector<glm::vec3> gpuGi, cpuGi;
    std::vector<bool> valid;
};

Images renderBoth(Fixture& f, float radius) {
    const int w = 64, h = 64;
    View view = makeView(f.scene.cameras[0], w, h);
    GBuffer gb = renderGBuffer(f.gpu, view, f.timer);
    ConeSettings cs = readConeSettings(f.params);
    GlTexture ao = coneTraceAO(f.grid, gb, view, radius, cs, f.timer);
    GlTexture gi = coneTraceGI(f.grid, gb, view, f.sky, cs, f.timer);
    Image aoImg = readTexture2D(ao.id(), w, h, 1), giImg = readTexture2D(gi.id(), w, h, 4);
    Image pos = readTexture2D(gb.position.id(), w, h, 4), nrm = readTexture2D(gb.normal.id(), w, h, 4),
          geo = readTexture2D(gb.geomNormal.id(), w, h, 4), alb = readTexture2D(gb.albedo.id(), w, h, 4);
    GlContext::shared().checkErrors("vdb_vs_gl: cone tracing");
    std::vector<SparsePoint> pts(size_t(w) * h);
    Images out;
    out.valid.resize(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        pts[i].position = glm::vec3(pos.pixels[4 * i], pos.pixels[4 * i + 1], pos.pixels[4 * i + 2]);
        pts[i].normal = glm::vec3(nrm.pixels[4 * i], nrm.pixels[4 * i + 1], nrm.pixels[4 * i + 2]);
        pts[i].geomNormal = glm::vec3(geo.pixels[4 * i], geo.pixels[4 * i + 1], geo.pixels[4 * i + 2]);
        pts[i].albedo = glm::vec3(alb.pixels[4 * i], alb.pixels[4 * i + 1], alb.pixels[4 * i + 2]);
        pts[i].valid = pos.pixels[4 * i + 3] > 0.f;
        out.valid[i] = pts[i].valid;
        out.gpuAo.push_back(aoImg.pixels[i]);
        out.gpuGi.push_back(glm::vec3(giImg.pixels[4 * i], giImg.pixels[4 * i + 1], giImg.pixels[4 * i + 2]));
    }
    out.cpuAo = sparseConeAO(f.sparse, pts, radius, cs);
    out.cpuGi = sparseConeGI(f.sparse, pts, f.sky, cs);
    return out;
}

TEST(VdbVsGl, AoAndIndirectAgree) {
    const float radius = 1.f;
    Images im = renderBoth(fixture(), radius);
    double aoSq = 0, giSq = 0, giRef = 0, aoMax = 0;
    size_t n = 0;
    for (size_t i = 0; i < im.valid.size(); ++i) {
        if (!im.valid[i]) {
            EXPECT_EQ(im.cpuAo[i], 1.f);
            continue;
        }
        ++n;
        const double d = double(im.cpuAo[i]) - im.gpuAo[i];
        aoSq += d * d;
        aoMax = std::max(aoMax, std::abs(d));
        const glm::dvec3 g = glm::dvec3(im.cpuGi[i]) - glm::dvec3(im.gpuGi[i]);
        giSq += glm::dot(g, g) / 3.0;
        giRef += glm::dot(glm::dvec3(im.gpuGi[i]), glm::dvec3(im.gpuGi[i])) / 3.0;
        ASSERT_TRUE(std::isfinite(im.cpuAo[i]) && std::isfinite(im.cpuGi[i].x));
    }
    ASSERT_GT(n, im.valid.size() / 2);
    const double aoRmse = std::sqrt(aoSq / n), giRmse = std::sqrt(giSq / n), giRms = std::sqrt(giRef / n);
    std::printf("[vdb_vs_gl] %zu pixels: AO RMSE %.2e (max %.2e), indirect RMSE %.2e (image RMS %.4f, rel %.2e)\n", n,
                aoRmse, aoMax, giRmse, giRms, giRmse / giRms);
    // Stated agreement (observed on llvmpipe: AO RMSE 4.6e-8, indirect 7e-5 of the image RMS):
    // AO RMSE < 1e-3, indirect RMSE < 0.5% of the image's RMS; on hardware texture filtering
    // (support/filter_precision.h; an H200: 3.8e-3 and 0.32%) AO RMSE < 0.01, indirect 1%.
    EXPECT_LT(aoRmse, vcttest::filterTolerance(1e-3, 0.01));
    EXPECT_LT(giRmse, vcttest::filterTolerance(0.005, 0.01) * giRms);
}

struct Agreement {
    double aoRmse = 0, giRmse = 0, giRms = 0, giMeanRatio = 0;
};

Agreement agreement(const Images& im) {
    double aoSq = 0, giSq = 0, giRef = 0, cpuSum = 0, gpuSum = 0;
    size_t n = 0;
    for (size_t i = 0; i < im.valid.size(); ++i) {
        if (!im.valid[i]) continue;
        ++n;
        const double d = double(im.cpuAo[i]) - im.gpuAo[i];
        aoSq += d * d;
        const glm::dvec3 g = glm::dvec3(im.cpuGi[i]) - glm::dvec3(im.gpuGi[i]);
        giSq += glm::dot(g, g) / 3.0;
        giRef += glm::dot(glm::dvec3(im.gpuGi[i]), glm::dvec3(im.gpuGi[i])) / 3.0;
        cpuSum += im.cpuGi[i].x + im.cpuGi[i].y + im.cpuGi[i].z;
        gpuSum += im.gpuGi[i].x + im.gpuGi[i].y + im.gpuGi[i].z;
    }
    Agreement a;
    a.aoRmse = std::sqrt(aoSq / double(n));
    a.giRmse = std::sqrt(giSq / double(n));
    a.giRms = std::sqrt(giRef / double(n));
    a.giMeanRatio = cpuSum / gpuSum;
    return a;
}

// The directional levels hold what the GPU's anisoRadiance textures hold, level by level.
TEST(VdbVsGl, DirectionalLevelsMatchTheGpuTextures) {
    Fixture f(true, 0, false);
    ASSERT_TRUE(f.sparse.anisotropic());
    for (int d = 0; d < 6; ++d)
        for (int level = 1; level < std::min(f.grid.levels, 4); ++level) {
            const glm::ivec3 size = f.sparse.levelSize(level);
            std::vector<float> gpu(size_t(size.x) * size.y * size.z * 4);
            glGetTextureImage(f.grid.anisoRadiance[size_t(d)].id(), level - 1, GL_RGBA, GL_FLOAT,
                              GLsizei(gpu.size() * sizeof(float)), gpu.data());
            GlContext::shared().checkErrors("vdb_vs_gl: directional readback");
            auto opAcc = f.sparse.directional[size_t(d)][size_t(level - 1)].opacity->getConstAccessor();
            auto raAcc = f.sparse.directional[size_t(d)][size_t(level - 1)].radiance->getConstAccessor();
            double maxAlphaErr = 0, maxRadianceErr = 0;
            for (int z = 0; z < size.z; ++z)
                for (int y = 0; y < size.y; ++y)
                    for (int x = 0; x < size.x; ++x) {
                        const size_t i = 4 * ((size_t(z) * size.y + y) * size.x + x);
                        maxAlphaErr = std::max(maxAlphaErr, double(std::abs(opAcc.getValue({x, y, z}) - gpu[i + 3])));
                        const openvdb::Vec3s L = raAcc.getValue({x, y, z});
                        for (int c = 0; c < 3; ++c)
                            maxRadianceErr = std::max(
                                maxRadianceErr, std::abs(L[c] - gpu[i + c]) / std::max(0.05, double(std::abs(L[c]))));
                    }
            SCOPED_TRACE("direction " + std::to_string(d) + " level " + std::to_string(level));
            EXPECT_LT(maxAlphaErr, 2e-3);     // RGBA16F on the GPU
            EXPECT_LT(maxRadianceErr, 0.01);  // relative, as the level-0 radiance above
        }
}

// On the GPU path's defaults (directional levels, vct.bounces bounces, the emitters' gather:
// the scene's glowing box emits and the sky is 0.5) the images agree as closely as the
// isotropic base case's do: one cone march, one bounce rule.
TEST(VdbVsGl, DirectionalLevelsAndBouncesAgree) {
    for (int bounces : {0, 1}) {
        Fixture f(true, bounces);
        const Agreement a = agreement(renderBoth(f, 1.f));
        std::printf("[vdb_vs_gl] aniso, %d bounce(s): AO RMSE %.2e, indirect RMSE %.2e (image RMS %.4f, rel %.2e), "
                    "mean ratio sparse / dense %.4f\n",
                    bounces, a.aoRmse, a.giRmse, a.giRms, a.giRmse / a.giRms, a.giMeanRatio);
        // Hardware texture filtering (support/filter_precision.h; an H200: AO 5.8e-3, indirect
        // 0.39% of the image RMS) gets the product's bound, RMSE 0.01.
        EXPECT_LT(a.aoRmse, vcttest::filterTolerance(2e-3, 0.01)) << bounces;
        EXPECT_LT(a.giRmse, 0.01 * a.giRms) << bounces;
        EXPECT_NEAR(a.giMeanRatio, 1.0, 0.005) << bounces;
    }
}

}  // namespace
}  // namespace vct
