// A camera moving through time: keyframes of (time, eye, target, up, field of view) and the
// rule that fills the time between them. Sequences (`vct render --path`, `vct compare --path`)
// sample it at their frames' times; it comes from a JSON file (loadCameraPath) or from a glTF
// file's own camera animation (scene/gltf_animation.h).
//
// The JSON form (every key but "keys" optional):
//   { "interpolation": "catmull-rom" | "linear",       default catmull-rom
//     "up": [0, 1, 0],                                  default up of every key
//     "animation": "NAME",                              a glTF animation of the scene to play along
//     "keys": [ { "time": 0, "eye": [x, y, z], "target": [x, y, z], "fov": 45, "up": [...] }, ... ] }
// Times in seconds, strictly increasing; fov is the vertical field of view in degrees, (0, 180),
// default 45.
//
// Interpolation between keys i and i+1 at u = (t - t_i) / (t_{i+1} - t_i):
// - linear: eye, target, up and fov each lerped;
// - catmull-rom: eye and target by the Catmull-Rom spline through the keys in time: a cubic
//   Hermite curve on each interval, the velocity at key i (p_{i+1} - p_{i-1}) / (t_{i+1} - t_{i-1})
//   (at an end key the chord to its neighbour), so the curve passes through every key and the
//   velocity is continuous even where keys are unevenly spaced in time; evenly timed collinear
//   keys move at constant speed. up and fov are lerped, so the field of view never overshoots.
// Before the first key and after the last the camera stands at that key.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace vct {

struct CameraKey {
    double time = 0.0;
    glm::vec3 eye{0.f, 0.f, 5.f};
    glm::vec3 target{0.f};
    glm::vec3 up{0.f, 1.f, 0.f};
    float fovDeg = 45.f;
};

enum class PathInterpolation { Linear, CatmullRom };

struct CameraPath {
    std::string source;  // the file, or "<scene>: animation 'x'", for messages and records
    PathInterpolation interpolation = PathInterpolation::CatmullRom;
    std::vector<CameraKey> keys;  // at least one, times strictly increasing
    // A glTF animation of the scene that plays along (it moves the scene's lights; empty: none).
    // A path file names it with "animation"; a glTF camera animation plays its own.
    std::string animation;

    double startTime() const { return keys.front().time; }
    double endTime() const { return keys.back().time; }
};

// Reads a path file; throws std::runtime_error naming the file and the element
// ("path.json: keys[2].eye: expected 3 finite numbers") for every problem.
CameraPath loadCameraPath(const std::string& file);
// The same checks on an already parsed document; `where` prefixes the messages.
CameraPath cameraPathFromJson(const nlohmann::json& doc, const std::string& where);
nlohmann::json cameraPathToJson(const CameraPath& path);

// The path's key at time t (clamped to the path's span), interpolated as the header says.
CameraKey interpolateCameraPath(const CameraPath& path, double t);
// That key as a camera: the camera `--eye E --target T --fov F` gives in `scene` (its near and
// far planes around the scene's bounds, scene/camera.h), with the key's up vector; so a frame
// of a path is the still render of its key.
Camera cameraOnPath(const CameraPath& path, double t, const Scene& scene);

// The times of `frames` frames spread evenly over the path, first and last key included
// (one frame: the first key's time).
std::vector<double> pathFrameTimes(const CameraPath& path, int frames);

// The per-frame seed of frame `frame` of a sequence rendered with `seed`: independent streams
// per frame (a reference's noise does not repeat from frame to frame), the same for a given
// seed and frame however the sequence is cut or resumed. Frame 0 keeps `seed`, so a one-frame
// sequence is the still render.
uint64_t frameSeed(uint64_t seed, int frame);

}  // namespace vct
