// glTF animations that move a camera: each sampler read and checked, evaluated as glTF 2.0
// defines it, composed through the camera's node chain and sampled densely into
// Scene::cameraAnimations; and those tracks listed and turned into camera paths.
#include "scene/gltf_animation.h"

#include "scene/camera.h"

#include "core/errors.h"  // UsageError, header-only: the scene layer's name lookups use it as camera.cpp does
#include "scene/gltf_detail.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace vct {

namespace {

// Key i of `keys` (times strictly increasing) with keys[i].time <= t < keys[i + 1].time, for t
// strictly inside the keys' span: the interval a pose between two samples comes from.
template <class Key>
size_t keyIntervalAt(const std::vector<Key>& keys, double t) {
    return size_t(std::upper_bound(keys.begin(), keys.end(), t, [](double x, const Key& key) { return x < key.time; }) -
                  keys.begin()) - 1;
}

}  // namespace

namespace gltf_detail {

namespace {

// The name tracks and messages give animation `index`: its own, or "animation<index>".
std::string animationName(const tinygltf::Animation& anim, size_t index) {
    return anim.name.empty() ? "animation" + std::to_string(index) : anim.name;
}

// Points sampled inside each interval between consecutive key times, so the path has 16
// linear segments per interval: a camera turning 90 degrees in one interval then strays from
// the exact arc by 1 - cos(90 / 32 degrees), about 0.12% of its distance to the pivot.
constexpr int kSamplesInsideInterval = 15;

enum class Interpolation { Linear, Step, CubicSpline };
enum class TrsPath { Translation, Rotation, Scale };

// A translation or scale (x, y, z, unused) or a rotation quaternion (x, y, z, w), glTF's order.
using Value4 = std::array<double, 4>;

// One sampler, read and checked.
struct Sampler {
    Interpolation interpolation = Interpolation::Linear;
    int components = 3;          // 3 (translation, scale) or 4 (rotation)
    std::vector<double> times;   // seconds, strictly increasing, at least one
    std::vector<double> values;  // per key: the value, or (in-tangent, value, out-tangent) for CUBICSPLINE
};

// A channel that moves a node of a camera's chain, with its sampler.
struct TrsChannel {
    int node = -1;
    TrsPath path = TrsPath::Translation;
    Sampler sampler;
};

std::string num(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

// False for "weights" and for paths of extensions: those never move a camera.
bool parseTrsPath(const std::string& name, TrsPath* path) {
    if (name == "translation") *path = TrsPath::Translation;
    else if (name == "rotation") *path = TrsPath::Rotation;
    else if (name == "scale") *path = TrsPath::Scale;
    else return false;
    return true;
}

bool parseInterpolation(const std::string& name, Interpolation* out) {
    if (name == "LINEAR") *out = Interpolation::Linear;
    else if (name == "STEP") *out = Interpolation::Step;
    else if (name == "CUBICSPLINE") *out = Interpolation::CubicSpline;
    else return false;
    return true;
}

// glTF asks for strictly increasing, finite key times; at least one is needed to have a value.
void checkTimes(const LoadContext& load, const std::vector<double>& times, const std::string& where) {
    if (times.empty()) load.fail(where + ": input has no keys");
    for (size_t i = 0; i < times.size(); ++i) {
        if (!std::isfinite(times[i])) load.fail(where + ": input time " + std::to_string(i) + " is not finite");
        if (i > 0 && !(times[i] > times[i - 1]))
            load.fail(where + ": input times not strictly increasing: key " + std::to_string(i) + " (" +
                      num(times[i]) + " s) after key " + std::to_string(i - 1) + " (" + num(times[i - 1]) + " s)");
    }
}

// Sampler `index` of `anim`, read for values of `components` numbers; `where` names the
// animation and the channel that uses it.
Sampler readSampler(const LoadContext& load, const tinygltf::Animation& anim, int index, int components,
                    const std::string& where) {
    if (index < 0 || index >= int(anim.samplers.size()))
        load.fail(where + ": " + outOfRange("sampler", index, anim.samplers.size()));
    const tinygltf::AnimationSampler& s = anim.samplers[size_t(index)];
    const std::string at = where + ", sampler " + std::to_string(index);
    Sampler out;
    out.components = components;
    if (!parseInterpolation(s.interpolation, &out.interpolation))
        load.fail(at + ": unknown interpolation '" + s.interpolation + "'");
    size_t keyCount = 0, valueCount = 0;
    out.times = readAccessor(load, s.input, at + " input", 1, &keyCount);
    checkTimes(load, out.times, at);
    out.values = readAccessor(load, s.output, at + " output", components, &valueCount);
    const size_t perKey = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (valueCount != perKey * keyCount)
        load.fail(at + ": output has " + std::to_string(valueCount) + " elements for " + std::to_string(keyCount) +
                  " key times, expected " + std::to_string(perKey * keyCount));
    for (size_t i = 0; i < out.values.size(); ++i)
        if (!std::isfinite(out.values[i]))
            load.fail(at + ": output element " + std::to_string(i / size_t(components)) + " is not finite");
    return out;
}

// Element `part` of key `key`: 0 in-tangent, 1 value, 2 out-tangent for CUBICSPLINE; the
// value (part ignored) otherwise.
Value4 element(const Sampler& s, size_t key, int part) {
    const bool cubic = s.interpolation == Interpolation::CubicSpline;
    const size_t first = (cubic ? 3 * key + size_t(part) : key) * size_t(s.components);
    Value4 v{0.0, 0.0, 0.0, 0.0};
    for (int c = 0; c < s.components; ++c) v[size_t(c)] = s.values[first + size_t(c)];
    return v;
}

Value4 keyValue(const Sampler& s, size_t key) { return element(s, key, 1); }

Value4 normalized(Value4 q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q) x /= n;  // a zero quaternion becomes NaN, which the camera check reports
    return q;
}

Value4 lerp(const Value4& a, const Value4& b, double u) {
    Value4 v;
    for (size_t c = 0; c < 4; ++c) v[c] = a[c] + u * (b[c] - a[c]);
    return v;
}

// glTF's LINEAR rotation: slerp of the normalized quaternions along the shorter arc (q and
// -q are the same rotation, so the one nearer `a` is used).
Value4 slerpShortest(Value4 a, Value4 b, double u) {
    a = normalized(a);
    b = normalized(b);
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    if (d < 0.0) {
        for (double& x : b) x = -x;
        d = -d;
    }
    // Nearly equal rotations: sin(theta) underflows the weights; the chord is the arc there.
    if (d > 0.9999999) return normalized(lerp(a, b, u));
    const double theta = std::acos(std::min(d, 1.0));
    const double wa = std::sin((1.0 - u) * theta) / std::sin(theta), wb = std::sin(u * theta) / std::sin(theta);
    Value4 v;
    for (size_t c = 0; c < 4; ++c) v[c] = wa * a[c] + wb * b[c];
    return v;
}

// glTF 2.0 appendix C, CUBICSPLINE: the cubic Hermite through v0 and v1 whose tangents, the
// key's out-tangent b0 and the next key's in-tangent a1, are scaled by the interval td.
Value4 hermite(const Value4& v0, const Value4& b0, const Value4& v1, const Value4& a1, double td, double u) {
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    Value4 v;
    for (size_t c = 0; c < 4; ++c) v[c] = h00 * v0[c] + h10 * td * b0[c] + h01 * v1[c] + h11 * td * a1[c];
    return v;
}

// The sampler's value at time t; before the first key and after the last, that key's value.
Value4 sample(const Sampler& s, bool rotation, double t) {
    const size_t n = s.times.size();
    if (t <= s.times.front()) return keyValue(s, 0);
    if (t >= s.times.back()) return keyValue(s, n - 1);
    const size_t k = size_t(std::upper_bound(s.times.begin(), s.times.end(), t) - s.times.begin()) - 1;
    const double td = s.times[k + 1] - s.times[k];
    const double u = (t - s.times[k]) / td;
    switch (s.interpolation) {
        case Interpolation::Step: return keyValue(s, k);
        case Interpolation::Linear:
            return rotation ? slerpShortest(keyValue(s, k), keyValue(s, k + 1), u)
                            : lerp(keyValue(s, k), keyValue(s, k + 1), u);
        case Interpolation::CubicSpline: {
            const Value4 v = hermite(keyValue(s, k), element(s, k, 2), keyValue(s, k + 1), element(s, k + 1, 0), td, u);
            return rotation ? normalized(v) : v;
        }
    }
    return keyValue(s, k);
}

// The animation's channels that move a node of `chain`, each with its sampler read and
// checked; the others (weights, other nodes, extensions' paths) are skipped unread.
std::vector<TrsChannel> channelsMoving(const LoadContext& load, int animIndex, const std::vector<int>& chain) {
    const tinygltf::Animation& anim = load.model.animations[size_t(animIndex)];
    const std::string animWhere = label("animation", animIndex, anim.name);
    std::vector<TrsChannel> out;
    for (size_t c = 0; c < anim.channels.size(); ++c) {
        const tinygltf::AnimationChannel& ch = anim.channels[c];
        TrsPath path = TrsPath::Translation;
        const bool inChain = std::find(chain.begin(), chain.end(), ch.target_node) != chain.end();
        if (!parseTrsPath(ch.target_path, &path) || !inChain) continue;
        const tinygltf::Node& node = load.model.nodes[size_t(ch.target_node)];
        const std::string where = animWhere + ", channel " + std::to_string(c) + " (" +
                                  label("node", ch.target_node, node.name) + " " + ch.target_path + ")";
        if (node.matrix.size() == 16)
            load.fail(where + ": the node has a matrix; glTF animates only nodes given as translation/rotation/scale");
        for (const TrsChannel& other : out)
            if (other.node == ch.target_node && other.path == path)
                load.fail(where + ": a second channel for the same node and path");
        const int components = path == TrsPath::Rotation ? 4 : 3;
        out.push_back({ch.target_node, path, readSampler(load, anim, ch.sampler, components, where)});
    }
    return out;
}

// Node `index`'s parentFromNode at time t: its own TRS (or matrix) with the channels that
// target it substituted, in double precision.
glm::dmat4 localAt(const LoadContext& load, int index, const std::vector<TrsChannel>& channels, double t) {
    const tinygltf::Node& node = load.model.nodes[size_t(index)];
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // never animated (channelsMoving)
    Value4 tr{0.0, 0.0, 0.0, 0.0}, r{0.0, 0.0, 0.0, 1.0}, s{1.0, 1.0, 1.0, 0.0};
    if (node.translation.size() == 3) std::copy(node.translation.begin(), node.translation.end(), tr.begin());
    if (node.rotation.size() == 4) std::copy(node.rotation.begin(), node.rotation.end(), r.begin());
    if (node.scale.size() == 3) std::copy(node.scale.begin(), node.scale.end(), s.begin());
    for (const TrsChannel& c : channels) {
        if (c.node != index) continue;
        const Value4 v = sample(c.sampler, c.path == TrsPath::Rotation, t);
        (c.path == TrsPath::Translation ? tr : c.path == TrsPath::Rotation ? r : s) = v;
    }
    const Value4 q = normalized(r);
    const glm::dquat rotation(q[3], q[0], q[1], q[2]);  // glm is (w, x, y, z)
    return glm::translate(glm::dmat4(1.0), glm::dvec3(tr[0], tr[1], tr[2])) * glm::mat4_cast(rotation) *
           glm::scale(glm::dmat4(1.0), glm::dvec3(s[0], s[1], s[2]));
}

glm::dmat4 worldAt(const LoadContext& load, const std::vector<int>& chain, const std::vector<TrsChannel>& channels,
                   double t) {
    glm::dmat4 worldFromNode(1.0);
    for (int index : chain) worldFromNode = worldFromNode * localAt(load, index, channels, t);
    return worldFromNode;
}

// The camera under `worldFromCamera`, as addCamera places a static one: eye at the node's
// origin, looking down its -Z with its +Y, re-orthogonalized, as up.
CameraAnimationKey cameraKey(const LoadContext& load, const glm::dmat4& worldFromCamera, double t, float yfov,
                             const std::string& where) {
    const glm::dmat3 linear(worldFromCamera);
    const glm::dvec3 eye(worldFromCamera[3]);
    glm::dvec3 forward = linear * glm::dvec3(0.0, 0.0, -1.0);
    glm::dvec3 up = linear * glm::dvec3(0.0, 1.0, 0.0);
    const std::string at = where + " at " + num(t) + " s";
    if (!finite3(glm::vec3(eye)) || !finite3(glm::vec3(forward)) || !finite3(glm::vec3(up)))
        load.fail(at + ": node transform is not finite");
    if (!(glm::length(forward) > 0.0)) load.fail(at + ": node transform collapses the view direction");
    forward = glm::normalize(forward);
    up -= glm::dot(up, forward) * forward;
    if (!(glm::length(up) > 0.0)) load.fail(at + ": node transform collapses the up direction");
    CameraAnimationKey key;
    key.time = t;
    key.eye = glm::vec3(eye);
    key.target = glm::vec3(eye + forward);
    key.up = glm::vec3(glm::normalize(up));
    key.yfov = yfov;
    return key;
}

// Every key time of the channels, and kSamplesInsideInterval evenly spaced times inside each
// interval between consecutive ones.
std::vector<double> sampleTimes(const std::vector<TrsChannel>& channels) {
    std::vector<double> keys;
    for (const TrsChannel& c : channels) keys.insert(keys.end(), c.sampler.times.begin(), c.sampler.times.end());
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<double> out;
    for (size_t i = 0; i < keys.size(); ++i) {
        out.push_back(keys[i]);
        if (i + 1 == keys.size()) break;
        for (int j = 1; j <= kSamplesInsideInterval; ++j) {
            const double t = keys[i] + (keys[i + 1] - keys[i]) * j / (kSamplesInsideInterval + 1);
            if (t > out.back() && t < keys[i + 1]) out.push_back(t);  // keys a few ulps apart keep times increasing
        }
    }
    return out;
}

CameraAnimationTrack sampleTrack(const LoadContext& load, int animIndex, const LoadContext::PlacedCamera& placed,
                                 const std::vector<TrsChannel>& channels) {
    const tinygltf::Animation& anim = load.model.animations[size_t(animIndex)];
    const Camera& camera = load.scene.cameras[placed.sceneCamera];
    CameraAnimationTrack track;
    track.name = animationName(anim, size_t(animIndex));
    track.animation = animIndex;
    track.cameraName = camera.name;
    const std::string where = label("animation", animIndex, anim.name) + " (camera '" + camera.name + "')";
    for (double t : sampleTimes(channels))
        track.keys.push_back(cameraKey(load, worldAt(load, placed.nodeChain, channels, t), t, camera.yfov, where));
    return track;
}

LightAnimationTrack sampleLightTrack(const LoadContext& load, int animIndex, const LoadContext::PlacedLight& placed,
                                     const std::vector<TrsChannel>& channels) {
    const tinygltf::Animation& anim = load.model.animations[size_t(animIndex)];
    const Light& light = load.scene.lights[placed.sceneLight];
    LightAnimationTrack track;
    track.name = animationName(anim, size_t(animIndex));
    track.animation = animIndex;
    track.light = placed.sceneLight;
    const std::string where = label("animation", animIndex, anim.name) + " (light '" + light.name + "')";
    for (double t : sampleTimes(channels)) {
        // As addLight places a static light: at the node's origin, travelling down its -Z.
        const glm::dmat4 world = worldAt(load, placed.nodeChain, channels, t);
        const glm::dvec3 position(world[3]);
        const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
        if (!finite3(glm::vec3(position)) || !finite3(glm::vec3(direction)) || !(glm::length(direction) > 0.0))
            load.fail(where + " at " + num(t) + " s: node transform is not finite or collapses the light direction");
        track.keys.push_back({t, glm::vec3(position), glm::vec3(glm::normalize(direction))});
    }
    return track;
}

MeshAnimationTrack sampleMeshTrack(const LoadContext& load, int animIndex, const LoadContext::PlacedMesh& placed,
                                   const std::vector<TrsChannel>& channels) {
    const tinygltf::Animation& anim = load.model.animations[size_t(animIndex)];
    MeshAnimationTrack track;
    track.name = animationName(anim, size_t(animIndex));
    track.animation = animIndex;
    track.nodeName = label("node", placed.node, load.model.nodes[size_t(placed.node)].name);
    const std::string where = label("animation", animIndex, anim.name) + " (" + track.nodeName + ")";
    // The rest pose in double precision, as the loader composed it (no channel substituted).
    const glm::dmat4 worldAtRest = worldAt(load, placed.nodeChain, {}, 0.0);
    if (!(std::abs(glm::determinant(glm::dmat3(worldAtRest))) > 1e-30))
        load.fail(where + ": the node's transform as loaded is singular, so its vertices cannot be moved from it");
    track.nodeFromWorldAtRest = glm::mat4(glm::inverse(worldAtRest));
    track.firstVertex = placed.firstVertex;
    const auto first = load.scene.positions.begin() + placed.firstVertex;
    track.restPositions.assign(first, first + placed.vertexCount);
    const auto firstNormal = load.scene.normals.begin() + placed.firstVertex;
    track.restNormals.assign(firstNormal, firstNormal + placed.vertexCount);
    for (double t : sampleTimes(channels)) {
        const glm::mat4 world(worldAt(load, placed.nodeChain, channels, t));
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(world[c].x) || !std::isfinite(world[c].y) || !std::isfinite(world[c].z) ||
                !std::isfinite(world[c].w))
                load.fail(where + " at " + num(t) + " s: node transform is not finite in single precision");
        track.keys.push_back({t, world});
    }
    return track;
}

}  // namespace

