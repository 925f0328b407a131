// Voxelization, injection and mips (src/voxelize) against closed forms and an independent
// CPU triangle/box overlap test.
#include "cone/cone_bounce.h"
#include "gl/context.h"
#include "core/gpu_scene.h"
#include "voxelize/voxelize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <set>

using namespace vct;

namespace {

constexpr double PI = 3.14159265358979323846;

// ---- scene building --------------------------------------------------------------------

struct TestScene {
    Scene scene;
    int addMaterial(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.f)) {
        Material m;
        m.baseColorFactor = glm::vec4(albedo, 1.f);
        m.emissiveFactor = emission;
        scene.materials.push_back(m);
        return int(scene.materials.size()) - 1;
    }
    void addTriangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, int material = 0) {
        glm::vec3 n = glm::cross(b - a, c - a);
        n = glm::length(n) > 0.f ? glm::normalize(n) : glm::vec3(0, 1, 0);
        uint32_t base = uint32_t(scene.positions.size());
        for (glm::vec3 p : {a, b, c}) {
            scene.positions.push_back(p);
            scene.normals.push_back(n);
            scene.uvs.push_back(glm::vec2(0.f));
            scene.bounds.expand(p);
        }
        scene.triangles.push_back(glm::uvec3(base, base + 1, base + 2));
        scene.triangleMaterial.push_back(uint32_t(material));
        scene.triangleOffscreen.push_back(0);
    }
    // Quad a, b, c, d in order (normal = (b - a) x (c - a)).
    void addQuad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int material = 0) {
        addTriangle(a, b, c, material);
        addTriangle(a, c, d, material);
    }
    // Closed axis-aligned box, outward normals (inward: seen from inside).
    void addBox(glm::vec3 lo, glm::vec3 hi, int material = 0, bool inward = false) {
        auto addQuad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int m) {
            if (inward) this->addQuad(a, d, c, b, m);
            else this->addQuad(a, b, c, d, m);
        };
        glm::vec3 p[8];
        for (int i = 0; i < 8; ++i) p[i] = glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        addQuad(p[0], p[2], p[3], p[1], material);  // -z
        addQuad(p[4], p[5], p[7], p[6], material);  // +z
        addQuad(p[0], p[1], p[5], p[4], material);  // -y
        addQuad(p[2], p[6], p[7], p[3], material);  // +y
        addQuad(p[0], p[4], p[6], p[2], material);  // -x
        addQuad(p[1], p[3], p[7], p[5], material);  // +x
    }
};

GpuScene upload(const Scene& scene) {
    GlContext::shared();  // creates and makes current the context on first use
    return uploadScene(scene);
}

// ---- GPU readback ----------------------------------------------------------------------

glm::ivec3 levelSize(GLuint tex, int level) {
    glm::ivec3 s;
    glGetTextureLevelParameteriv(tex, level, GL_TEXTURE_WIDTH, &s.x);
    glGetTextureLevelParameteriv(tex, level, GL_TEXTURE_HEIGHT, &s.y);
    glGetTextureLevelParameteriv(tex, level, GL_TEXTURE_DEPTH, &s.z);
    return s;
}

struct Volume {
    glm::ivec3 size{0};
    int channels = 1;
    std::vector<float> data;
    float at(int x, int y, int z, int c = 0) const {
        return data[((size_t(z) * size.y + y) * size.x + x) * channels + c];
    }
    double mean(int c = 0) const {
        double s = 0;
        for (size_t i = c; i < data.size(); i += channels) s += data[i];
        return s / double(data.size() / channels);
    }
};

Volume readVolume(const GlTexture& tex, int level, int channels) {
    Volume v;
    v.size = levelSize(tex.id(), level);
    v.channels = channels;
    v.data.resize(size_t(v.size.x) * v.size.y * v.size.z * channels);
    glGetTextureImage(tex.id(), level, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT,
                      GLsizei(v.data.size() * sizeof(float)), v.data.data());
    return v;
}

std::vector<uint8_t> readRawBytes(const GlTexture& tex, GLenum format, GLenum type, size_t texelBytes) {
    glm::ivec3 s = levelSize(tex.id(), 0);
    std::vector<uint8_t> bytes(size_t(s.x) * s.y * s.z * texelBytes);
    glGetTextureImage(tex.id(), 0, format, type, GLsizei(bytes.size()), bytes.data());
    return bytes;
}

// ---- independent CPU overlap test (separating axes, double precision) --------------------

// True when no axis among the 3 box normals, the triangle normal and the 9 edge x axis
// cross products separates the triangle from the cube of half-size h centred at c.
bool cpuTriangleBoxOverlap(const std::array<glm::dvec3, 3>& tri, glm::dvec3 c, double h) {
    std::array<glm::dvec3, 3> v = {tri[0] - c, tri[1] - c, tri[2] - c};
    std::vector<glm::dvec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, glm::cross(v[1] - v[0], v[2] - v[0])};
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 e = v[(i + 1) % 3] - v[i];
        for (int k = 0; k < 3; ++k) {
            glm::dvec3 unit(0.0);
            unit[k] = 1.0;
            axes.push_back(glm::cross(e, unit));
        }
    }
    for (const glm::dvec3& a : axes) {
        double lo = 1e300, hi = -1e300;
        for (const glm::dvec3& p : v) {
            lo = std::min(lo, glm::dot(a, p));
            hi = std::max(hi, glm::dot(a, p));
        }
        double r = h * (std::abs(a.x) + std::abs(a.y) + std::abs(a.z));
        if (lo > r || hi < -r) return false;
    }
    return true;
}

