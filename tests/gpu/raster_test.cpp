// The raster path against closed forms: G-buffer positions and depths on a known plane,
// Lambertian direct light from directional and point lights, shadows, and AO applied to
// the ambient term only.
#include "core/gpu_scene.h"
#include "core/timing.h"
#include "core/view.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "raster/gbuffer_pass.h"
#include "render/renderer.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vct;
using namespace vcttest;

namespace {

constexpr float kPi = 3.14159265358979f;

// A 20 x 20 floor at y = 0 seen from straight above.
Scene floorScene(glm::vec3 albedo) {
    Scene s;
    uint32_t m = addMaterial(s, albedo);
    addQuad(s, {-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, m);
    finish(s);
    return s;
}

RenderRequest topDown(std::vector<std::string> aovs, int size = 32) {
    RenderRequest r;
    r.width = r.height = size;
    r.camera.eye = {0, 5, 0};
    r.camera.target = {0, 0, 0};
    r.camera.up = {0, 0, -1};
    r.camera.yfov = glm::radians(60.f);
    r.camera.znear = 0.01f;
    r.aovs = std::move(aovs);
    r.sky = 0.f;
    return r;
}

}  // namespace

TEST(Raster, GBufferPositionsAndDepthMatchRayPlaneIntersection) {
    Scene s = floorScene({0.5f, 0.5f, 0.5f});
    RenderSession session(s);
    RenderRequest r = topDown({"position", "depth", "normal"});
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("raster test");
    const Image& pos = res.aovs.at("position");
    const Image& depth = res.aovs.at("depth");
    const Image& normal = res.aovs.at("normal");
    const float t = std::tan(0.5f * r.camera.yfov);
    for (int y = 0; y < r.height; y += 5)
        for (int x = 0; x < r.width; x += 5) {
            // Pixel centre direction in view space; the camera looks down -y with up = -z.
            float ndcX = (x + 0.5f) / r.width * 2.f - 1.f;
            float ndcY = 1.f - (y + 0.5f) / r.height * 2.f;
            glm::vec3 expected(ndcX * t * 5.f, 0.f, -ndcY * t * 5.f);
            EXPECT_NEAR(pos.at(x, y, 0), expected.x, 1e-3f) << x << "," << y;
            EXPECT_NEAR(pos.at(x, y, 1), 0.f, 1e-4f);
            EXPECT_NEAR(pos.at(x, y, 2), expected.z, 1e-3f) << x << "," << y;
            EXPECT_NEAR(depth.at(x, y), 5.f, 1e-4f);
            EXPECT_NEAR(normal.at(x, y, 1), 1.f, 1e-5f);
        }
}

// The geometric normal is the triangle's own (its plane's normal turned toward the eye),
// whatever the vertex normals say, and w names the triangle (index + 1).
TEST(Raster, GBufferGeometricNormalIsTheTrianglesPlaneFacingTheEye) {
    Scene s;
    const uint32_t m = addMaterial(s, glm::vec3(0.5f));
    // A plane through the origin with normal (-1, 2, 0) / sqrt(5): spanned by (2, 1, 0) and z.
    addQuad(s, {-8, -4, -10}, {0, 0, 20}, {16, 8, 0}, m);
    for (glm::vec3& n : s.normals) n = glm::vec3(1, 0, 0);  // smooth normals that disagree
    finish(s);
    const glm::vec3 plane = glm::vec3(-1, 2, 0) / std::sqrt(5.f);
    GlContext::shared();
    GpuScene gpu = uploadScene(s);
    PassTimer timer;
    for (float side : {1.f, -1.f}) {
        Camera cam;
        cam.eye = glm::vec3(0, 5 * side, 0);
        cam.target = glm::vec3(0, 0, 0);
        cam.up = glm::vec3(0, 0, -1);
        cam.yfov = glm::radians(40.f);
        cam.znear = 0.01f;
        const int w = 16;
        GBuffer g = renderGBuffer(gpu, makeView(cam, w, w), timer, false);
        const Image geo = readTexture2D(g.geomNormal.id(), w, w, 4);
        GlContext::shared().checkErrors("raster test: geometric normal");
        int covered = 0;
        for (int i = 0; i < w * w; ++i) {
            const float* q = &geo.pixels[4 * size_t(i)];
            if (q[3] == 0.f) continue;
            ++covered;
            // RGBA16F: a unit normal's components to one unit in the last place of a half float
            // below 1, 2^-11 (GL leaves the rounding of the conversion to the driver; llvmpipe
            // truncates).
            EXPECT_NEAR(q[0], side * plane.x, 4.9e-4f) << "pixel " << i;
            EXPECT_NEAR(q[1], side * plane.y, 4.9e-4f) << "pixel " << i;
            EXPECT_NEAR(q[2], 0.f, 1e-6f) << "pixel " << i;
            EXPECT_EQ(q[3], 1.f) << "pixel " << i;
        }
        EXPECT_EQ(covered, w * w);
    }
}

TEST(Raster, DirectionalLightGivesLambertClosedForm) {
    Scene s = floorScene({0.6f, 0.4f, 0.2f});
    Light sun;
    sun.type = LightType::Directional;
    sun.color = glm::vec3(3.f);  // lux
    const float theta = glm::radians(30.f);
    sun.direction = glm::normalize(glm::vec3(std::sin(theta), -std::cos(theta), 0.f));
    s.lights.push_back(sun);
    RenderSession session(s);
    RenderResult res = session.render(topDown({"direct"}));
    GlContext::shared().checkErrors("raster test");
    const Image& d = res.aovs.at("direct");
    const float e = 3.f * std::cos(theta);
    for (int c = 0; c < 3; ++c) {
        const float albedo = c == 0 ? 0.6f : c == 1 ? 0.4f : 0.2f;
        EXPECT_NEAR(d.at(16, 16, c), albedo / kPi * e, 1e-3f) << "channel " << c;
        EXPECT_NEAR(d.at(3, 28, c), albedo / kPi * e, 1e-3f) << "channel " << c;
    }
}

TEST(Raster, PointLightFollowsInverseSquareAndCastsShadows) {
    Scene s = floorScene({0.5f, 0.5f, 0.5f});
    // A small blocker between the light and the floor to the left of the centre.
    uint32_t m = addMaterial(s, {0.5f, 0.5f, 0.5f});
    addQuad(s, {-1.5f, 1.f, -0.5f}, {0, 0, 1}, {1, 0, 0}, m);
    finish(s);
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0, 2, 0};
    bulb.color = glm::vec3(8.f);  // candela
    s.lights.push_back(bulb);
    RenderSession session(s);
    RenderRequest r = topDown({"direct", "position"}, 64);
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("raster test");
    const Image& d = res.aovs.at("direct");
    const Image& p = res.aovs.at("position");
    int lit = 0, shadowed = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (std::abs(p.at(x, y, 1)) > 1e-3f) continue;  // the blocker itself
            glm::vec3 q(p.at(x, y, 0), 0.f, p.at(x, y, 2));
            glm::vec3 toLight = bulb.position - q;
            float d2 = glm::dot(toLight, toLight);
            float expected = 0.5f / kPi * 8.f * (toLight.y / std::sqrt(d2)) / d2;
            // The blocker's shadow on the floor: project its corners from the light (y=1 -> y=0 doubles x, z).
            bool inShadow = q.x > -3.f + 0.1f && q.x < -1.f - 0.1f && q.z > -1.f + 0.1f && q.z < 1.f - 0.1f;
            bool nearEdge = q.x > -3.2f && q.x < -0.8f && q.z > -1.2f && q.z < 1.2f;
            if (inShadow) {
                EXPECT_LT(d.at(x, y, 0), 0.02f * expected) << q.x << "," << q.z;
                ++shadowed;
            } else if (!nearEdge) {
                EXPECT_NEAR(d.at(x, y, 0), expected, 0.01f * expected + 1e-5f) << q.x << "," << q.z;
                ++lit;
            }
        }
    EXPECT_GT(lit, 500);
    EXPECT_GT(shadowed, 20);
}