namespace {

// True when node `index` or a node below it carries a mesh (depth-limited against cycles, which
// visitNode has already refused for the nodes of the scene).
bool carriesSkin(const tinygltf::Model& model, int index, size_t depth) {
    if (index < 0 || index >= int(model.nodes.size()) || depth > model.nodes.size()) return false;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    if (node.skin >= 0) return true;
    for (int child : node.children)
        if (carriesSkin(model, child, depth + 1)) return true;
    return false;
}

bool isJoint(const tinygltf::Model& model, int index) {
    for (const tinygltf::Skin& skin : model.skins)
        if (std::find(skin.joints.begin(), skin.joints.end(), index) != skin.joints.end()) return true;
    return false;
}

}  // namespace

void findGeometryAnimations(LoadContext& load) {
    const tinygltf::Model& model = load.model;
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& anim = model.animations[a];
        const std::string name = animationName(anim, a);
        for (const tinygltf::AnimationChannel& ch : anim.channels) {
            if (ch.target_node < 0 || ch.target_node >= int(model.nodes.size())) continue;
            const tinygltf::Node& node = model.nodes[size_t(ch.target_node)];
            const std::string target = label("node", ch.target_node, node.name);
            std::string what;
            if (ch.target_path == "weights") what = "animates the morph target weights of " + target;
            else if (isJoint(model, ch.target_node)) what = "moves " + target + ", a joint of a skin";
            else if (carriesSkin(model, ch.target_node, 0)) what = "moves " + target + ", which carries a skinned mesh";
            if (what.empty()) continue;
            load.scene.geometryAnimations.push_back({name, what});
            break;
        }
    }
}

