#include "scene/scene_library.h"

#include "core/errors.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

namespace vct {
namespace {

const glm::vec3 kWhite(0.73f, 0.73f,
                       0.73f);  // Cornell box reflectances (Cornell program of computer graphics)
const glm::vec3 kRed(0.63f, 0.065f, 0.05f);
const glm::vec3 kGreen(0.14f, 0.45f, 0.091f);
const glm::vec3 kFloorGrey(0.7f);
const glm::vec3 kWallBeige(0.75f, 0.7f, 0.62f);
const glm::vec3 kOccluderBlue(0.35f, 0.45f, 0.65f);

glm::quat yaw(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0.f, 1.f, 0.f)); }

NodeTransform boxAt(const glm::vec3& center, const glm::vec3& size, float yawDegrees) {
    NodeTransform t;
    t.translation = center;
    t.rotation = yaw(yawDegrees);
    t.scale = size;
    return t;
}

// The point `distance` ahead of `eye` along a view pitched down by `pitchDownDegrees` toward -Z.
glm::vec3 targetPitchedDown(const glm::vec3& eye, float pitchDownDegrees, float distance = 2.f) {
    const float a = glm::radians(pitchDownDegrees);
    return eye + distance * glm::vec3(0.f, -std::sin(a), -std::cos(a));
}

// An off-screen occluder: named "offscreen_*" and flagged in extras, so either convention finds it.
int offscreenBox(SceneBuilder& b, const std::string& name, const glm::vec3& min, const glm::vec3& max,
                 int material) {
    const int node = b.addBox("offscreen_" + name, min, max, material);
    b.markOffscreen(node);
    return node;
}

void addSun(SceneBuilder& b, float intensity = 2.f) {
    b.addDirectionalLight("sun", glm::normalize(glm::vec3(0.4f, -1.f, -0.3f)), glm::vec3(1.f, 0.96f, 0.9f),
                          intensity);
}

// The Cornell box under `name`; `pointLight` and `shortBox` (when given) receive those nodes.
SceneBuilder cornellBoxNamed(const std::string& name, int* pointLight, int* shortBox = nullptr) {
    SceneBuilder b(name);
    const int white = b.addMaterial("white", kWhite);
    const int red = b.addMaterial("red", kRed);
    const int green = b.addMaterial("green", kGreen);
    const int light = b.addMaterial("light", glm::vec3(0.78f), 8.f * glm::vec3(1.f, 0.85f, 0.6f));
    // Walls as single quads facing into the box; the front (+Z) is open.
    b.addQuad("floor", glm::vec3(-1, 0, -1), glm::vec3(0, 0, 2), glm::vec3(2, 0, 0), white);
    b.addQuad("ceiling", glm::vec3(-1, 2, -1), glm::vec3(2, 0, 0), glm::vec3(0, 0, 2), white);
    b.addQuad("back_wall", glm::vec3(-1, 0, -1), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0), white);
    b.addQuad("left_wall", glm::vec3(-1, 0, -1), glm::vec3(0, 2, 0), glm::vec3(0, 0, 2), red);
    b.addQuad("right_wall", glm::vec3(1, 0, -1), glm::vec3(0, 0, 2), glm::vec3(0, 2, 0), green);
    b.addTransformedBox("tall_box", boxAt(glm::vec3(-0.33f, 0.6f, -0.3f), glm::vec3(0.6f, 1.2f, 0.6f), 17.f),
                        white);
    const int shortNode =
        b.addTransformedBox("short_box", boxAt(glm::vec3(0.35f, 0.3f, 0.35f), glm::vec3(0.6f), -17.f), white);
    if (shortBox) *shortBox = shortNode;
    // The emitter 2 cm under the ceiling, facing down: cross(+X, +Z) = -Y.
    b.addQuad("ceiling_light", glm::vec3(-0.25f, 1.98f, -0.25f), glm::vec3(0.5f, 0, 0), glm::vec3(0, 0, 0.5f),
              light);
    const int lamp = b.addPointLight("ceiling_point", glm::vec3(0.f, 1.8f, 0.f), glm::vec3(1.f, 0.85f, 0.6f), 4.f);
    if (pointLight) *pointLight = lamp;
    // The classic camera: 39.3 degrees frames the 2 m opening from 2.9 m in front of it.
    b.addCamera("front", glm::vec3(0.f, 1.f, 3.9f), glm::vec3(0.f, 1.f, 0.f), glm::radians(39.3f), 0.1f,
                20.f);
    return b;
}