std::array<glm::dvec3, 3> voxelTriangle(const Scene& s, size_t t, const VoxelGrid& g) {
    std::array<glm::dvec3, 3> out;
    for (int k = 0; k < 3; ++k)
        out[size_t(k)] = (glm::dvec3(s.positions[s.triangles[t][k]]) - glm::dvec3(g.origin)) / double(g.voxelSize);
    return out;
}

// Voxels overlapped by any triangle of the scene with box half-size h.
std::set<std::array<int, 3>> cpuVoxelSet(const Scene& s, const VoxelGrid& g, double h) {
    std::set<std::array<int, 3>> set;
    for (size_t t = 0; t < s.triangles.size(); ++t) {
        auto tri = voxelTriangle(s, t, g);
        glm::dvec3 lo = glm::min(tri[0], glm::min(tri[1], tri[2])), hi = glm::max(tri[0], glm::max(tri[1], tri[2]));
        glm::ivec3 a = glm::max(glm::ivec3(glm::floor(lo)) - 1, glm::ivec3(0));
        glm::ivec3 b = glm::min(glm::ivec3(glm::floor(hi)) + 1, g.resolution - 1);
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x)
                    if (cpuTriangleBoxOverlap(tri, glm::dvec3(x, y, z) + 0.5, h)) set.insert({x, y, z});
    }
    return set;
}

struct HoleReport {
    size_t gpu = 0, cpuExact = 0, missing = 0, extra = 0;
};

// Every voxel the CPU test finds overlapped with a slightly shrunk box must be occupied
// (no holes), and every occupied voxel must overlap a slightly grown box (conservative,
// not bloated). The margins (1e-3 voxel) only absorb float rounding at exact contact.
HoleReport compareWithCpu(const Scene& s, const VoxelGrid& g) {
    Volume opacity = readVolume(g.opacity, 0, 1);
    auto must = cpuVoxelSet(s, g, 0.5 - 1e-3), may = cpuVoxelSet(s, g, 0.5 + 1e-3), exact = cpuVoxelSet(s, g, 0.5);
    HoleReport r;
    r.cpuExact = exact.size();
    for (int z = 0; z < g.resolution.z; ++z)
        for (int y = 0; y < g.resolution.y; ++y)
            for (int x = 0; x < g.resolution.x; ++x) {
                bool occupied = opacity.at(x, y, z) > 0.f;
                r.gpu += occupied;
                if (!occupied && must.count({x, y, z})) ++r.missing;
                if (occupied && !may.count({x, y, z})) ++r.extra;
            }
    return r;
}

VoxelGrid voxelize(const Scene& scene, const GpuScene& gpu, int res, const Bounds3* region = nullptr,
                   const ParamMap& params = ParamMap()) {
    PassTimer timer;
    VoxelGrid g = voxelizeScene(gpu, region ? *region : scene.bounds, res, params, timer);
    GlContext::shared().checkErrors("voxelize");
    return g;
}

void expectNoHoles(const Scene& scene, int res, const Bounds3* region = nullptr) {
    GpuScene gpu = upload(scene);
    VoxelGrid g = voxelize(scene, gpu, res, region);
    HoleReport r = compareWithCpu(scene, g);
    EXPECT_EQ(r.missing, 0u) << "holes";
    EXPECT_EQ(r.extra, 0u) << "voxels no triangle touches";
    EXPECT_GT(r.gpu, 0u);
    EXPECT_EQ(size_t(g.occupiedVoxels), r.gpu);
    EXPECT_GT(g.memoryBytes, 0u);
    std::printf("  occupied %zu (CPU exact-box count %zu)\n", r.gpu, r.cpuExact);
}

glm::vec3 randomPoint(std::mt19937& rng, float lo, float hi) {
    std::uniform_real_distribution<float> u(lo, hi);
    return glm::vec3(u(rng), u(rng), u(rng));
}

}  // namespace

// ---- voxelization: no holes -------------------------------------------------------------

TEST(Voxelize, ThinTriangleHasNoHoles) {
    TestScene t;
    t.addMaterial(glm::vec3(0.5f));
    // A long sliver crossing the grid diagonally, far thinner than a voxel.
    t.addTriangle({0.f, 0.f, 0.f}, {1.f, 0.9f, 0.7f}, {1.f, 0.9003f, 0.7002f});
    expectNoHoles(t.scene, 32);
}