void addLightAnimations(LoadContext& load) {
    for (size_t a = 0; a < load.model.animations.size(); ++a)
        for (const LoadContext::PlacedLight& placed : load.placedLights) {
            const std::vector<TrsChannel> channels = channelsMoving(load, int(a), placed.nodeChain);
            if (!channels.empty()) load.scene.lightAnimations.push_back(sampleLightTrack(load, int(a), placed, channels));
        }
}

void addMeshAnimations(LoadContext& load) {
    for (size_t a = 0; a < load.model.animations.size(); ++a) {
        // A malformed animation of an object does not stop the file's still renders: it is
        // named instead (Scene::geometryAnimations), and a sequence that plays it is refused.
        std::vector<MeshAnimationTrack> tracks;
        try {
            for (const LoadContext::PlacedMesh& placed : load.placedMeshes) {
                const std::vector<TrsChannel> channels = channelsMoving(load, int(a), placed.nodeChain);
                if (!channels.empty()) tracks.push_back(sampleMeshTrack(load, int(a), placed, channels));
            }
        } catch (const SceneError& e) {
            const tinygltf::Animation& anim = load.model.animations[a];
            load.scene.geometryAnimations.push_back(
                {animationName(anim, a),
                 std::string("is malformed where it moves an object (") + e.what() + ")"});
            continue;
        }
        for (MeshAnimationTrack& t : tracks) load.scene.meshAnimations.push_back(std::move(t));
    }
}

