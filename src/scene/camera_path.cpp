#include "scene/camera_path.h"

#include "scene/camera.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace vct {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw std::runtime_error(where + ": " + what);
}

glm::vec3 vec3From(const nlohmann::json& j, const std::string& where) {
    if (!j.is_array() || j.size() != 3 || !std::all_of(j.begin(), j.end(), [](auto& v) { return v.is_number(); }))
        fail(where, "expected 3 finite numbers");
    glm::vec3 v(j[0].get<float>(), j[1].get<float>(), j[2].get<float>());
    if (!finite3(v)) fail(where, "expected 3 finite numbers");
    return v;
}

nlohmann::json vec3Json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Cubic Hermite between p0 (tangent m0) and p1 (tangent m1), tangents per unit of u.
glm::vec3 hermite(const glm::vec3& p0, const glm::vec3& m0, const glm::vec3& p1, const glm::vec3& m1, float u) {
    const float u2 = u * u, u3 = u2 * u;
    return (2.f * u3 - 3.f * u2 + 1.f) * p0 + (u3 - 2.f * u2 + u) * m0 + (-2.f * u3 + 3.f * u2) * p1 +
           (u3 - u2) * m1;
}

// The Catmull-Rom velocity at key i, per second: the chord between its neighbours over their
// time; at an end key, the chord to its one neighbour.
glm::vec3 keyVelocity(const std::vector<CameraKey>& k, size_t i, glm::vec3 CameraKey::*member) {
    const size_t a = i == 0 ? 0 : i - 1, b = std::min(i + 1, k.size() - 1);
    return (k[b].*member - k[a].*member) / float(k[b].time - k[a].time);
}

}  // namespace

CameraPath cameraPathFromJson(const nlohmann::json& doc, const std::string& where) {
    if (!doc.is_object()) fail(where, "expected a JSON object with \"keys\"");
    for (auto it = doc.begin(); it != doc.end(); ++it)
        if (it.key() != "interpolation" && it.key() != "up" && it.key() != "keys" && it.key() != "animation")
            fail(where, "unknown key \"" + it.key() + "\" (expected interpolation, up, animation, keys)");
    CameraPath path;
    path.source = where;
    if (doc.contains("interpolation")) {
        const nlohmann::json& i = doc["interpolation"];
        if (i == "linear") path.interpolation = PathInterpolation::Linear;
        else if (i == "catmull-rom") path.interpolation = PathInterpolation::CatmullRom;
        else fail(where + ": interpolation", "expected \"linear\" or \"catmull-rom\", got " + i.dump());
    }
    if (doc.contains("animation")) {
        if (!doc["animation"].is_string() || doc["animation"].get<std::string>().empty())
            fail(where + ": animation", "expected the name of a glTF animation of the scene");
        path.animation = doc["animation"].get<std::string>();
    }
    glm::vec3 up(0.f, 1.f, 0.f);
    if (doc.contains("up")) up = vec3From(doc["up"], where + ": up");
    if (!doc.contains("keys") || !doc["keys"].is_array() || doc["keys"].empty())
        fail(where + ": keys", "expected a non-empty array of keyframes");
    const nlohmann::json& keys = doc["keys"];
    for (size_t i = 0; i < keys.size(); ++i) {
        const std::string at = where + ": keys[" + std::to_string(i) + "]";
        const nlohmann::json& k = keys[i];
        if (!k.is_object()) fail(at, "expected an object with time, eye, target");
        for (auto it = k.begin(); it != k.end(); ++it)
            if (it.key() != "time" && it.key() != "eye" && it.key() != "target" && it.key() != "fov" && it.key() != "up")
                fail(at, "unknown key \"" + it.key() + "\" (expected time, eye, target, fov, up)");
        CameraKey key;
        if (!k.contains("time") || !k["time"].is_number() || !std::isfinite(k["time"].get<double>()))
            fail(at + ".time", "expected a finite number of seconds");
        key.time = k["time"].get<double>();
        if (!k.contains("eye")) fail(at + ".eye", "missing");
        if (!k.contains("target")) fail(at + ".target", "missing");
        key.eye = vec3From(k["eye"], at + ".eye");
        key.target = vec3From(k["target"], at + ".target");
        key.up = k.contains("up") ? vec3From(k["up"], at + ".up") : up;
        if (k.contains("fov")) {
            if (!k["fov"].is_number()) fail(at + ".fov", "expected degrees in (0, 180)");
            key.fovDeg = k["fov"].get<float>();
            if (!(key.fovDeg > 0.f && key.fovDeg < 180.f)) fail(at + ".fov", "expected degrees in (0, 180)");
        }
        const glm::vec3 forward = key.target - key.eye;
        if (!(glm::length(forward) > 0.f)) fail(at, "eye and target coincide");
        if (!(glm::length(glm::cross(forward, key.up)) > 1e-6f * glm::length(forward) * glm::length(key.up)))
            fail(at + ".up", "zero or parallel to the view direction");
        if (!path.keys.empty() && !(key.time > path.keys.back().time))
            fail(at + ".time", "times must increase strictly (" + std::to_string(key.time) + " after " +
                                   std::to_string(path.keys.back().time) + ")");
        path.keys.push_back(key);
    }
    return path;
}