SceneBuilder cornellBox() { return cornellBoxNamed("cornell_box", nullptr); }

// The box with its point light sweeping under the ceiling, left to right, dipping at the middle
// (animation light_sweep, 0..2 s): a light that moves while the geometry stands.
SceneBuilder cornellMovingLight() {
    int lamp = -1;
    SceneBuilder b = cornellBoxNamed("cornell_moving_light", &lamp);
    b.addTranslationAnimation("light_sweep", lamp, {0.f, 1.f, 2.f},
                              {glm::vec3(-0.55f, 1.75f, -0.4f), glm::vec3(0.f, 1.6f, 0.2f), glm::vec3(0.55f, 1.75f, -0.4f)});
    return b;
}

// The box with its short box sliding across the floor, right to left in front of the tall one
// (animation box_slide, 0..2 s): an object that moves while the light stands, so contact
// shadows, occlusion and the colour bleeding onto it move with it.
SceneBuilder cornellMovingBox() {
    int box = -1;
    SceneBuilder b = cornellBoxNamed("cornell_moving_box", nullptr, &box);
    b.addTranslationAnimation("box_slide", box, {0.f, 2.f}, {glm::vec3(0.35f, 0.3f, 0.35f), glm::vec3(-0.3f, 0.3f, 0.55f)});
    return b;
}

SceneBuilder courtyard() {
    SceneBuilder b("default");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int wall = b.addMaterial("wall", kWallBeige);
    const int terracotta = b.addMaterial("terracotta", glm::vec3(0.7f, 0.35f, 0.2f));
    const int teal = b.addMaterial("teal", glm::vec3(0.2f, 0.5f, 0.5f));
    const int wood = b.addMaterial("wood", glm::vec3(0.55f, 0.4f, 0.25f));
    const int glow = b.addMaterial("glow", glm::vec3(0.8f), 6.f * glm::vec3(1.f, 0.55f, 0.2f));
    b.addPlane("floor", glm::vec3(0.f), glm::vec2(10.f, 10.f), floor);
    b.addBox("back_wall", glm::vec3(-5.f, 0.f, -5.f), glm::vec3(5.f, 3.f, -4.7f), wall);
    b.addBox("left_wall", glm::vec3(-5.f, 0.f, -4.7f), glm::vec3(-4.7f, 3.f, 1.f), wall);
    // An arch: two pillars and a lintel, for occlusion under the lintel and in the pillar corners.
    b.addBox("arch_pillar_left", glm::vec3(-2.2f, 0.f, -2.4f), glm::vec3(-1.8f, 2.f, -2.f), terracotta);
    b.addBox("arch_pillar_right", glm::vec3(0.2f, 0.f, -2.4f), glm::vec3(0.6f, 2.f, -2.f), terracotta);
    b.addBox("arch_lintel", glm::vec3(-2.3f, 2.f, -2.5f), glm::vec3(0.7f, 2.4f, -1.9f), terracotta);
    // A table: thin top on four legs, contact shadows and occlusion underneath.
    b.addBox("table_top", glm::vec3(-2.f, 0.75f, 0.2f), glm::vec3(-0.6f, 0.8f, 1.2f), wood);
    for (int i = 0; i < 4; ++i) {
        const float x = i % 2 ? -0.7f : -1.95f, z = i / 2 ? 1.1f : 0.25f;
        b.addBox("table_leg_" + std::to_string(i), glm::vec3(x, 0.f, z - 0.05f),
                 glm::vec3(x + 0.05f, 0.75f, z), wood);
    }
    b.addTransformedBox("crate_large", boxAt(glm::vec3(2.5f, 0.5f, 1.2f), glm::vec3(1.f), 30.f), teal);
    b.addTransformedBox("crate_small", boxAt(glm::vec3(2.45f, 1.25f, 1.15f), glm::vec3(0.5f), -10.f), teal);
    b.addBox("pillar", glm::vec3(-3.6f, 0.f, 1.8f), glm::vec3(-3.1f, 2.6f, 2.3f), wall);
    b.addBox("bench", glm::vec3(1.5f, 0.f, -4.7f), glm::vec3(4.f, 0.45f, -4.2f), wood);
    // A glowing panel on the back wall, 1 cm in front of it, facing +Z.
    b.addQuad("glow_panel", glm::vec3(2.f, 1.2f, -4.69f), glm::vec3(1.5f, 0.f, 0.f),
              glm::vec3(0.f, 0.6f, 0.f), glow);
    // A post just right of the view, 0.1 m from visible floor: it darkens the floor beside the
    // crates, which only a world-space method sees.
    offscreenBox(b, "post", glm::vec3(3.45f, 0.f, 0.35f), glm::vec3(3.75f, 2.4f, 0.65f), terracotta);
    addSun(b, 3.f);
    b.addPointLight("lamp", glm::vec3(-1.3f, 1.6f, 0.7f), glm::vec3(1.f, 0.8f, 0.55f), 3.f);
    b.addCamera("main", glm::vec3(4.f, 2.8f, 5.2f), glm::vec3(-0.8f, 0.8f, -1.5f), glm::radians(50.f), 0.1f,
                60.f);
    return b;
}