void addCameraAnimations(LoadContext& load) {
    for (size_t a = 0; a < load.model.animations.size(); ++a)
        for (const LoadContext::PlacedCamera& placed : load.placedCameras) {
            const std::vector<TrsChannel> channels = channelsMoving(load, int(a), placed.nodeChain);
            if (!channels.empty()) load.scene.cameraAnimations.push_back(sampleTrack(load, int(a), placed, channels));
        }
}

}  // namespace gltf_detail


std::string describeLightAnimations(const Scene& scene) {
    if (scene.lightAnimations.empty()) return "(none)";
    std::ostringstream os;
    for (size_t i = 0; i < scene.lightAnimations.size(); ++i) {
        const LightAnimationTrack& t = scene.lightAnimations[i];
        os << (i ? ", " : "") << i << " '" << t.name << "' (light '" << scene.lights[t.light].name << "', "
           << t.keys.front().time << ".." << t.keys.back().time << " s, " << t.keys.size() << " keys)";
    }
    return os.str();
}

bool animationMovesLights(const Scene& scene, const std::string& animation) {
    for (const LightAnimationTrack& t : scene.lightAnimations)
        if (t.name == animation) return true;
    return false;
}

int poseLights(Scene& scene, const std::string& animation, double t) {
    int moved = 0;
    for (const LightAnimationTrack& track : scene.lightAnimations) {
        if (track.name != animation || track.light >= scene.lights.size()) continue;
        const std::vector<LightAnimationKey>& k = track.keys;
        LightAnimationKey at = k.front();
        if (t >= k.back().time) {
            at = k.back();
        } else if (t > k.front().time) {
            const size_t i = keyIntervalAt(k, t);
            const float u = float((t - k[i].time) / (k[i + 1].time - k[i].time));
            at.position = glm::mix(k[i].position, k[i + 1].position, u);
            const glm::vec3 d = glm::mix(k[i].direction, k[i + 1].direction, u);
            at.direction = glm::length(d) > 0.f ? glm::normalize(d) : k[i].direction;
        }
        scene.lights[track.light].position = at.position;
        scene.lights[track.light].direction = at.direction;
        ++moved;
    }
    return moved;
}