TEST(Voxelize, AxisAlignedWallOneVoxelThickHasNoHoles) {
    TestScene t;
    t.addMaterial(glm::vec3(0.5f));
    // 32^3 over a 3-unit cube: voxels of 0.1; the wall is 0.1 thick, with faces on voxel
    // boundaries and mid-voxel.
    t.addBox({0.f, 0.f, 1.5f}, {3.f, 3.f, 1.6f});
    t.addBox({0.f, 0.f, 0.f}, {0.1f, 3.f, 3.f});
    t.addBox({1.05f, 0.f, 0.f}, {1.15f, 3.f, 1.f});
    expectNoHoles(t.scene, 32);
}

TEST(Voxelize, SubVoxelTriangleIsFound) {
    TestScene t;
    t.addMaterial(glm::vec3(0.5f));
    t.addTriangle({0.301f, 0.302f, 0.303f}, {0.3012f, 0.302f, 0.3031f}, {0.3011f, 0.3023f, 0.303f});
    // A tiny triangle straddling a voxel corner as well.
    Bounds3 region;
    region.expand(glm::vec3(-1.f));
    region.expand(glm::vec3(1.f));
    VoxelGrid layout = makeGridLayout(region, 32);
    glm::vec3 corner = layout.origin + glm::vec3(10.f) * layout.voxelSize;
    float e = 0.01f * layout.voxelSize;
    t.addTriangle(corner - glm::vec3(e, e, e), corner + glm::vec3(e, -e, e), corner + glm::vec3(0.f, e, -e));
    expectNoHoles(t.scene, 32, &region);
}

TEST(Voxelize, RandomTiltedTrianglesHaveNoHoles) {
    TestScene t;
    t.addMaterial(glm::vec3(0.5f));
    std::mt19937 rng(7);
    for (int i = 0; i < 40; ++i) {  // big ones (deferred to the big-triangle pass) ...
        glm::vec3 c = randomPoint(rng, -1.f, 1.f);
        t.addTriangle(c, c + randomPoint(rng, -1.f, 1.f), c + randomPoint(rng, -1.f, 1.f));
    }
    for (int i = 0; i < 200; ++i) {  // ... and small ones
        glm::vec3 c = randomPoint(rng, -1.f, 1.f);
        t.addTriangle(c, c + randomPoint(rng, -0.1f, 0.1f), c + randomPoint(rng, -0.1f, 0.1f));
    }
    expectNoHoles(t.scene, 48);
}

// ---- determinism and averages ------------------------------------------------------------

// `count` random triangles in [-1, 1]^3 over `materials` random albedos, every tenth big (the
// big-triangle pass) and the others of size `small`; material `emissive` emits `emission`.
TestScene randomSoup(uint32_t seed, int materials, int count, float small, int emissive, glm::vec3 emission) {
    TestScene t;
    std::mt19937 rng(seed);
    for (int m = 0; m < materials; ++m) t.addMaterial(randomPoint(rng, 0.f, 1.f), m == emissive ? emission : glm::vec3(0.f));
    std::uniform_int_distribution<int> mat(0, materials - 1);
    for (int i = 0; i < count; ++i) {
        glm::vec3 c = randomPoint(rng, -1.f, 1.f);
        float s = i % 10 == 0 ? 1.f : small;
        t.addTriangle(c, c + randomPoint(rng, -s, s), c + randomPoint(rng, -s, s), mat(rng));
    }
    return t;
}

TEST(Voxelize, TwoRunsGiveIdenticalBytes) {
    TestScene t = randomSoup(11, 8, 3000, 0.08f, 3, glm::vec3(5.f, 2.f, 0.5f));
    GpuScene gpu = upload(t.scene);
    std::array<std::vector<uint8_t>, 4> first;
    for (int run = 0; run < 2; ++run) {
        VoxelGrid g = voxelize(t.scene, gpu, 48);
        std::array<std::vector<uint8_t>, 4> bytes = {
            readRawBytes(g.opacity, GL_RED, GL_HALF_FLOAT, 2), readRawBytes(g.albedo, GL_RGBA, GL_HALF_FLOAT, 8),
            readRawBytes(g.normal, GL_RGBA, GL_HALF_FLOAT, 8), readRawBytes(g.emission, GL_RGBA, GL_FLOAT, 16)};
        if (run == 0) {
            first = bytes;
            continue;
        }
        for (size_t k = 0; k < 4; ++k) {
            ASSERT_EQ(first[k].size(), bytes[k].size());
            EXPECT_EQ(std::memcmp(first[k].data(), bytes[k].data(), bytes[k].size()), 0) << "texture " << k;
        }
    }
}

