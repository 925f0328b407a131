// glTF camera animations: closed-form motions (a linear slide, a slerped turn, STEP, a
// CUBICSPLINE with zero tangents, a parent's orbit) checked at their dense samples; which
// animations become camera paths; malformed samplers; the listing and the lookup by name
// and index.
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "scene/scene_builder.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using vct::CameraAnimationKey;
using vct::CameraAnimationTrack;
using vct::Scene;

namespace {

constexpr float kYfov = 0.8f;

// A box (the loader needs triangles) and camera 'cam' at (0, 0, 5) looking down -Z, as a
// tinygltf model that the tests add animations to before loading it.
struct AnimatedModel {
    tinygltf::Model model;
    int cameraNode = -1;
    int boxNode = -1;
    int lampNode = -1;

    AnimatedModel() {
        vct::SceneBuilder b("anim");
        const int grey = b.addMaterial("grey", glm::vec3(0.5f));
        boxNode = b.addBox("box", glm::vec3(-1.f), glm::vec3(1.f), grey);
        cameraNode = b.addCamera("cam", glm::vec3(0.f, 0.f, 5.f), glm::vec3(0.f), kYfov);
        lampNode = b.addPointLight("lamp", glm::vec3(0.f, 3.f, 0.f), glm::vec3(1.f), 10.f);
        model = b.build();
    }

    // Float accessor of `type` (TINYGLTF_TYPE_SCALAR, _VEC3, _VEC4) over new bytes in buffer 0.
    int accessor(const std::vector<float>& values, int type) {
        std::vector<unsigned char>& data = model.buffers[0].data;
        data.resize((data.size() + 3) & ~size_t(3), 0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = values.size() * sizeof(float);
        data.resize(data.size() + view.byteLength);
        std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
        model.bufferViews.push_back(view);
        tinygltf::Accessor acc;
        acc.bufferView = int(model.bufferViews.size()) - 1;
        acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        acc.type = type;
        acc.count = values.size() / size_t(tinygltf::GetNumComponentsInType(uint32_t(type)));
        model.accessors.push_back(acc);
        return int(model.accessors.size()) - 1;
    }

    // A channel on `node`'s `path` with its own sampler, in animation `name` (created when
    // the model has none of that name). Returns the animation's index.
    int animate(const std::string& name, int node, const std::string& path, const std::vector<float>& times,
                const std::vector<float>& values, const std::string& interpolation = "LINEAR") {
        int a = 0;
        while (a < int(model.animations.size()) && model.animations[size_t(a)].name != name) ++a;
        if (a == int(model.animations.size())) {
            model.animations.emplace_back();
            model.animations.back().name = name;
        }
        tinygltf::Animation& anim = model.animations[size_t(a)];
        tinygltf::AnimationSampler s;
        s.input = accessor(times, TINYGLTF_TYPE_SCALAR);
        const int type = path == "rotation" ? TINYGLTF_TYPE_VEC4 : path == "weights" ? TINYGLTF_TYPE_SCALAR
                                                                                     : TINYGLTF_TYPE_VEC3;
        s.output = accessor(values, type);
        s.interpolation = interpolation;
        anim.samplers.push_back(s);
        tinygltf::AnimationChannel ch;
        ch.sampler = int(anim.samplers.size()) - 1;
        ch.target_node = node;
        ch.target_path = path;
        anim.channels.push_back(ch);
        return a;
    }

    Scene load() const { return vct::sceneFromModel(model, "anim.gltf"); }
};

// The sample at time t (the tests pick times on the 16-per-interval grid).
const CameraAnimationKey& keyAt(const CameraAnimationTrack& track, double t) {
    for (const CameraAnimationKey& k : track.keys)
        if (std::abs(k.time - t) < 1e-9) return k;
    ADD_FAILURE() << "no sample at t = " << t << " in animation '" << track.name << "'";
    return track.keys.front();
}

void expectNear(const glm::vec3& got, const glm::vec3& want, float tol = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tol) << "got (" << got.x << ", " << got.y << ", " << got.z << ")";
    EXPECT_NEAR(got.y, want.y, tol) << "got (" << got.x << ", " << got.y << ", " << got.z << ")";
    EXPECT_NEAR(got.z, want.z, tol) << "got (" << got.x << ", " << got.y << ", " << got.z << ")";
}

// glTF's (x, y, z, w) for a rotation of `degrees` about +Y.
std::vector<float> aboutY(float degrees) {
    const float half = 0.5f * glm::radians(degrees);
    return {0.f, std::sin(half), 0.f, std::cos(half)};
}

std::vector<float> concat(std::vector<float> a, const std::vector<float>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

std::string messageOf(const AnimatedModel& m) {
    try {
        m.load();
    } catch (const vct::SceneError& e) {
        return e.what();
    }
    return "(loaded without error)";
}

}  // namespace

TEST(GltfAnimation, LinearTranslationMovesTheEye) {
    AnimatedModel m;
    m.animate("slide", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 5, 4, 0, 5});
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    EXPECT_EQ(track.name, "slide");
    EXPECT_EQ(track.animation, 0);
    EXPECT_EQ(track.cameraName, "cam");
    EXPECT_EQ(track.keys.size(), 17u);  // 2 key times and 15 samples between them
    const CameraAnimationKey& k = keyAt(track, 0.5);
    expectNear(k.eye, glm::vec3(1.f, 0.f, 5.f));
    expectNear(k.target, k.eye + glm::vec3(0.f, 0.f, -1.f));
    expectNear(k.up, glm::vec3(0.f, 1.f, 0.f));
    EXPECT_FLOAT_EQ(k.yfov, kYfov);
    expectNear(track.keys.back().eye, glm::vec3(4.f, 0.f, 5.f));
    // The static camera keeps the node's own pose.
    expectNear(s.cameras[0].eye, glm::vec3(0.f, 0.f, 5.f));
}