namespace {

// The node's world transform at time t: exact at a sample, its translation, rotation (shortest
// slerp) and scale interpolated between two (a sheared chain loses its shear between samples).
glm::mat4 worldFromNodeAt(const MeshAnimationTrack& track, double t) {
    const std::vector<MeshAnimationKey>& k = track.keys;
    if (t <= k.front().time) return k.front().worldFromNode;
    if (t >= k.back().time) return k.back().worldFromNode;
    const size_t i = keyIntervalAt(k, t);
    if (t == k[i].time) return k[i].worldFromNode;
    const float u = float((t - k[i].time) / (k[i + 1].time - k[i].time));
    glm::vec3 scale[2], translation[2], skew;
    glm::quat rotation[2];
    glm::vec4 perspective;
    for (int j = 0; j < 2; ++j)
        if (!glm::decompose(k[i + size_t(j)].worldFromNode, scale[j], rotation[j], translation[j], skew, perspective))
            return u < 0.5f ? k[i].worldFromNode : k[i + 1].worldFromNode;  // singular: the nearer sample
    return glm::translate(glm::mat4(1.f), glm::mix(translation[0], translation[1], u)) *
           glm::mat4_cast(glm::slerp(rotation[0], rotation[1], u)) *
           glm::scale(glm::mat4(1.f), glm::mix(scale[0], scale[1], u));
}

// The map from the node's vertices as loaded to where they are at time t.
glm::mat4 worldFromRestAt(const MeshAnimationTrack& track, double t) {
    return worldFromNodeAt(track, t) * track.nodeFromWorldAtRest;
}

}  // namespace