TEST(Raster, AoScalesOnlyTheAmbientTerm) {
    // beauty = emission + direct + sky * albedo * AO: with --ao reference on an open floor
    // (A = 1), the beauty equals direct + sky * albedo exactly; direct is not scaled.
    Scene s = floorScene({0.5f, 0.5f, 0.5f});
    Light sun;
    sun.type = LightType::Directional;
    sun.color = glm::vec3(2.f);
    sun.direction = {0, -1, 0};
    s.lights.push_back(sun);
    RenderSession session(s);
    RenderRequest r = topDown({"beauty", "direct", "indirect"});
    r.sky = 0.7f;
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("raster test");
    const float direct = 0.5f / kPi * 2.f;
    EXPECT_NEAR(res.aovs.at("direct").at(10, 10, 0), direct, 1e-4f);
    EXPECT_NEAR(res.aovs.at("indirect").at(10, 10, 0), 0.7f * 0.5f, 1e-5f);
    EXPECT_NEAR(res.aovs.at("beauty").at(10, 10, 0), direct + 0.35f, 1e-4f);
}

TEST(Raster, SharedGBufferAcrossRendersOfOneView) {
    Scene s = floorScene({0.5f, 0.5f, 0.5f});
    RenderSession session(s);
    session.render(topDown({"depth"}));
    session.render(topDown({"normal"}));
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 1);
    session.render(topDown({"normal"}, 16));
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 2);
}