TEST(GltfAnimation, LinearRotationIsASlerp) {
    AnimatedModel m;
    m.animate("turn", m.cameraNode, "rotation", {0.f, 1.f}, concat(aboutY(0.f), aboutY(90.f)));
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationKey& k = keyAt(s.cameraAnimations[0], 0.5);
    const float h = std::sqrt(0.5f);
    expectNear(k.eye, glm::vec3(0.f, 0.f, 5.f));
    expectNear(k.target - k.eye, glm::vec3(-h, 0.f, -h));  // -Z turned 45 degrees about +Y
    expectNear(k.up, glm::vec3(0.f, 1.f, 0.f));
    // A quarter of the way: a quarter of the angle (a lerp of the quaternions would not be).
    const CameraAnimationKey& q = keyAt(s.cameraAnimations[0], 0.25);
    expectNear(q.target - q.eye, glm::vec3(-std::sin(glm::radians(22.5f)), 0.f, -std::cos(glm::radians(22.5f))));
}

TEST(GltfAnimation, SlerpTakesTheShorterArc) {
    AnimatedModel m;
    std::vector<float> end = aboutY(90.f);
    for (float& x : end) x = -x;  // the same rotation, on the far side of the quaternion sphere
    m.animate("turn", m.cameraNode, "rotation", {0.f, 1.f}, concat(aboutY(0.f), end));
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationKey& k = keyAt(s.cameraAnimations[0], 0.5);
    const float h = std::sqrt(0.5f);
    expectNear(k.target - k.eye, glm::vec3(-h, 0.f, -h));
}

TEST(GltfAnimation, StepHoldsEachValueUntilTheNextKey) {
    AnimatedModel m;
    m.animate("jump", m.cameraNode, "translation", {0.f, 1.f, 2.f}, {0, 0, 5, 4, 0, 5, 8, 0, 5}, "STEP");
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    EXPECT_EQ(track.keys.size(), 33u);
    expectNear(keyAt(track, 0.5).eye, glm::vec3(0.f, 0.f, 5.f));
    expectNear(keyAt(track, 15.0 / 16.0).eye, glm::vec3(0.f, 0.f, 5.f));
    expectNear(keyAt(track, 1.0).eye, glm::vec3(4.f, 0.f, 5.f));
    expectNear(keyAt(track, 1.5).eye, glm::vec3(4.f, 0.f, 5.f));
    expectNear(keyAt(track, 2.0).eye, glm::vec3(8.f, 0.f, 5.f));
}