bool animationMovesGeometry(const Scene& scene, const std::string& animation) {
    for (const MeshAnimationTrack& t : scene.meshAnimations)
        if (t.name == animation) return true;
    return false;
}

int poseMeshes(Scene& scene, const std::string& animation, double t) {
    int changed = 0;
    for (const MeshAnimationTrack& track : scene.meshAnimations) {
        if (track.name != animation || track.firstVertex + track.restPositions.size() > scene.positions.size()) continue;
        const glm::mat4 m = worldFromRestAt(track, t);
        const glm::mat3 normalFromRest = glm::transpose(glm::inverse(glm::mat3(m)));
        bool moved = false;
        for (size_t v = 0; v < track.restPositions.size(); ++v) {
            const glm::vec3 p = glm::vec3(m * glm::vec4(track.restPositions[v], 1.f));
            glm::vec3 n = normalFromRest * track.restNormals[v];
            n = glm::length(n) > 0.f ? glm::normalize(n) : track.restNormals[v];
            glm::vec3& position = scene.positions[track.firstVertex + v];
            glm::vec3& normal = scene.normals[track.firstVertex + v];
            moved = moved || position != p || normal != n;
            position = p;
            normal = n;
        }
        changed += moved ? 1 : 0;
    }
    return changed;
}

Bounds3 animationBounds(const Scene& scene, const std::string& animation) {
    Bounds3 b = scene.bounds;
    for (const MeshAnimationTrack& track : scene.meshAnimations) {
        if (track.name != animation) continue;
        Bounds3 rest;
        for (const glm::vec3& p : track.restPositions) rest.expand(p);
        for (const MeshAnimationKey& key : track.keys) {
            const glm::mat4 m = key.worldFromNode * track.nodeFromWorldAtRest;
            for (int c = 0; c < 8; ++c) {
                const glm::vec3 corner(c & 1 ? rest.max.x : rest.min.x, c & 2 ? rest.max.y : rest.min.y,
                                       c & 4 ? rest.max.z : rest.min.z);
                b.expand(glm::vec3(m * glm::vec4(corner, 1.f)));
            }
        }
    }
    return b;
}