// A grid for AO (no attributes) keeps opacity alone: the same opacity and directional levels
// bit for bit as the full grid of the same scene (emissive and doubleSided materials
// included, whose passes it skips), no albedo, normal or emission, and a fraction of the
// memory.
TEST(Voxelize, AGridForAoHoldsTheSameOpacityAndNothingElse) {
    TestScene t = randomSoup(5, 4, 600, 0.1f, 1, glm::vec3(3.f));
    t.scene.materials[2].doubleSided = true;
    GpuScene gpu = upload(t.scene);
    PassTimer timer;
    VoxelGrid full = voxelizeScene(gpu, t.scene.bounds, 48, ParamMap(), timer, false, true);
    VoxelGrid ao = voxelizeScene(gpu, t.scene.bounds, 48, ParamMap(), timer, false, false);
    for (VoxelGrid* g : {&full, &ao}) buildMips(*g, true, timer);
    GlContext::shared().checkErrors("voxelize for AO");
    EXPECT_FALSE(ao.albedo);
    EXPECT_FALSE(ao.normal);
    EXPECT_FALSE(ao.emission);
    EXPECT_TRUE(full.albedo && full.normal && full.emission);
    EXPECT_EQ(ao.occupiedVoxels, full.occupiedVoxels);
    EXPECT_GT(ao.occupiedVoxels, 1000u);
    for (int level = 0; level < full.levels; ++level) {
        const Volume a = readVolume(full.opacity, level, 1), b = readVolume(ao.opacity, level, 1);
        ASSERT_EQ(a.data.size(), b.data.size());
        EXPECT_EQ(a.data, b.data) << "opacity level " << level;
    }
    ASSERT_TRUE(full.anisoOpacity && ao.anisoOpacity);
    const std::vector<uint8_t> da = readRawBytes(full.anisoOpacity, GL_RGBA, GL_HALF_FLOAT, 8),
                               db = readRawBytes(ao.anisoOpacity, GL_RGBA, GL_HALF_FLOAT, 8);
    ASSERT_EQ(da.size(), db.size());
    EXPECT_EQ(std::memcmp(da.data(), db.data(), da.size()), 0);
    std::printf("[ AO grid ] %zu bytes against %zu with attributes\n", ao.memoryBytes, full.memoryBytes);
    EXPECT_LT(ao.memoryBytes * 4, full.memoryBytes);
}

TEST(Voxelize, AlbedoOfTwoTrianglesSharingVoxelsIsTheirMean) {
    TestScene t;
    glm::vec3 a(0.8f, 0.2f, 0.1f), b(0.2f, 0.6f, 0.9f);
    int ma = t.addMaterial(a), mb = t.addMaterial(b);
    // Region: a 3-unit cube at 32^3 -> 0.1 voxels; both triangles lie inside one voxel layer.
    Bounds3 region;
    region.expand(glm::vec3(0.f));
    region.expand(glm::vec3(3.f));
    VoxelGrid layout = makeGridLayout(region, 32);
    float z0 = layout.origin.z + 15.2f * layout.voxelSize, z1 = layout.origin.z + 15.7f * layout.voxelSize;
    t.addTriangle({0.2f, 0.2f, z0}, {2.8f, 0.2f, z0}, {0.2f, 2.8f, z0}, ma);
    t.addTriangle({0.2f, 0.2f, z1}, {2.8f, 0.2f, z1}, {0.2f, 2.8f, z1}, mb);
    GpuScene gpu = upload(t.scene);
    VoxelGrid g = voxelize(t.scene, gpu, 32, &region);
    Volume albedo = readVolume(g.albedo, 0, 4);
    Volume opacity = readVolume(g.opacity, 0, 1);
    glm::vec3 mean = 0.5f * (a + b);
    int shared = 0;
    double maxErr = 0.0;
    for (int y = 0; y < g.resolution.y; ++y)
        for (int x = 0; x < g.resolution.x; ++x) {
            // Both triangles overlap voxel (x, y, 15) when the CPU test says so for each.
            auto ta = voxelTriangle(t.scene, 0, g), tb = voxelTriangle(t.scene, 1, g);
            glm::dvec3 c(x + 0.5, y + 0.5, 15.5);
            bool inA = cpuTriangleBoxOverlap(ta, c, 0.5), inB = cpuTriangleBoxOverlap(tb, c, 0.5);
            if (!inA && !inB) continue;
            ASSERT_GT(opacity.at(x, y, 15), 0.f);
            glm::vec3 expected = inA && inB ? mean : (inA ? a : b);
            shared += inA && inB;
            for (int k = 0; k < 3; ++k) maxErr = std::max(maxErr, double(std::abs(albedo.at(x, y, 15, k) - expected[k])));
        }
    EXPECT_GT(shared, 100);
    EXPECT_LT(maxErr, 2e-3);
    std::printf("  %d shared voxels, max |albedo - expected| %.2e\n", shared, maxErr);
}

TEST(Voxelize, EmissionUpToMillionStaysFinite) {
    TestScene t;
    t.addMaterial(glm::vec3(0.5f), glm::vec3(1e6f, 2.5f, 0.f));
    t.addQuad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
    GpuScene gpu = upload(t.scene);
    VoxelGrid g = voxelize(t.scene, gpu, 16);
    PassTimer timer;
    injectRadiance(g, gpu, t.scene, ParamMap(), timer);
    GlContext::shared().checkErrors("inject");
    Volume e = readVolume(g.emission, 0, 4), r = readVolume(g.radiance, 0, 4);
    int n = 0;
    for (size_t i = 0; i < e.data.size(); i += 4) {
        if (r.data[i + 3] <= 0.f) continue;
        ++n;
        EXPECT_NEAR(e.data[i], 1e6f, 1.f);
        EXPECT_NEAR(e.data[i + 1], 2.5f, 1e-3f);
        EXPECT_NEAR(r.data[i], 1e6f * r.data[i + 3], 1.f);
    }
    EXPECT_GT(n, 0);
}

