// A glTF file's own camera animations as camera paths.
//
// At load time (sceneFromModel) every animation whose translation, rotation or scale channels
// move a perspective camera's node, or an ancestor of it, is evaluated exactly as glTF 2.0
// defines it (LINEAR with shortest-path slerp for rotations, STEP, CUBICSPLINE Hermite with
// tangents scaled by the key interval), composed through the camera's node chain and
// sampled into Scene::cameraAnimations: every key time of those channels plus 15 evenly
// spaced points inside each interval between consecutive ones. The path made of them is
// linear between those dense exact samples, so it passes through every glTF key and strays
// from the exact motion by at most the chord of a sixteenth of a key interval.
//
// Animations that move no camera are neither read nor checked (files that loaded before still
// load); "weights" channels and skins are ignored. A malformed sampler of an animation that
// moves a camera (times not strictly increasing, an accessor out of range, counts that do not
// match, non-finite values, an unknown interpolation) is a SceneError naming the file, the
// animation, the channel and the sampler.
#pragma once

#include "scene/camera_path.h"
#include "scene/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vct {

struct CameraAnimationInfo {
    std::string name;        // as cameraAnimationPath accepts it
    int animation = -1;      // index of the animation in the glTF file
    std::string cameraName;  // the camera it moves
    double start = 0.0;      // seconds, first and last sample
    double end = 0.0;
    size_t keyCount = 0;     // samples in the path
};

// One entry per Scene::cameraAnimations track, in that order.
std::vector<CameraAnimationInfo> listCameraAnimations(const Scene& scene);

// "0 'orbit' (camera 'cam', 0..4 s, 65 keys), 1 ..." or "(none)", for `vct info` and messages.
std::string describeCameraAnimations(const Scene& scene);

// Track `nameOrIndex` (an animation name, the first track of that name, or an index into
// Scene::cameraAnimations) as a linear CameraPath whose source is
// "<scene path>: animation '<name>'". Throws UsageError listing the scene's camera animations
// when there is no such track.
CameraPath cameraAnimationPath(const Scene& scene, const std::string& nameOrIndex);

// Lights moved by glTF animations (rigid node animation of a light's node or its ancestors),
// sampled at load time as camera tracks are (Scene::lightAnimations).
// "0 'sweep' (light 'lamp', 0..2 s, 33 keys)" or "(none)".
std::string describeLightAnimations(const Scene& scene);
// True when `animation` (a glTF animation's name) moves a light of the scene.
bool animationMovesLights(const Scene& scene, const std::string& animation);
// Places every light that `animation` moves where it is at time t (linear between the dense
// samples; held at the ends). Returns how many lights it moved; the others keep their pose.
int poseLights(Scene& scene, const std::string& animation, double t);

// Mesh nodes moved rigidly by glTF animations (a node's own translation, rotation or scale, or
// an ancestor's), sampled at load time as camera tracks are (Scene::meshAnimations). Skins and
// morph targets are not posed (Scene::geometryAnimations names the animations that use them).
// "0 'slide' (node 3 'box', 24 vertices, 0..2 s, 33 keys)" or "(none)".
std::string describeMeshAnimations(const Scene& scene);
// True when `animation` moves a mesh node of the scene.
bool animationMovesGeometry(const Scene& scene, const std::string& animation);
// Places the vertices (positions and normals) of every mesh node that `animation` moves where
// they are at time t, computed from the node's rest pose: exact at the dense samples, the
// node's translation, rotation and scale interpolated between them; held at the ends. Returns
// how many nodes' vertices changed. Scene::bounds is left as it is (animationBounds).
int poseMeshes(Scene& scene, const std::string& animation, double t);
// Scene::bounds grown by every sampled pose of the nodes `animation` moves (their rest box's
// corners carried along): bounds a sequence can keep for all its frames, so a voxel lattice
// fixed to the scene does not move with the object.
Bounds3 animationBounds(const Scene& scene, const std::string& animation);

// What posing a scene at one instant of an animation changed.
struct AnimationPose {
    int lightsMoved = 0;  // lights placed by the animation (poseLights)
    int meshesMoved = 0;  // mesh nodes whose vertices changed (poseMeshes)
};
// poseLights and poseMeshes at time t.
AnimationPose poseAnimation(Scene& scene, const std::string& animation, double t);

// A path's "animation" must move a camera, a light or a mesh node of the scene rigidly;
// otherwise a UsageError naming the scene's animations, or what the animation deforms (a skin,
// morph weights) or where it is malformed. Every sequence (render, compare, sweep) checks it.
void checkPathAnimation(const CameraPath& path, const Scene& scene);

}  // namespace vct