AnimationPose poseAnimation(Scene& scene, const std::string& animation, double t) {
    AnimationPose pose;
    pose.lightsMoved = poseLights(scene, animation, t);
    pose.meshesMoved = poseMeshes(scene, animation, t);
    return pose;
}

std::string describeMeshAnimations(const Scene& scene) {
    if (scene.meshAnimations.empty()) return "(none)";
    std::ostringstream os;
    for (size_t i = 0; i < scene.meshAnimations.size(); ++i) {
        const MeshAnimationTrack& t = scene.meshAnimations[i];
        os << (i ? ", " : "") << i << " '" << t.name << "' (" << t.nodeName << ", " << t.restPositions.size()
           << " vertices, " << t.keys.front().time << ".." << t.keys.back().time << " s, " << t.keys.size()
           << " keys)";
    }
    return os.str();
}

std::vector<CameraAnimationInfo> listCameraAnimations(const Scene& scene) {
    std::vector<CameraAnimationInfo> out;
    for (const CameraAnimationTrack& track : scene.cameraAnimations)
        out.push_back({track.name, track.animation, track.cameraName, track.keys.front().time,
                       track.keys.back().time, track.keys.size()});
    return out;
}

std::string describeCameraAnimations(const Scene& scene) {
    const std::vector<CameraAnimationInfo> infos = listCameraAnimations(scene);
    if (infos.empty()) return "(none)";
    std::ostringstream os;
    for (size_t i = 0; i < infos.size(); ++i)
        os << (i ? ", " : "") << i << " '" << infos[i].name << "' (camera '" << infos[i].cameraName << "', "
           << infos[i].start << ".." << infos[i].end << " s, " << infos[i].keyCount << " keys)";
    return os.str();
}