// ---- injection ---------------------------------------------------------------------------

namespace {

// A 2 x 2 floor (albedo rho) at y = 0 under a directional light, a blocker quad above it.
struct FloorScene {
    TestScene t;
    float rho = 0.5f;
    glm::vec3 lightDir = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));  // direction of travel
    float lux = 3.f;
    glm::vec2 blockerLo{-0.7f, -0.7f}, blockerHi{0.3f, 0.3f};
    float blockerY = 0.8f;
    explicit FloorScene(bool blocker) {
        t.addMaterial(glm::vec3(rho));
        t.addQuad({-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
        if (blocker)
            t.addQuad({blockerLo.x, blockerY, blockerLo.y}, {blockerLo.x, blockerY, blockerHi.y},
                      {blockerHi.x, blockerY, blockerHi.y}, {blockerHi.x, blockerY, blockerLo.y});
        else
            t.scene.bounds.expand(glm::vec3(0.f, blockerY, 0.f));  // same grid either way
        Light l;
        l.type = LightType::Directional;
        l.color = glm::vec3(lux);
        l.direction = lightDir;
        t.scene.lights.push_back(l);
    }
    // Distance in floor xz from the blocker's shadow rectangle (negative inside).
    float shadowDistance(glm::vec2 p) const {
        glm::vec3 toLight = -lightDir;
        glm::vec2 shift = glm::vec2(toLight.x, toLight.z) * (blockerY / toLight.y);
        glm::vec2 q = p + shift;  // where the ray to the light crosses the blocker plane
        glm::vec2 d = glm::max(blockerLo - q, q - blockerHi);
        return std::max(d.x, d.y);
    }
};

struct FloorResult {
    double meanFloor = 0.0;
    int lit = 0, shadowed = 0;
    double maxLitErr = 0.0, maxShadow = 0.0;
};

FloorResult injectFloor(const FloorScene& f, int res) {
    GpuScene gpu = upload(f.t.scene);
    VoxelGrid g = voxelize(f.t.scene, gpu, res);
    PassTimer timer;
    injectRadiance(g, gpu, f.t.scene, ParamMap(), timer);
    GlContext::shared().checkErrors("inject");
    Volume r = readVolume(g.radiance, 0, 4);
    const double expected = f.rho / PI * f.lux * double(-f.lightDir.y);
    FloorResult out;
    double sum = 0.0;
    int count = 0;
    for (int z = 0; z < g.resolution.z; ++z)
        for (int y = 0; y < g.resolution.y; ++y)
            for (int x = 0; x < g.resolution.x; ++x) {
                float alpha = r.at(x, y, z, 3);
                if (alpha <= 0.f) continue;
                glm::vec3 c = g.origin + (glm::vec3(x, y, z) + 0.5f) * g.voxelSize;
                if (std::abs(c.y) > g.voxelSize) continue;  // floor voxels only
                double L = r.at(x, y, z, 0) / alpha;
                sum += L;
                ++count;
                float d = f.shadowDistance(glm::vec2(c.x, c.z));
                if (d > 3.f * g.voxelSize) {
                    ++out.lit;
                    out.maxLitErr = std::max(out.maxLitErr, std::abs(L - expected) / expected);
                } else if (d < -3.f * g.voxelSize) {
                    ++out.shadowed;
                    out.maxShadow = std::max(out.maxShadow, L / expected);
                }
            }
    out.meanFloor = sum / std::max(1, count);
    return out;
}

}  // namespace

TEST(Inject, DirectionalLightOnFloorMatchesClosedFormAndShadows) {
    FloorScene f(true);
    FloorResult r = injectFloor(f, 32);
    EXPECT_GT(r.lit, 200);
    EXPECT_GT(r.shadowed, 10);
    EXPECT_LT(r.maxLitErr, 0.01);   // half-float storage
    EXPECT_LT(r.maxShadow, 1e-3);
    std::printf("  lit %d (max rel err %.2e), shadowed %d (max L/expected %.2e)\n", r.lit, r.maxLitErr, r.shadowed,
                r.maxShadow);
}

TEST(Inject, FloorRadianceDoesNotDependOnResolution) {
    FloorScene f(true);
    FloorResult a = injectFloor(f, 32), b = injectFloor(f, 64);
    double rel = std::abs(a.meanFloor - b.meanFloor) / b.meanFloor;
    EXPECT_LT(rel, 0.05);
    std::printf("  floor mean radiance %.5f at 32^3, %.5f at 64^3 (rel diff %.3f)\n", a.meanFloor, b.meanFloor, rel);
}

