// The project scenes: they load (from the builder and from written files), and the off-screen study
// scenes do what their names claim, checked by brute-force ray casting through the camera.
#include "core/errors.h"
#include "scene/gltf_loader.h"
#include "scene/scene_library.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// Möller-Trumbore; returns the hit distance or +inf. Both faces count.
float intersect(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b,
                const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::numeric_limits<float>::infinity();
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) / det;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) / det;
    const float t = glm::dot(e2, q) / det;
    if (u < 0.f || v < 0.f || u + v > 1.f || t <= 1e-6f) return std::numeric_limits<float>::infinity();
    return t;
}

struct Hit {
    float t = std::numeric_limits<float>::infinity();
    size_t triangle = 0;
};

Hit closestHit(const vct::Scene& s, const glm::vec3& o, const glm::vec3& d) {
    Hit h;
    for (size_t i = 0; i < s.triangleCount(); ++i) {
        const glm::uvec3 t = s.triangles[i];
        const float ti = intersect(o, d, s.positions[t.x], s.positions[t.y], s.positions[t.z]);
        if (ti < h.t) h = Hit{ti, i};
    }
    return h;
}

// Distance from p to the axis-aligned box [lo, hi].
float distanceToBox(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::vec3(0.f)));
}

struct PrimaryStats {
    int pixels = 0;
    int offscreenHits = 0;
    float nearestVisibleToOccluder = std::numeric_limits<float>::infinity();
};

// Casts one ray through each pixel centre of an n x n/aspect image of the scene's first camera.
PrimaryStats castPrimaryRays(const vct::Scene& s, float aspect, int width) {
    const vct::Camera& c = s.cameras.at(0);
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanY = std::tan(0.5f * c.yfov), tanX = tanY * aspect;
    const int height = std::max(1, int(float(width) / aspect));
    vct::Bounds3 occluder;
    for (size_t i = 0; i < s.triangleCount(); ++i)
        if (s.triangleOffscreen[i])
            for (int k = 0; k < 3; ++k) occluder.expand(s.positions[s.triangles[i][k]]);
    PrimaryStats stats;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float sx = (2.f * (float(x) + 0.5f) / float(width) - 1.f) * tanX;
            const float sy = (1.f - 2.f * (float(y) + 0.5f) / float(height)) * tanY;
            const glm::vec3 d = glm::normalize(forward + sx * right + sy * up);
            const Hit h = closestHit(s, c.eye, d);
            ++stats.pixels;
            if (!std::isfinite(h.t)) continue;
            if (s.triangleOffscreen[h.triangle]) {
                ++stats.offscreenHits;
                continue;
            }
            stats.nearestVisibleToOccluder = std::min(
                stats.nearestVisibleToOccluder, distanceToBox(c.eye + h.t * d, occluder.min, occluder.max));
        }
    return stats;
}

}  // namespace