CameraPath cameraAnimationPath(const Scene& scene, const std::string& nameOrIndex) {
    const CameraAnimationTrack* found = nullptr;
    for (const CameraAnimationTrack& track : scene.cameraAnimations)
        if (!found && track.name == nameOrIndex) found = &track;
    size_t index = 0;
    if (!found && parseIndex(nameOrIndex, &index) && index < scene.cameraAnimations.size())
        found = &scene.cameraAnimations[index];
    if (!found)
        throw UsageError("no camera animation '" + nameOrIndex + "' in " +
                         (scene.path.empty() ? std::string("the scene") : scene.path) +
                         "; the scene has: " + describeCameraAnimations(scene));
    CameraPath path;
    path.source = (scene.path.empty() ? std::string() : scene.path + ": ") + "animation '" + found->name + "'";
    path.interpolation = PathInterpolation::Linear;  // the keys are dense exact samples (gltf_animation.h)
    for (const CameraAnimationKey& k : found->keys)
        path.keys.push_back({k.time, k.eye, k.target, k.up, glm::degrees(k.yfov)});
    path.animation = found->name;  // the same animation moves the scene's lights along
    return path;
}

void checkPathAnimation(const CameraPath& path, const Scene& scene) {
    if (path.animation.empty()) return;
    for (const auto& [name, what] : scene.geometryAnimations)
        if (name == path.animation)
            throw UsageError(path.source + ": animation '" + name + "' " + what +
                             ": a sequence plays rigid animations of cameras, lights and objects (skins and morph "
                             "targets are not posed)");
    if (animationMovesLights(scene, path.animation) || animationMovesGeometry(scene, path.animation)) return;
    for (const CameraAnimationTrack& t : scene.cameraAnimations)
        if (t.name == path.animation) return;
    throw UsageError(path.source + ": animation '" + path.animation + "' moves no camera, light or object of " +
                     scene.path + " (camera animations: " + describeCameraAnimations(scene) +
                     "; light animations: " + describeLightAnimations(scene) +
                     "; object animations: " + describeMeshAnimations(scene) + ")");
}

}  // namespace vct