TEST(Inject, SpotLightFollowsInverseSquareAndGltfFalloff) {
    TestScene t;
    const float rho = 0.6f;
    t.addMaterial(glm::vec3(rho));
    t.addQuad({-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
    t.scene.bounds.expand(glm::vec3(0.f, 1.f, 0.f));
    Light l;
    l.type = LightType::Spot;
    l.position = {0.1f, 0.9f, -0.05f};
    l.direction = {0.f, -1.f, 0.f};
    l.color = glm::vec3(2.f);  // candela
    l.innerConeAngle = 0.3f;
    l.outerConeAngle = 0.6f;
    t.scene.lights.push_back(l);
    GpuScene gpu = upload(t.scene);
    VoxelGrid g = voxelize(t.scene, gpu, 32);
    PassTimer timer;
    injectRadiance(g, gpu, t.scene, ParamMap(), timer);
    GlContext::shared().checkErrors("inject spot");
    Volume r = readVolume(g.radiance, 0, 4);
    int inner = 0, falloff = 0, outside = 0;
    double maxErr = 0.0;
    for (int z = 0; z < g.resolution.z; ++z)
        for (int y = 0; y < g.resolution.y; ++y)
            for (int x = 0; x < g.resolution.x; ++x) {
                float alpha = r.at(x, y, z, 3);
                glm::dvec3 c = glm::dvec3(g.origin) + (glm::dvec3(x, y, z) + 0.5) * double(g.voxelSize);
                if (alpha <= 0.f || std::abs(c.y) > g.voxelSize) continue;
                // Closed form at the voxel centre (normal +y): E = I cos / d^2 * att^2.
                glm::dvec3 toLight = glm::dvec3(l.position) - c;
                double d = glm::length(toLight);
                double cosTheta = toLight.y / d, cd = cosTheta;  // spot axis is -y
                double att = std::clamp((cd - std::cos(0.6)) / (std::cos(0.3) - std::cos(0.6)), 0.0, 1.0);
                double expected = rho / PI * 2.0 * cosTheta / (d * d) * att * att;
                double L = r.at(x, y, z, 0) / alpha;
                if (att >= 1.0) ++inner;
                else if (att > 0.0) ++falloff;
                else ++outside;
                maxErr = std::max(maxErr, std::abs(L - expected) / (rho / PI * 2.0));
            }
    EXPECT_GT(inner, 20);
    EXPECT_GT(falloff, 20);
    EXPECT_GT(outside, 20);
    // Relative to the radiance scale rho/pi * I / (1 m)^2; observed 1.7e-3, about one
    // half-float step at the peak (0.5) where radiance is stored in RGBA16F.
    EXPECT_LT(maxErr, 3e-3);
    std::printf("  inner %d, falloff %d, outside %d voxels; max err %.2e\n", inner, falloff, outside, maxErr);
}

TEST(Inject, BouncesAddBoundedEnergy) {
    // A closed white box lit through nothing but its emissive ceiling: each bounce adds
    // light, but with albedo 0.9 the increments shrink.
    TestScene t;
    int white = t.addMaterial(glm::vec3(0.9f));
    int lamp = t.addMaterial(glm::vec3(0.f), glm::vec3(1.f));
    t.addBox({-1, -1, -1}, {1, 1, 1}, white, true);
    t.addQuad({-0.3f, 0.95f, -0.3f}, {0.3f, 0.95f, -0.3f}, {0.3f, 0.95f, 0.3f}, {-0.3f, 0.95f, 0.3f}, lamp);
    GpuScene gpu = upload(t.scene);
    std::vector<double> means;
    for (int bounces : {0, 1, 2, 3}) {
        VoxelGrid g = voxelize(t.scene, gpu, 24);
        ParamMap params;
        params.set("vct.bounces", std::to_string(bounces));
        PassTimer timer;
        injectRadiance(g, gpu, t.scene, params, timer);
        traceVoxelBounces(g, 0.f, readConeSettings(params), params, timer);
        GlContext::shared().checkErrors("inject bounces");
        means.push_back(readVolume(g.radiance, 0, 4).mean(0));
    }
    for (size_t i = 1; i < means.size(); ++i) {
        EXPECT_GT(means[i], means[i - 1]);
        EXPECT_TRUE(std::isfinite(means[i]));
    }
    EXPECT_LT(means[3] - means[2], means[2] - means[1]);
    EXPECT_LT(means[2] - means[1], means[1] - means[0]);
    std::printf("  mean radiance by bounces: %.5f %.5f %.5f %.5f\n", means[0], means[1], means[2], means[3]);
}

// Lights split over dispatches (injectLightsPerDispatch) sum to what one dispatch gives, bit
// for bit: radiance and the two-sided voxels' facing normals, one light per dispatch or two.
TEST(Inject, LightsSplitOverDispatchesGiveTheSameBytes) {
    TestScene t = randomSoup(7, 4, 800, 0.08f, 1, glm::vec3(0.5f));
    t.scene.materials[2].doubleSided = true;
    std::mt19937 rng(5);
    for (int i = 0; i < 7; ++i) {
        Light l;
        l.type = i == 0 ? LightType::Directional : LightType::Point;
        l.position = randomPoint(rng, -1.5f, 1.5f);
        l.direction = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
        l.color = randomPoint(rng, 0.2f, 2.f);
        t.scene.lights.push_back(l);
    }
    GpuScene gpu = upload(t.scene);
    std::array<std::vector<uint8_t>, 2> whole;
    for (int perDispatch : {0, 1, 2}) {
        VoxelGrid g = voxelize(t.scene, gpu, 32);
        ASSERT_TRUE(g.twoSided);
        ParamMap params;
        params.set("vct.inject.dispatch-lights", std::to_string(perDispatch));
        PassTimer timer;
        injectRadiance(g, gpu, t.scene, params, timer);
        GlContext::shared().checkErrors("inject in slices");
        // 7 lights: one dispatch, 7 of one light, 4 of two (the last holds one).
        EXPECT_EQ(g.injectDispatches, perDispatch == 0 ? 1 : perDispatch == 1 ? 7 : 4);
        const std::array<std::vector<uint8_t>, 2> bytes = {readRawBytes(g.radiance, GL_RGBA, GL_FLOAT, 16),
                                                           readRawBytes(g.normal, GL_RGBA, GL_FLOAT, 16)};
        if (perDispatch == 0) {
            whole = bytes;
            Volume r = readVolume(g.radiance, 0, 4);
            int lit = 0;
            for (size_t i = 0; i < r.data.size(); i += 4) lit += r.data[i + 3] > 0.f && r.data[i] > 0.f;
            EXPECT_GT(lit, 500);
            continue;
        }
        for (size_t k = 0; k < 2; ++k) {
            ASSERT_EQ(whole[k].size(), bytes[k].size());
            EXPECT_EQ(std::memcmp(whole[k].data(), bytes[k].data(), bytes[k].size()), 0)
                << (k == 0 ? "radiance" : "normal") << " with " << perDispatch << " light(s) per dispatch";
        }
    }
}

// Enough lights that one invocation's shadow walks run far past the 65535 loop iterations
// after which llvmpipe silently ends its loops: 3000 identical directional lights must light
// every voxel as one light of their summed colour does (within half-float storage). In one
// dispatch llvmpipe left voxels up to 77% darker than that.
TEST(Inject, ThousandsOfLightsSumAsTheirTotal) {
    TestScene t = randomSoup(3, 2, 120, 0.1f, -1, glm::vec3(0.f));
    const int count = 3000;
    const glm::vec3 colour(1.5f, 1.f, 0.5f);
    auto inject = [&](int lights) {
        Scene scene = t.scene;
        for (int i = 0; i < lights; ++i) {
            Light l;
            l.type = LightType::Directional;
            l.direction = glm::normalize(glm::vec3(-1.f, -0.35f, -0.6f));
            l.color = colour / float(lights);
            scene.lights.push_back(l);
        }
        GpuScene gpu = upload(scene);
        VoxelGrid g = voxelize(scene, gpu, 48);
        // Each light's walks can cross the grid, so the lights need several dispatches.
        if (lights == count) {
            EXPECT_GT(count, 2 * injectLightsPerDispatch(g.resolution, 0, 0, false, 0));
        }
        PassTimer timer;
        injectRadiance(g, gpu, scene, ParamMap(), timer);
        GlContext::shared().checkErrors("inject many lights");
        if (lights == count) {
            EXPECT_GT(g.injectDispatches, 2);
        }
        return readVolume(g.radiance, 0, 4);
    };
    const Volume one = inject(1), many = inject(count);
    ASSERT_EQ(one.data.size(), many.data.size());
    int lit = 0;
    double maxRel = 0.0;
    for (size_t i = 0; i < one.data.size(); i += 4) {
        if (one.data[i + 3] <= 0.f || one.data[i] <= 1e-3f) continue;
        ++lit;
        for (int c = 0; c < 3; ++c)
            maxRel = std::max(maxRel, double(std::abs(many.data[i + c] - one.data[i + c]) / one.data[i + c]));
    }
    EXPECT_GT(lit, 100);
    EXPECT_LT(maxRel, 2e-3);  // half-float radiance; a dropped share of the lights is tens of percent
    std::printf("  %d lit voxels, max relative difference %.2e\n", lit, maxRel);
}

// ---- mips --------------------------------------------------------------------------------

TEST(Mips, SolidBlockIsOpaqueEmptyIsZeroAndMeansArePreserved) {
    Bounds3 region;
    region.expand(glm::vec3(0.f));
    region.expand(glm::vec3(1.f));
    VoxelGrid layout = makeGridLayout(region, 32);
    ASSERT_EQ(layout.resolution, glm::ivec3(32));
    auto world = [&](glm::vec3 u) { return layout.origin + u * layout.voxelSize; };
    TestScene t;
    t.addMaterial(glm::vec3(0.7f));
    // Surface of a box spanning voxels 4..7 entirely (faces inside voxels 4 and 7 would leave
    // 5..6 hollow, so use a 2x2x2 block: faces at 4.25 and 5.75 touch only voxels 4 and 5).
    t.addBox(world(glm::vec3(4.25f)), world(glm::vec3(5.75f)));
    std::mt19937 rng(3);
    for (int i = 0; i < 300; ++i) {  // clutter in the upper half for the mean test
        glm::vec3 c = world(randomPoint(rng, 16.f, 31.f));
        t.addTriangle(c, c + randomPoint(rng, -0.1f, 0.1f), c + randomPoint(rng, -0.1f, 0.1f));
    }
    GpuScene gpu = upload(t.scene);
    VoxelGrid g = voxelize(t.scene, gpu, 32, &region);
    PassTimer timer;
    buildMips(g, false, timer);  // AO-only path: no radiance
    GlContext::shared().checkErrors("mips");
    EXPECT_FALSE(bool(g.radiance));
    Volume l1 = readVolume(g.opacity, 1, 1);
    EXPECT_EQ(l1.at(2, 2, 2), 1.f);  // children 4..5: the solid block
    EXPECT_EQ(l1.at(5, 2, 2), 0.f);  // empty region
    EXPECT_EQ(l1.at(1, 1, 1), 0.f);
    double mean0 = readVolume(g.opacity, 0, 1).mean();
    for (int k = 1; k < g.levels; ++k) {
        double mk = readVolume(g.opacity, k, 1).mean();
        EXPECT_NEAR(mk, mean0, 2e-3 * mean0) << "level " << k;
    }

    // With radiance: premultiplied means are preserved too.
    Light l;
    l.type = LightType::Point;
    l.position = world(glm::vec3(10.f, 20.f, 8.f));
    l.color = glm::vec3(2.f, 1.f, 0.5f);
    t.scene.lights.push_back(l);
    GpuScene lit = upload(t.scene);
    VoxelGrid g2 = voxelize(t.scene, lit, 32, &region);
    injectRadiance(g2, lit, t.scene, ParamMap(), timer);
    buildMips(g2, true, timer);
    GlContext::shared().checkErrors("mips with radiance");
    Volume r0 = readVolume(g2.radiance, 0, 4);
    EXPECT_GT(r0.mean(0), 0.0);
    for (int k = 1; k < g2.levels; ++k) {
        Volume rk = readVolume(g2.radiance, k, 4);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(rk.mean(c), r0.mean(c), 3e-3 * r0.mean(c)) << "level " << k;
    }
    EXPECT_GT(g2.memoryBytes, g.memoryBytes);
}

TEST(Mips, AnisotropicCompositesAlongTheAxisAndAveragesAcross) {
    Bounds3 region;
    region.expand(glm::vec3(0.f));
    region.expand(glm::vec3(1.f));
    VoxelGrid layout = makeGridLayout(region, 16);
    auto world = [&](glm::vec3 u) { return layout.origin + u * layout.voxelSize; };
    TestScene t;
    t.addMaterial(glm::vec3(0.7f));
    // A plane x = 4.5 (voxel units): one voxel layer (x = 4) across y, z in 2..14.
    t.addQuad(world({4.5f, 2.f, 2.f}), world({4.5f, 14.f, 2.f}), world({4.5f, 14.f, 14.f}), world({4.5f, 2.f, 14.f}));
    GpuScene gpu = upload(t.scene);
    VoxelGrid g = voxelize(t.scene, gpu, 16, &region);
    PassTimer timer;
    buildMips(g, true, timer);  // AO-only: aniso alpha from opacity
    GlContext::shared().checkErrors("aniso mips");
    ASSERT_TRUE(g.anisotropic);
    // An AO grid packs its directional opacity into one texture: rgb = along X, Y, Z (the same
    // both ways along an axis).
    for (const GlTexture& t : g.anisoRadiance) EXPECT_FALSE(t);
    ASSERT_TRUE(g.anisoOpacity);
    const Volume axes = readVolume(g.anisoOpacity, 0, 4);
    // Mip voxel (2, 4, 4) has children x = 4 (opaque) and 5 (empty), y/z all in the plane.
    std::array<float, 6> alpha;
    for (int d = 0; d < 6; ++d) alpha[size_t(d)] = axes.at(2, 4, 4, d / 2);
    EXPECT_NEAR(alpha[0], 1.f, 1e-3);  // +X: the opaque child is in front
    EXPECT_NEAR(alpha[1], 1.f, 1e-3);  // -X: behind an empty child, still fully blocked
    for (int d = 2; d < 6; ++d) EXPECT_NEAR(alpha[size_t(d)], 0.5f, 1e-3) << "direction " << d;
    EXPECT_NEAR(readVolume(g.opacity, 1, 1).at(2, 4, 4), 0.5f, 1e-3);
    // Next level: (1, 2, 2) covers x 2..3 of level 0 of aniso: (+X) composite of x=2 (alpha 1)
    // with x=3 (0) then averaged across: 1 along X.
    EXPECT_NEAR(readVolume(g.anisoOpacity, 1, 4).at(1, 2, 2, 0), 1.f, 1e-3);
}
