// Camera resolution and the default framing, checked by projecting with glm's own
// lookAt/perspective (an independent path from src/render/view).
#include "scene/camera.h"
#include "scene/scene_builder.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>

namespace {

vct::Bounds3 boundsOf(const glm::vec3& lo, const glm::vec3& hi) {
    vct::Bounds3 b;
    b.expand(lo);
    b.expand(hi);
    return b;
}

vct::Scene twoCameraScene() {
    vct::SceneBuilder b("cams");
    b.addBox("box", glm::vec3(-1.f), glm::vec3(1.f), b.addMaterial("m", glm::vec3(0.5f)));
    b.addCamera("front", glm::vec3(0, 0, 5), glm::vec3(0), 0.8f);
    b.addCamera("top", glm::vec3(0, 6, 0.01f), glm::vec3(0), 0.5f);
    return b.toScene();
}

}  // namespace

TEST(CameraResolve, DefaultFramingContainsEveryBoundsCorner) {
    const vct::Bounds3 cases[] = {boundsOf({-1, 0, -1}, {1, 2, 1}), boundsOf({-20, -1, -3}, {40, 2, 5}),
                                  boundsOf({1e-4f, 0, 0}, {2e-4f, 1e-4f, 3e-4f}),
                                  boundsOf({-5, -5, -90}, {5, 5, 90})};
    for (const vct::Bounds3& b : cases) {
        for (float aspect : {0.5f, 1.f, 16.f / 9.f, 3.f}) {
            const vct::Camera c = vct::defaultCamera(b, aspect);
            const glm::mat4 clipFromWorld =
                glm::perspective(c.yfov, aspect, c.znear, c.zfar) * glm::lookAt(c.eye, c.target, c.up);
            bool anyNearEdge = false;
            for (int i = 0; i < 8; ++i) {
                const glm::vec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                                       i & 4 ? b.max.z : b.min.z);
                const glm::vec4 clip = clipFromWorld * glm::vec4(corner, 1.f);
                ASSERT_GT(clip.w, 0.f);
                const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                EXPECT_LE(std::abs(ndc.x), 1.f) << "aspect " << aspect << " corner " << i;
                EXPECT_LE(std::abs(ndc.y), 1.f) << "aspect " << aspect << " corner " << i;
                EXPECT_GE(ndc.z, -1.f) << "corner in front of znear";
                EXPECT_LE(ndc.z, 1.f) << "corner before zfar";
                anyNearEdge = anyNearEdge || std::max(std::abs(ndc.x), std::abs(ndc.y)) > 0.3f;
            }
            EXPECT_TRUE(anyNearEdge) << "the framing should not leave the scene tiny (aspect " << aspect
                                     << ")";
            EXPECT_GT(c.eye.y, b.center().y) << "elevated view";
        }
    }
}

TEST(CameraResolve, ExplicitEyeTargetFovWins) {
    const vct::Scene s = twoCameraScene();
    vct::CameraRequest r;
    r.nameOrIndex = "top";  // ignored: the explicit eye wins
    r.hasEye = true;
    r.eye = glm::vec3(3, 2, 1);
    r.target = glm::vec3(0, 0.5f, 0);
    r.fovDeg = 30.f;
    const vct::Camera c = vct::resolveCamera(s, r, 1.5f);
    EXPECT_EQ(c.eye, r.eye);
    EXPECT_EQ(c.target, r.target);
    EXPECT_FLOAT_EQ(c.yfov, glm::radians(30.f));
    EXPECT_GT(c.znear, 0.f);
    EXPECT_GT(c.zfar, glm::length(r.eye) + 1.7f);  // beyond the far side of the box

    r.eye = glm::vec3(0, 5, 0);  // straight down: up must not be parallel to the view
    r.target = glm::vec3(0);
    const vct::Camera down = vct::resolveCamera(s, r, 1.f);
    EXPECT_LT(std::abs(glm::dot(down.up, glm::vec3(0, -1, 0))), 0.5f);
}

TEST(CameraResolve, ByNameByIndexFirstAndDefault) {
    const vct::Scene s = twoCameraScene();
    vct::CameraRequest r;
    r.nameOrIndex = "top";
    EXPECT_FLOAT_EQ(vct::resolveCamera(s, r, 1.f).yfov, 0.5f);
    EXPECT_NEAR(vct::resolveCamera(s, r, 1.f).eye.y, 6.f, 1e-5f);
    r.nameOrIndex = "1";
    EXPECT_EQ(vct::resolveCamera(s, r, 1.f).name, "top");
    r.nameOrIndex = "0";
    EXPECT_EQ(vct::resolveCamera(s, r, 1.f).name, "front");
    r.nameOrIndex = "";
    EXPECT_EQ(vct::resolveCamera(s, r, 1.f).name, "front");

    vct::Scene noCameras = s;
    noCameras.cameras.clear();
    const vct::Camera d = vct::resolveCamera(noCameras, r, 1.f);
    EXPECT_EQ(d.name, "default");
    EXPECT_NEAR(glm::length(d.target - s.bounds.center()), 0.f, 1e-5f);
}

TEST(CameraResolve, UnknownCameraListsTheAvailableOnes) {
    const vct::Scene s = twoCameraScene();
    for (const char* request : {"side", "2", "-1"}) {
        vct::CameraRequest r;
        r.nameOrIndex = request;
        try {
            vct::resolveCamera(s, r, 1.f);
            FAIL() << "no error for camera '" << request << "'";
        } catch (const std::invalid_argument& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(std::string("'") + request + "'"), std::string::npos) << msg;
            EXPECT_NE(msg.find("0 'front', 1 'top'"), std::string::npos) << msg;
        }
    }
}

TEST(CameraResolve, ParseVec3) {
    EXPECT_EQ(vct::parseVec3("1,2,3"), glm::vec3(1, 2, 3));
    EXPECT_EQ(vct::parseVec3(" 1.5, -2 ,3e2"), glm::vec3(1.5f, -2.f, 300.f));
    for (const char* bad :
         {"", "1,2", "1,2,3,4", "a,b,c", "1,,3", "1,2,3x", "nan,0,0", "0,inf,0", "1e39,0,0"})
        EXPECT_THROW(vct::parseVec3(bad), std::invalid_argument) << "'" << bad << "'";
}