CameraPath loadCameraPath(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open the camera path");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(file + ": not valid JSON (" + std::string(e.what()) + ")");
    }
    return cameraPathFromJson(doc, file);
}

nlohmann::json cameraPathToJson(const CameraPath& path) {
    nlohmann::json keys = nlohmann::json::array();
    for (const CameraKey& k : path.keys)
        keys.push_back({{"time", k.time}, {"eye", vec3Json(k.eye)}, {"target", vec3Json(k.target)},
                        {"up", vec3Json(k.up)}, {"fov", k.fovDeg}});
    nlohmann::json doc = {{"interpolation", path.interpolation == PathInterpolation::Linear ? "linear" : "catmull-rom"},
                          {"keys", keys}};
    if (!path.animation.empty()) doc["animation"] = path.animation;
    return doc;
}

CameraKey interpolateCameraPath(const CameraPath& path, double t) {
    const std::vector<CameraKey>& k = path.keys;
    if (k.empty()) throw std::invalid_argument("interpolateCameraPath: a path without keys");
    if (!(t > k.front().time)) return k.front();
    if (!(t < k.back().time)) return k.back();
    // The interval [t_i, t_{i+1}) holding t.
    const size_t i = size_t(std::upper_bound(k.begin(), k.end(), t, [](double x, const CameraKey& key) {
                                 return x < key.time;
                             }) - k.begin()) - 1;
    const CameraKey& a = k[i];
    const CameraKey& b = k[i + 1];
    const float u = float((t - a.time) / (b.time - a.time));
    CameraKey out;
    out.time = t;
    out.up = glm::mix(a.up, b.up, u);
    out.fovDeg = glm::mix(a.fovDeg, b.fovDeg, u);
    if (path.interpolation == PathInterpolation::Linear) {
        out.eye = glm::mix(a.eye, b.eye, u);
        out.target = glm::mix(a.target, b.target, u);
    } else {
        const float span = float(b.time - a.time);
        for (glm::vec3 CameraKey::*m : {&CameraKey::eye, &CameraKey::target})
            out.*m = hermite(a.*m, span * keyVelocity(k, i, m), b.*m, span * keyVelocity(k, i + 1, m), u);
    }
    return out;
}

Camera cameraOnPath(const CameraPath& path, double t, const Scene& scene) {
    const CameraKey k = interpolateCameraPath(path, t);
    CameraRequest request;
    request.hasEye = true;
    request.eye = k.eye;
    request.target = k.target;
    request.fovDeg = k.fovDeg;
    Camera c = resolveCamera(scene, request, 1.f);
    c.name = "path";
    // An interpolated up may pass through the view direction (two keys' ups lerping across it):
    // then the explicit camera's own up stands.
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(glm::cross(forward, k.up)) > 1e-6f * glm::length(forward) * glm::length(k.up)) c.up = k.up;
    return c;
}

std::vector<double> pathFrameTimes(const CameraPath& path, int frames) {
    std::vector<double> t;
    if (frames <= 0) return t;
    const double t0 = path.startTime(), t1 = path.endTime();
    for (int f = 0; f < frames; ++f) t.push_back(frames == 1 ? t0 : t0 + (t1 - t0) * double(f) / double(frames - 1));
    return t;
}

uint64_t frameSeed(uint64_t seed, int frame) {
    if (frame == 0) return seed;
    // SplitMix64 of (seed, frame): neighbouring frames get unrelated streams.
    uint64_t z = seed + 0x9E3779B97F4A7C15ull * uint64_t(frame);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace vct