// All in-view directions point down (pitch 32 > half fov 25), so nothing above the eye is visible:
// the slab at 0.56-0.66 m (eye at 0.5 m) covers visible floor 1.2 m ahead of the eye and extends 3 m
// behind it.
SceneBuilder offscreenOverhang() {
    SceneBuilder b("offscreen_overhang");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("occluder", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addPlane("floor", glm::vec3(0.f, 0.f, 0.f), glm::vec2(12.f, 12.f), floor);
    b.addBox("box", glm::vec3(0.2f, 0.f, 0.2f), glm::vec3(0.6f, 0.2f, 0.6f), wall);
    offscreenBox(b, "overhang", glm::vec3(-3.f, 0.56f, 0.8f), glm::vec3(3.f, 0.66f, 5.f), blue);
    addSun(b);
    const glm::vec3 eye(0.f, 0.5f, 2.f);
    b.addCamera("view", eye, targetPitchedDown(eye, 32.f), glm::radians(50.f), 0.05f, 50.f);
    return b;
}

// Looking 45 degrees down, every in-view direction has -Z, so the wall at z >= 0.55 behind the eye
// (z = 0.5) is out of view while the floor from z = 0.06 forward is in view.
SceneBuilder offscreenWallBehind() {
    SceneBuilder b("offscreen_wall_behind");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("occluder", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addPlane("floor", glm::vec3(0.f, 0.f, -1.f), glm::vec2(12.f, 12.f), floor);
    b.addBox("box", glm::vec3(0.4f, 0.f, -1.f), glm::vec3(0.8f, 0.4f, -0.6f), wall);
    offscreenBox(b, "wall_behind", glm::vec3(-3.f, 0.f, 0.55f), glm::vec3(3.f, 2.5f, 0.75f), blue);
    addSun(b);
    const glm::vec3 eye(0.f, 1.2f, 0.5f);
    b.addCamera("view", eye, targetPitchedDown(eye, 45.f), glm::radians(50.f), 0.05f, 50.f);
    return b;
}

// At 16:9 the right frustum plane reaches x = 1.24 at the back wall (1.5 m away); the pillar starts at
// x = 1.28. At 1:1 the visible wall ends near x = 0.7.
SceneBuilder offscreenSide() {
    SceneBuilder b("offscreen_side");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("occluder", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addPlane("floor", glm::vec3(0.f, 0.f, 1.f), glm::vec2(10.f, 10.f), floor);
    b.addBox("back_wall", glm::vec3(-4.f, 0.f, -1.7f), glm::vec3(4.f, 3.f, -1.5f), wall);
    offscreenBox(b, "pillar", glm::vec3(1.28f, 0.f, -1.5f), glm::vec3(1.85f, 2.2f, -1.1f), blue);
    addSun(b);
    b.addCamera("view", glm::vec3(0.f, 1.f, 0.f), glm::vec3(0.f, 0.9f, -1.5f), glm::radians(50.f), 0.05f,
                50.f);
    return b;
}

// The blocker (in view) hides the box behind it: rays from the eye to every corner of the hidden box
// pass through the blocker. The wall behind is visible above about 0.87 m, the floor beside the blocker.
SceneBuilder offscreenHidden() {
    SceneBuilder b("offscreen_hidden");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("occluder", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    const int blocker = b.addMaterial("blocker", glm::vec3(0.6f, 0.3f, 0.25f));
    b.addPlane("floor", glm::vec3(0.f, 0.f, 1.f), glm::vec2(10.f, 10.f), floor);
    b.addBox("back_wall", glm::vec3(-3.f, 0.f, -1.f), glm::vec3(3.f, 2.5f, -0.8f), wall);
    b.addBox("blocker", glm::vec3(-0.8f, 0.f, 0.6f), glm::vec3(0.8f, 1.f, 0.8f), blocker);
    offscreenBox(b, "hidden_box", glm::vec3(-0.5f, 0.f, -0.7f), glm::vec3(0.5f, 0.6f, -0.2f), blue);
    addSun(b);
    b.addCamera("view", glm::vec3(0.f, 1.2f, 3.f), glm::vec3(0.f, 0.7f, -0.8f), glm::radians(45.f), 0.05f,
                50.f);
    return b;
}

// A 1 cm shelf at eye height and a 1 cm fin in the vertical plane through the eye: both project to
// (sub-)pixel lines, yet they occlude the wall and floor around them.
SceneBuilder offscreenThin() {
    SceneBuilder b("offscreen_thin");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("occluder", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addPlane("floor", glm::vec3(0.f, 0.f, 1.f), glm::vec2(10.f, 10.f), floor);
    b.addBox("back_wall", glm::vec3(-3.f, 0.f, -1.2f), glm::vec3(3.f, 3.f, -1.f), wall);
    offscreenBox(b, "thin_shelf", glm::vec3(-1.2f, 0.995f, -1.f), glm::vec3(1.2f, 1.005f, -0.4f), blue);
    offscreenBox(b, "thin_fin", glm::vec3(-0.005f, 0.f, -1.f), glm::vec3(0.005f, 0.99f, -0.4f), blue);
    addSun(b);
    b.addCamera("view", glm::vec3(0.f, 1.f, 3.f), glm::vec3(0.f, 1.f, -1.f), glm::radians(50.f), 0.05f, 50.f);
    return b;
}

// Off-screen light, for GI: in each, the light that reaches the visible surfaces after one bounce
// leaves a surface the camera cannot see. The sources are flagged off-screen, so the GI ROI is
// where removing them changes the reference's indirect light.

// offscreen_wall_behind's view and wall, the wall orange and sunlit on the face toward the view:
// the sun travels toward +Z, so the floor ahead is lit too and the wall bounces onto it.
SceneBuilder offscreenGiWall() {
    SceneBuilder b("offscreen_gi_wall");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int orange = b.addMaterial("sunlit_wall", glm::vec3(0.85f, 0.45f, 0.15f));
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addPlane("floor", glm::vec3(0.f, 0.f, -1.f), glm::vec2(12.f, 12.f), floor);
    b.addBox("box", glm::vec3(0.4f, 0.f, -1.f), glm::vec3(0.8f, 0.4f, -0.6f), wall);
    offscreenBox(b, "sunlit_wall", glm::vec3(-3.f, 0.f, 0.55f), glm::vec3(3.f, 2.5f, 0.75f), orange);
    b.addDirectionalLight("sun", glm::normalize(glm::vec3(0.3f, -0.8f, 0.6f)), glm::vec3(1.f, 0.96f, 0.9f),
                          3.f);
    const glm::vec3 eye(0.f, 1.2f, 0.5f);
    b.addCamera("view", eye, targetPitchedDown(eye, 45.f), glm::radians(50.f), 0.05f, 50.f);
    return b;
}

// offscreen_overhang's view under a slab whose underside, 8 cm above the eye and out of view, is
// an emitter facing down: every visible floor point under it is lit only through GI.
SceneBuilder offscreenGiEmitter() {
    SceneBuilder b("offscreen_gi_emitter");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int blue = b.addMaterial("slab", kOccluderBlue);
    const int wall = b.addMaterial("wall", kWallBeige);
    const int panel = b.addMaterial("panel", glm::vec3(0.8f), 1.5f * glm::vec3(1.f, 0.9f, 0.75f));
    b.addPlane("floor", glm::vec3(0.f, 0.f, 0.f), glm::vec2(12.f, 12.f), floor);
    b.addBox("box", glm::vec3(0.2f, 0.f, 0.2f), glm::vec3(0.6f, 0.2f, 0.6f), wall);
    offscreenBox(b, "slab", glm::vec3(-3.f, 0.59f, 0.8f), glm::vec3(3.f, 0.69f, 5.f), blue);
    // cross(+X, +Z) = -Y: the panel faces the floor, 1 cm under the slab.
    const int emitter =
        b.addQuad("offscreen_emitter", glm::vec3(-1.5f, 0.58f, 0.9f), glm::vec3(3.f, 0.f, 0.f),
                  glm::vec3(0.f, 0.f, 3.f), panel);
    b.markOffscreen(emitter);
    addSun(b, 1.f);
    const glm::vec3 eye(0.f, 0.5f, 2.f);
    b.addCamera("view", eye, targetPitchedDown(eye, 32.f), glm::radians(50.f), 0.05f, 50.f);
    return b;
}

// Looking 30 degrees up (half fov 25), every in-view direction rises, so the red, sunlit floor
// under the eye (0.3 m) is out of view; it bounces red onto the white wall ahead.
SceneBuilder offscreenGiFloor() {
    SceneBuilder b("offscreen_gi_floor");
    const int red = b.addMaterial("red_floor", glm::vec3(0.8f, 0.1f, 0.05f));
    const int white = b.addMaterial("wall", kWhite);
    const int floorNode = b.addPlane("offscreen_floor", glm::vec3(0.f, 0.f, 1.f), glm::vec2(10.f, 8.f), red);
    b.markOffscreen(floorNode);
    b.addBox("back_wall", glm::vec3(-4.f, 0.f, -1.2f), glm::vec3(4.f, 3.f, -1.f), white);
    b.addDirectionalLight("sun", glm::normalize(glm::vec3(0.2f, -1.f, -0.4f)), glm::vec3(1.f, 0.96f, 0.9f),
                          3.f);
    const glm::vec3 eye(0.f, 0.3f, 1.f);
    const float up = glm::radians(30.f);
    b.addCamera("view", eye, eye + 2.f * glm::vec3(0.f, std::sin(up), -std::cos(up)), glm::radians(50.f), 0.05f,
                50.f);
    return b;
}

// Closed forms: AO = 1 everywhere (nothing above the plane); a sun straight down gives E = 1 lux.
SceneBuilder openPlane() {
    SceneBuilder b("open_plane");
    const int floor = b.addMaterial("floor", kFloorGrey);
    b.addPlane("plane", glm::vec3(0.f), glm::vec2(100.f, 100.f), floor);
    b.addDirectionalLight("sun", glm::vec3(0.f, -1.f, 0.f), glm::vec3(1.f), 1.f);
    b.addCamera("view", glm::vec3(0.f, 4.f, 4.f), glm::vec3(0.f), glm::radians(45.f), 0.05f, 200.f);
    return b;
}

// Closed form: a floor point at distance d from the (effectively infinite) wall.
SceneBuilder wallBase() {
    SceneBuilder b("wall_base");
    const int floor = b.addMaterial("floor", kFloorGrey);
    const int wall = b.addMaterial("wall", kWallBeige);
    b.addQuad("floor", glm::vec3(-20.f, 0.f, 0.f), glm::vec3(0.f, 0.f, 20.f), glm::vec3(40.f, 0.f, 0.f),
              floor);
    b.addQuad("wall", glm::vec3(-20.f, 0.f, 0.f), glm::vec3(40.f, 0.f, 0.f), glm::vec3(0.f, 20.f, 0.f), wall);
    b.addDirectionalLight("sun", glm::normalize(glm::vec3(0.3f, -1.f, -0.5f)), glm::vec3(1.f), 1.f);
    b.addCamera("view", glm::vec3(0.f, 2.f, 6.f), glm::vec3(0.f, 0.5f, 0.f), glm::radians(50.f), 0.05f,
                200.f);
    return b;
}

const std::vector<std::pair<std::string, std::function<SceneBuilder()>>>& registry() {
    static const std::vector<std::pair<std::string, std::function<SceneBuilder()>>> scenes = {
        {"cornell_box", cornellBox},
        {"cornell_moving_box", cornellMovingBox},
        {"cornell_moving_light", cornellMovingLight},
        {"default", courtyard},
        {"offscreen_overhang", offscreenOverhang},
        {"offscreen_wall_behind", offscreenWallBehind},
        {"offscreen_side", offscreenSide},
        {"offscreen_hidden", offscreenHidden},
        {"offscreen_thin", offscreenThin},
        {"offscreen_gi_wall", offscreenGiWall},
        {"offscreen_gi_emitter", offscreenGiEmitter},
        {"offscreen_gi_floor", offscreenGiFloor},
        {"open_plane", openPlane},
        {"wall_base", wallBase},
    };
    return scenes;
}

}  // namespace

std::vector<std::string> projectSceneNames() {
    std::vector<std::string> names;
    for (const auto& entry : registry()) names.push_back(entry.first);
    return names;
}

SceneBuilder makeProjectScene(const std::string& name) {
    for (const auto& entry : registry())
        if (entry.first == name) return entry.second();
    std::string known;
    for (const auto& entry : registry()) known += (known.empty() ? "" : ", ") + entry.first;
    throw UsageError("unknown project scene '" + name + "'; known: " + known);
}

}  // namespace vct