TEST(SceneLibrary, EveryProjectSceneLoadsFromBuilderAndFiles) {
    const fs::path dir = fs::temp_directory_path() / ("vct_scene_library_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::vector<std::string> names = vct::projectSceneNames();
    ASSERT_GE(names.size(), 9u);
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const vct::SceneBuilder builder = vct::makeProjectScene(name);
        const vct::Scene direct = builder.toScene();
        EXPECT_GT(direct.triangleCount(), 0u);
        EXPECT_TRUE(direct.warnings.empty()) << direct.warnings.front();
        EXPECT_FALSE(direct.cameras.empty());
        EXPECT_FALSE(direct.bounds.empty());
        for (const char* ext : {".gltf", ".glb"}) {
            const std::string path = (dir / (name + ext)).string();
            builder.write(path);
            const vct::Scene loaded = vct::loadScene(path);
            EXPECT_EQ(loaded.triangleCount(), direct.triangleCount());
            EXPECT_EQ(loaded.positions, direct.positions);
            EXPECT_EQ(loaded.lights.size(), direct.lights.size());
            EXPECT_EQ(loaded.triangleOffscreen, direct.triangleOffscreen);
        }
        // Every triangle faces where its shading normals say (no inverted winding from the builder).
        for (size_t i = 0; i < direct.triangleCount(); ++i)
            ASSERT_GT(glm::dot(direct.geometricNormal(i), direct.normals[direct.triangles[i].x]), 0.99f) << i;
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    EXPECT_THROW(vct::makeProjectScene("no_such_scene"), vct::UsageError);
}

TEST(SceneLibrary, CornellBoxHasEmitterPointLightAndCamera) {
    const vct::Scene s = vct::makeProjectScene("cornell_box").toScene();
    EXPECT_NEAR(s.bounds.min.x, -1.f, 1e-5f);
    EXPECT_NEAR(s.bounds.max.x, 1.f, 1e-5f);
    EXPECT_NEAR(s.bounds.min.y, 0.f, 1e-5f);
    EXPECT_NEAR(s.bounds.max.y, 2.f, 1e-5f);
    int emissiveTriangles = 0;
    for (size_t i = 0; i < s.triangleCount(); ++i) {
        const vct::Material& m = s.materials[s.triangleMaterial[i]];
        if (!m.isEmissive()) continue;
        ++emissiveTriangles;
        EXPECT_GT(m.emissiveFactor.r, 1.f);  // carried through KHR_materials_emissive_strength
        EXPECT_LT(s.geometricNormal(i).y, -0.99f) << "the emitter faces down";
    }
    EXPECT_EQ(emissiveTriangles, 2);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, vct::LightType::Point);
    EXPECT_GT(s.lights[0].position.y, 1.5f);
    EXPECT_LT(s.lights[0].position.y, 2.f);
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(s.cameras[0].name, "front");
    EXPECT_GT(s.cameras[0].eye.z, 1.f);  // outside, looking in through the open front
    // Red left wall, green right wall: the materials of the triangles at x = -1 and x = +1.
    for (size_t i = 0; i < s.triangleCount(); ++i) {
        const glm::vec3 p = s.positions[s.triangles[i].x];
        const glm::vec3 n = s.geometricNormal(i);
        const glm::vec4 albedo = s.materials[s.triangleMaterial[i]].baseColorFactor;
        if (p.x == -1.f && n.x > 0.99f) { EXPECT_GT(albedo.r, 3.f * albedo.g); }
        if (p.x == 1.f && n.x < -0.99f) { EXPECT_GT(albedo.g, 2.f * albedo.r); }
    }
}

TEST(SceneLibrary, OffscreenOccludersAreOutOfViewButNearVisibleSurfaces) {
    for (const char* name : {"offscreen_overhang", "offscreen_wall_behind", "offscreen_side",
                             "offscreen_hidden", "offscreen_thin", "offscreen_gi_wall", "offscreen_gi_emitter",
                             "offscreen_gi_floor"}) {
        const vct::Scene s = vct::makeProjectScene(name).toScene();
        const size_t marked = size_t(std::count(s.triangleOffscreen.begin(), s.triangleOffscreen.end(), 1));
        EXPECT_GT(marked, 0u) << name;
        EXPECT_LT(marked, s.triangleCount()) << name;
        for (float aspect : {1.f, 16.f / 9.f}) {
            const PrimaryStats st = castPrimaryRays(s, aspect, 48);
            if (std::string(name) == "offscreen_thin") {
                // Edge-on: at most a sliver of pixels sees the 1 cm shelf and fin.
                EXPECT_LE(st.offscreenHits, st.pixels / 50) << name << " aspect " << aspect;
            } else {
                EXPECT_EQ(st.offscreenHits, 0) << name << " aspect " << aspect;
            }
            EXPECT_LT(st.nearestVisibleToOccluder, 0.6f) << name << " aspect " << aspect;
        }
    }
}

TEST(SceneLibrary, ClosedFormScenes) {
    const vct::Scene plane = vct::makeProjectScene("open_plane").toScene();
    EXPECT_EQ(plane.triangleCount(), 2u);
    EXPECT_NEAR(plane.bounds.extent().x, 100.f, 1e-4f);
    EXPECT_EQ(plane.bounds.extent().y, 0.f);
    for (const glm::vec3& n : plane.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
    ASSERT_EQ(plane.lights.size(), 1u);
    EXPECT_NEAR(glm::length(plane.lights[0].direction - glm::vec3(0, -1, 0)), 0.f, 1e-6f);

    const vct::Scene wall = vct::makeProjectScene("wall_base").toScene();
    EXPECT_EQ(wall.bounds.min.y, 0.f);
    EXPECT_EQ(wall.bounds.min.z, 0.f);
    EXPECT_GE(wall.bounds.max.y, 20.f);
    int facingUp = 0, facingFront = 0;
    for (size_t i = 0; i < wall.triangleCount(); ++i) {
        facingUp += wall.geometricNormal(i).y > 0.999f;
        facingFront += wall.geometricNormal(i).z > 0.999f;
    }
    EXPECT_EQ(facingUp, 2);
    EXPECT_EQ(facingFront, 2);
}