TEST(GltfAnimation, CubicSplineWithZeroTangentsIsSmoothstep) {
    AnimatedModel m;
    // Per key: in-tangent, value, out-tangent.
    m.animate("ease", m.cameraNode, "translation", {0.f, 1.f}, {0, 0, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 4, 0, 5, 0, 0, 0},
              "CUBICSPLINE");
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    for (double u : {0.0, 0.25, 0.5, 0.8125, 1.0}) {
        const float smooth = float(u * u * (3.0 - 2.0 * u));
        expectNear(keyAt(track, u).eye, glm::vec3(4.f * smooth, 0.f, 5.f));
    }
}

TEST(GltfAnimation, CubicSplineTangentsScaleWithTheInterval) {
    AnimatedModel m;
    // x from 0 to 0 over 2 s with out-tangent 1 (units per second) and in-tangent 0: the
    // Hermite x(u) = td * (u^3 - 2u^2 + u) with td = 2.
    m.animate("bump", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 0, 0, 0, 5, 1, 0, 0, 0, 0, 0, 0, 0, 5, 0, 0, 0},
              "CUBICSPLINE");
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    const double u = 0.25;
    expectNear(keyAt(track, 2.0 * u).eye, glm::vec3(float(2.0 * (u * u * u - 2 * u * u + u)), 0.f, 5.f));
}

TEST(GltfAnimation, ParentAnimationMovesAChildCamera) {
    vct::SceneBuilder b("anim");
    const int grey = b.addMaterial("grey", glm::vec3(0.5f));
    b.addBox("box", glm::vec3(-1.f), glm::vec3(1.f), grey);
    const int rig = b.addNode("rig");
    vct::NodeTransform local;
    local.translation = glm::vec3(0.f, 0.f, 5.f);
    const int camNode = b.addNode("cam", -1, local, rig);
    AnimatedModel m;
    m.model = b.build();
    tinygltf::Camera c;
    c.name = "orbiter";
    c.type = "perspective";
    c.perspective.yfov = kYfov;
    c.perspective.znear = 0.05;
    c.perspective.zfar = 100.0;
    m.model.cameras.push_back(c);
    m.model.nodes[size_t(camNode)].camera = 0;
    m.animate("orbit", rig, "rotation", {0.f, 1.f}, concat(aboutY(0.f), aboutY(90.f)));
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    EXPECT_EQ(track.cameraName, "orbiter");
    const float h = std::sqrt(0.5f);
    const CameraAnimationKey& mid = keyAt(track, 0.5);
    expectNear(mid.eye, glm::vec3(5.f * h, 0.f, 5.f * h));
    expectNear(mid.target - mid.eye, glm::vec3(-h, 0.f, -h));  // still facing the pivot
    const CameraAnimationKey& end = keyAt(track, 1.0);
    expectNear(end.eye, glm::vec3(5.f, 0.f, 0.f));
    expectNear(end.target, glm::vec3(4.f, 0.f, 0.f));
}

TEST(GltfAnimation, KeyTimesOfEveryChannelAreSampled) {
    AnimatedModel m;
    m.animate("both", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 5, 4, 0, 5});
    m.animate("both", m.cameraNode, "rotation", {0.f, 1.f}, concat(aboutY(0.f), aboutY(90.f)));
    const Scene s = m.load();
    ASSERT_EQ(s.cameraAnimations.size(), 1u);
    const CameraAnimationTrack& track = s.cameraAnimations[0];
    EXPECT_EQ(track.keys.size(), 33u);  // key times 0, 1, 2 and 15 between each pair
    const CameraAnimationKey& k = keyAt(track, 1.5);
    expectNear(k.eye, glm::vec3(3.f, 0.f, 5.f));
    expectNear(k.target - k.eye, glm::vec3(-1.f, 0.f, 0.f));  // the rotation holds its last key
    for (size_t i = 1; i < track.keys.size(); ++i) EXPECT_GT(track.keys[i].time, track.keys[i - 1].time);
}

TEST(GltfAnimation, AnimationsThatMoveNoCameraAreIgnoredUnchecked) {
    AnimatedModel m;
    m.animate("spin box", m.boxNode, "translation", {0.f, 1.f}, {0, 0, 0, 0, 1, 0});
    // Decreasing times, but on the box: named as malformed, not a camera path; the file loads.
    m.animate("broken box", m.boxNode, "translation", {1.f, 0.f}, {0, 0, 0, 0, 1, 0});
    m.animate("morph", m.cameraNode, "weights", {0.f, 1.f}, {0.f, 1.f});
    const Scene s = m.load();
    EXPECT_TRUE(s.cameraAnimations.empty());
    EXPECT_EQ(vct::describeCameraAnimations(s), "(none)");
}

