// Camera paths: the interpolation against its closed forms (lerp, the Catmull-Rom spline through
// its keys with the tangents (p_{i+1} - p_{i-1}) / 2), frame times, per-frame seeds, and the
// messages that name the file and the element.
#include "scene/camera_path.h"
#include "scene/camera.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <set>
#include <stdexcept>

namespace {

using vct::CameraPath;

nlohmann::json key(double t, glm::vec3 eye, glm::vec3 target, float fov = 45.f) {
    return {{"time", t}, {"eye", {eye.x, eye.y, eye.z}}, {"target", {target.x, target.y, target.z}}, {"fov", fov}};
}

CameraPath pathOf(const std::string& interpolation, const std::vector<nlohmann::json>& keys) {
    return vct::cameraPathFromJson({{"interpolation", interpolation}, {"keys", keys}}, "test.json");
}

std::string errorOf(const nlohmann::json& doc) {
    try {
        vct::cameraPathFromJson(doc, "walk.json");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(CameraPath, LinearIsTheLerpOfItsKeys) {
    CameraPath p = pathOf("linear", {key(0, {0, 0, 5}, {0, 0, 0}, 40), key(2, {4, 2, 5}, {1, 0, 0}, 60)});
    vct::CameraKey k = vct::interpolateCameraPath(p, 0.5);
    EXPECT_NEAR(k.eye.x, 1.f, 1e-6f);
    EXPECT_NEAR(k.eye.y, 0.5f, 1e-6f);
    EXPECT_NEAR(k.target.x, 0.25f, 1e-6f);
    EXPECT_NEAR(k.fovDeg, 45.f, 1e-5f);
    // Outside the span the camera stands at the end keys.
    EXPECT_EQ(vct::interpolateCameraPath(p, -1.0).eye, glm::vec3(0, 0, 5));
    EXPECT_EQ(vct::interpolateCameraPath(p, 9.0).eye, glm::vec3(4, 2, 5));
}

TEST(CameraPath, CatmullRomPassesThroughEveryKeyWithCentralTangents) {
    const std::vector<glm::vec3> eyes{{0, 0, 5}, {2, 1, 5}, {3, 3, 4}, {6, 2, 6}};
    std::vector<nlohmann::json> keys;
    for (size_t i = 0; i < eyes.size(); ++i) keys.push_back(key(double(i), eyes[i], {0, 0, 0}));
    CameraPath p = pathOf("catmull-rom", keys);
    for (size_t i = 0; i < eyes.size(); ++i) {
        glm::vec3 e = vct::interpolateCameraPath(p, double(i)).eye;
        EXPECT_NEAR(glm::length(e - eyes[i]), 0.f, 1e-5f) << "key " << i;
    }
    // The velocity at interior key 1 is (p2 - p0) / 2 per unit time, from both sides (no kink).
    // One-sided second-order differences, each within one interval: error O(h^2).
    auto eyeAt = [&](double t) { return vct::interpolateCameraPath(p, t).eye; };
    const double h = 1e-2;
    glm::vec3 after = (-3.f * eyeAt(1.0) + 4.f * eyeAt(1.0 + h) - eyeAt(1.0 + 2 * h)) / float(2 * h);
    glm::vec3 before = (3.f * eyeAt(1.0) - 4.f * eyeAt(1.0 - h) + eyeAt(1.0 - 2 * h)) / float(2 * h);
    glm::vec3 expected = 0.5f * (eyes[2] - eyes[0]);
    EXPECT_NEAR(glm::length(before - expected), 0.f, 2e-3f);
    EXPECT_NEAR(glm::length(after - expected), 0.f, 2e-3f);
    // Three collinear, evenly timed keys: the spline is the straight line at constant speed.
    CameraPath line = pathOf("catmull-rom", {key(0, {0, 0, 5}, {0, 0, 0}), key(1, {1, 0, 5}, {0, 0, 0}),
                                             key(2, {2, 0, 5}, {0, 0, 0})});
    EXPECT_NEAR(vct::interpolateCameraPath(line, 0.5).eye.x, 0.5f, 1e-5f);
    EXPECT_NEAR(vct::interpolateCameraPath(line, 1.25).eye.x, 1.25f, 1e-5f);
}

TEST(CameraPath, FrameTimesSpanThePathAndSeedsDiffer) {
    CameraPath p = pathOf("linear", {key(1, {0, 0, 5}, {0, 0, 0}), key(3, {1, 0, 5}, {0, 0, 0})});
    std::vector<double> t = vct::pathFrameTimes(p, 5);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_DOUBLE_EQ(t.front(), 1.0);
    EXPECT_DOUBLE_EQ(t[2], 2.0);
    EXPECT_DOUBLE_EQ(t.back(), 3.0);
    EXPECT_EQ(vct::pathFrameTimes(p, 1), std::vector<double>{1.0});
    EXPECT_EQ(vct::frameSeed(7, 0), 7u);  // one frame is the still render
    std::set<uint64_t> seeds;
    for (int f = 0; f < 100; ++f) seeds.insert(vct::frameSeed(7, f));
    EXPECT_EQ(seeds.size(), 100u);
    EXPECT_EQ(vct::frameSeed(7, 3), vct::frameSeed(7, 3));
}

TEST(CameraPath, AFrameIsTheExplicitCameraOfItsKey) {
    CameraPath p = pathOf("linear", {key(0, {0, 0, 5}, {0, 0, 0}, 30), key(1, {0, 0, 7}, {0, 0, 0}, 30)});
    vct::Scene scene;
    scene.bounds.expand(glm::vec3(-1.f));
    scene.bounds.expand(glm::vec3(1.f));
    vct::Camera c = vct::cameraOnPath(p, 0.5, scene);
    vct::CameraRequest still;
    still.hasEye = true;
    still.eye = glm::vec3(0, 0, 6);
    still.target = glm::vec3(0);
    still.fovDeg = 30.f;
    vct::Camera want = vct::resolveCamera(scene, still, 1.f);
    EXPECT_EQ(c.eye, want.eye);
    EXPECT_EQ(c.up, want.up);
    EXPECT_EQ(c.yfov, want.yfov);
    EXPECT_EQ(c.znear, want.znear);
    EXPECT_EQ(c.zfar, want.zfar);
}

TEST(CameraPath, RoundTripsThroughJson) {
    CameraPath p = pathOf("linear", {key(0, {0, 0, 5}, {0, 0, 0}), key(1, {1, 0, 5}, {0, 1, 0})});
    CameraPath q = vct::cameraPathFromJson(vct::cameraPathToJson(p), "again");
    ASSERT_EQ(q.keys.size(), 2u);
    EXPECT_EQ(q.interpolation, vct::PathInterpolation::Linear);
    EXPECT_EQ(q.keys[1].target, glm::vec3(0, 1, 0));
}

TEST(CameraPath, BadInputNamesTheFileAndTheElement) {
    const nlohmann::json good = key(0, {0, 0, 5}, {0, 0, 0});
    EXPECT_NE(errorOf({{"keys", nlohmann::json::array()}}).find("walk.json: keys"), std::string::npos);
    nlohmann::json badEye = good;
    badEye["eye"] = {1, 2};
    EXPECT_NE(errorOf({{"keys", {good, badEye}}}).find("walk.json: keys[1].eye"), std::string::npos);
    nlohmann::json same = key(0, {0, 0, 5}, {0, 0, 0});
    EXPECT_NE(errorOf({{"keys", {good, same}}}).find("keys[1].time: times must increase"), std::string::npos);
    nlohmann::json fov = key(1, {0, 0, 5}, {0, 0, 0}, 180.f);
    EXPECT_NE(errorOf({{"keys", {good, fov}}}).find("keys[1].fov"), std::string::npos);
    nlohmann::json coincide = key(1, {0, 0, 0}, {0, 0, 0});
    EXPECT_NE(errorOf({{"keys", {good, coincide}}}).find("eye and target coincide"), std::string::npos);
    nlohmann::json upAlong = key(1, {0, 5, 0}, {0, 0, 0});
    EXPECT_NE(errorOf({{"keys", {good, upAlong}}}).find("keys[1].up"), std::string::npos);
    EXPECT_NE(errorOf({{"interpolation", "cubic"}, {"keys", {good}}}).find("interpolation"), std::string::npos);
    EXPECT_NE(errorOf({{"keys", {good}}, {"speed", 2}}).find("unknown key \"speed\""), std::string::npos);
    nlohmann::json nan = good;
    nan["time"] = "soon";
    EXPECT_NE(errorOf({{"keys", {nan}}}).find("keys[0].time"), std::string::npos);

    const std::string file = testing::TempDir() + "/broken_path.json";
    std::ofstream(file) << "{ \"keys\": [ ";
    try {
        vct::loadCameraPath(file);
        FAIL() << "a truncated file loaded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file + ": not valid JSON"), std::string::npos) << e.what();
    }
    std::remove(file.c_str());
    EXPECT_THROW(vct::loadCameraPath("/nonexistent/path.json"), std::runtime_error);
}

}  // namespace