TEST(GltfAnimation, MalformedSamplerOnACameraNamesFileAnimationChannelAndSampler) {
    {
        AnimatedModel m;
        m.animate("bad", m.cameraNode, "translation", {1.f, 0.5f}, {0, 0, 5, 4, 0, 5});
        const std::string msg = messageOf(m);
        EXPECT_NE(msg.find("anim.gltf: animation 0 'bad', channel 0 (node 1 'cam' translation), sampler 0"),
                  std::string::npos) << msg;
        EXPECT_NE(msg.find("not strictly increasing"), std::string::npos) << msg;
    }
    {
        AnimatedModel m;
        m.animate("short", m.cameraNode, "translation", {0.f, 1.f, 2.f}, {0, 0, 5, 4, 0, 5});
        const std::string msg = messageOf(m);
        EXPECT_NE(msg.find("animation 0 'short'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("output has 2 elements for 3 key times"), std::string::npos) << msg;
    }
    {
        AnimatedModel m;
        m.animate("odd", m.cameraNode, "translation", {0.f, 1.f}, {0, 0, 5, 4, 0, 5}, "BEZIER");
        EXPECT_NE(messageOf(m).find("unknown interpolation 'BEZIER'"), std::string::npos) << messageOf(m);
    }
    {
        AnimatedModel m;
        m.animate("nan", m.cameraNode, "translation", {0.f, 1.f}, {0, 0, 5, NAN, 0, 5});
        EXPECT_NE(messageOf(m).find("output element 1 is not finite"), std::string::npos) << messageOf(m);
    }
    {
        AnimatedModel m;
        m.animate("lost", m.cameraNode, "translation", {0.f, 1.f}, {0, 0, 5, 4, 0, 5});
        m.model.animations[0].samplers[0].output = 99;
        const std::string msg = messageOf(m);
        EXPECT_NE(msg.find("animation 0 'lost'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("accessor 99 out of range"), std::string::npos) << msg;
    }
}

TEST(GltfAnimation, DescribeListsNameCameraSpanAndKeyCount) {
    AnimatedModel m;
    m.animate("slide", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 5, 4, 0, 5});
    m.animate("turn", m.cameraNode, "rotation", {0.5f, 1.f, 1.5f},
              concat(aboutY(0.f), concat(aboutY(45.f), aboutY(90.f))));
    const Scene s = m.load();
    EXPECT_EQ(vct::describeCameraAnimations(s),
              "0 'slide' (camera 'cam', 0..2 s, 17 keys), 1 'turn' (camera 'cam', 0.5..1.5 s, 33 keys)");
    const std::vector<vct::CameraAnimationInfo> infos = vct::listCameraAnimations(s);
    ASSERT_EQ(infos.size(), 2u);
    EXPECT_EQ(infos[1].animation, 1);
    EXPECT_DOUBLE_EQ(infos[1].start, 0.5);
    EXPECT_DOUBLE_EQ(infos[1].end, 1.5);
    EXPECT_EQ(infos[1].keyCount, 33u);
}

TEST(GltfAnimation, PathByNameAndByIndex) {
    AnimatedModel m;
    m.animate("slide", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 5, 4, 0, 5});
    m.animate("turn", m.cameraNode, "rotation", {0.f, 1.f}, concat(aboutY(0.f), aboutY(90.f)));
    const Scene s = m.load();
    const vct::CameraPath byName = vct::cameraAnimationPath(s, "turn");
    EXPECT_EQ(byName.source, "anim.gltf: animation 'turn'");
    EXPECT_EQ(byName.interpolation, vct::PathInterpolation::Linear);
    ASSERT_EQ(byName.keys.size(), 17u);
    EXPECT_DOUBLE_EQ(byName.startTime(), 0.0);
    EXPECT_DOUBLE_EQ(byName.endTime(), 1.0);
    EXPECT_NEAR(byName.keys[0].fovDeg, glm::degrees(kYfov), 1e-4);
    expectNear(byName.keys.back().target - byName.keys.back().eye, glm::vec3(-1.f, 0.f, 0.f));

    const vct::CameraPath byIndex = vct::cameraAnimationPath(s, "0");
    EXPECT_EQ(byIndex.source, "anim.gltf: animation 'slide'");
    expectNear(byIndex.keys.back().eye, glm::vec3(4.f, 0.f, 5.f));
}

TEST(GltfAnimation, UnknownPathNamesTheAvailableOnes) {
    AnimatedModel m;
    m.animate("slide", m.cameraNode, "translation", {0.f, 2.f}, {0, 0, 5, 4, 0, 5});
    const Scene s = m.load();
    for (const char* wrong : {"spin", "1"}) {
        try {
            vct::cameraAnimationPath(s, wrong);
            ADD_FAILURE() << "no error for '" << wrong << "'";
        } catch (const vct::UsageError& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(std::string("no camera animation '") + wrong + "' in anim.gltf"), std::string::npos)
                << msg;
            EXPECT_NE(msg.find("0 'slide' (camera 'cam', 0..2 s, 17 keys)"), std::string::npos) << msg;
        }
    }
}

// Lights: a translation channel on the lamp's node becomes a light track, which poses the light
// at any time (linear between the dense samples, held at the ends); its own animation moves no
// camera, so it is no camera path.
TEST(GltfAnimation, ALightsNodeAnimationPosesTheLight) {
    AnimatedModel m;
    m.animate("sweep", m.lampNode, "translation", {0.f, 2.f}, {-2.f, 3.f, 0.f, 2.f, 3.f, 0.f});
    Scene s = m.load();
    ASSERT_EQ(s.lightAnimations.size(), 1u);
    EXPECT_TRUE(s.cameraAnimations.empty());
    EXPECT_EQ(s.lightAnimations[0].name, "sweep");
    EXPECT_TRUE(vct::animationMovesLights(s, "sweep"));
    EXPECT_FALSE(vct::animationMovesLights(s, "other"));
    EXPECT_NE(vct::describeLightAnimations(s).find("'sweep' (light 'lamp', 0..2 s"), std::string::npos)
        << vct::describeLightAnimations(s);
    EXPECT_EQ(vct::poseLights(s, "sweep", 0.5), 1);
    expectNear(s.lights[0].position, glm::vec3(-1.f, 3.f, 0.f));
    EXPECT_EQ(vct::poseLights(s, "sweep", 9.0), 1);
    expectNear(s.lights[0].position, glm::vec3(2.f, 3.f, 0.f));
    EXPECT_EQ(vct::poseLights(s, "other", 1.0), 0);
    expectNear(s.lights[0].position, glm::vec3(2.f, 3.f, 0.f));
}

// Objects: a rigid animation of a mesh node becomes a mesh track, which poses the node's
// vertices at any time from their rest pose (exact at the samples, the node's rotation slerped
// between them), holds them at the ends, and leaves them alone when nothing changed.
TEST(GltfAnimation, ARigidObjectAnimationPosesItsVertices) {
    AnimatedModel m;
    m.animate("slide", m.boxNode, "translation", {0.f, 1.f}, {0.f, 0.f, 0.f, 1.f, 0.f, 0.f});
    m.animate("sweep", m.lampNode, "translation", {0.f, 1.f}, {0.f, 3.f, 0.f, 1.f, 3.f, 0.f});
    Scene s = m.load();
    EXPECT_TRUE(s.geometryAnimations.empty());
    ASSERT_EQ(s.meshAnimations.size(), 1u);
    const vct::MeshAnimationTrack& track = s.meshAnimations[0];
    EXPECT_EQ(track.name, "slide");
    EXPECT_EQ(track.nodeName, "node 0 'box'");
    ASSERT_EQ(track.restPositions.size(), s.positions.size());  // the box is the only mesh
    EXPECT_TRUE(vct::animationMovesGeometry(s, "slide"));
    EXPECT_FALSE(vct::animationMovesGeometry(s, "sweep"));
    EXPECT_NE(vct::describeMeshAnimations(s).find("'slide' (node 0 'box', 24 vertices, 0..1 s"), std::string::npos)
        << vct::describeMeshAnimations(s);
    const std::vector<glm::vec3> rest = s.positions, restNormals = s.normals;

    EXPECT_EQ(vct::poseMeshes(s, "slide", 0.3), 1);
    for (size_t v = 0; v < rest.size(); ++v) {
        expectNear(s.positions[v], rest[v] + glm::vec3(0.3f, 0.f, 0.f));
        expectNear(s.normals[v], restNormals[v]);
    }
    EXPECT_EQ(vct::poseMeshes(s, "slide", 0.3), 0) << "the same pose again changed the vertices";
    EXPECT_EQ(vct::poseMeshes(s, "sweep", 0.6), 0);
    EXPECT_EQ(vct::poseMeshes(s, "slide", 7.0), 1);
    for (size_t v = 0; v < rest.size(); ++v) expectNear(s.positions[v], rest[v] + glm::vec3(1.f, 0.f, 0.f));
    const vct::AnimationPose both = vct::poseAnimation(s, "slide", 0.0);
    EXPECT_EQ(both.meshesMoved, 1);
    EXPECT_EQ(both.lightsMoved, 0);
    for (size_t v = 0; v < rest.size(); ++v) expectNear(s.positions[v], rest[v]);

    // The bounds a sequence keeps hold every pose: the box spans x in [-1, 2] over the slide.
    const vct::Bounds3 swept = vct::animationBounds(s, "slide");
    EXPECT_NEAR(swept.min.x, -1.f, 1e-5f);
    EXPECT_NEAR(swept.max.x, 2.f, 1e-5f);
    EXPECT_NEAR(swept.max.y, s.bounds.max.y, 1e-5f);
    EXPECT_NEAR(vct::animationBounds(s, "sweep").max.x, s.bounds.max.x, 1e-6f);
}

TEST(GltfAnimation, ARotatingObjectTurnsItsVerticesAndNormals) {
    AnimatedModel m;
    m.animate("turn", m.boxNode, "rotation", {0.f, 1.f}, concat(aboutY(0.f), aboutY(90.f)));
    Scene s = m.load();
    ASSERT_EQ(s.meshAnimations.size(), 1u);
    const std::vector<glm::vec3> rest = s.positions, restNormals = s.normals;
    // 0.23 s lies between two dense samples: slerp of a uniform turn is the turn itself.
    for (double t : {0.5, 0.23}) {
        ASSERT_EQ(vct::poseMeshes(s, "turn", t), 1);
        const float a = glm::radians(90.f * float(t));
        auto turned = [&](const glm::vec3& p) {
            return glm::vec3(std::cos(a) * p.x + std::sin(a) * p.z, p.y, -std::sin(a) * p.x + std::cos(a) * p.z);
        };
        for (size_t v = 0; v < rest.size(); ++v) {
            expectNear(s.positions[v], turned(rest[v]), 1e-4f);
            expectNear(s.normals[v], turned(restNormals[v]), 1e-4f);
        }
    }
}

// Animations that deform geometry (morph weights, a skin's joints) or that are malformed where
// they move an object are named with what they do, so a sequence can refuse them; the file's
// still renders load as before.
TEST(GltfAnimation, DeformingOrMalformedObjectAnimationsAreNamed) {
    AnimatedModel m;
    m.animate("morph", m.boxNode, "weights", {0.f, 1.f}, {0.f, 1.f});
    m.animate("broken", m.boxNode, "translation", {1.f, 0.f}, {0.f, 0.f, 0.f, 1.f, 0.f, 0.f});
    tinygltf::Node joint;
    joint.name = "joint";
    m.model.nodes.push_back(joint);
    const int jointNode = int(m.model.nodes.size()) - 1;
    m.model.scenes[0].nodes.push_back(jointNode);
    tinygltf::Skin skin;
    skin.joints = {jointNode};
    m.model.skins.push_back(skin);
    m.animate("wave", jointNode, "translation", {0.f, 1.f}, {0.f, 0.f, 0.f, 0.f, 1.f, 0.f});
    const Scene s = m.load();
    EXPECT_TRUE(s.meshAnimations.empty()) << vct::describeMeshAnimations(s);
    std::map<std::string, std::string> named(s.geometryAnimations.begin(), s.geometryAnimations.end());
    ASSERT_EQ(named.size(), 3u);
    EXPECT_NE(named["morph"].find("morph target weights of node 0 'box'"), std::string::npos) << named["morph"];
    EXPECT_NE(named["broken"].find("malformed"), std::string::npos) << named["broken"];
    EXPECT_NE(named["broken"].find("not strictly increasing"), std::string::npos) << named["broken"];
    EXPECT_NE(named["wave"].find("'joint', a joint of a skin"), std::string::npos) << named["wave"];
}
