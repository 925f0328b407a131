// What a sweep is: the spec (scenes x cameras x radii x method grids, with per-scene
// settings) as validated structs, and the cases it expands into. The format is documented
// in docs/sweeps.md.
#pragma once

#include "eval/comparison.h"
#include "scene/camera_path.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace vct {

// A camera moving along a path: a case with one runs a sequence comparison
// (eval/sequence_comparison.h) instead of a still one.
struct SweepCameraPath {
    std::string entry;      // as written in the spec: a file, or "gltf:NAME" (empty: no path)
    std::string animation;  // NAME of "gltf:NAME": the scene's camera animation, known once it loads
    CameraPath file;        // the path file, read and checked while parsing (unused for gltf:)
    int frames = 0;         // [1, 10000]
    bool perFrameSeeds = true;  // "frame_seeds": "per-frame" (true) or "fixed"
};

// A view of one scene: a camera of the file (by name or index; empty = the file's first
// camera, else a framing of the bounds), an explicit eye/target/fov, or a camera path.
struct SweepCamera {
    std::string label;        // part of the case id: the name, "cam<index>", "default" or given
    std::string nameOrIndex;  // file camera; empty with hasEye = false: the default camera
    bool hasEye = false;
    glm::vec3 eye{0.f}, target{0.f};
    float fovDeg = 45.f;      // vertical, degrees, (0, 180)
    SweepCameraPath path;     // set (path.entry not empty): the case is a sequence

    bool isPath() const { return !path.entry.empty(); }
};

// Settings a scene entry may override (top level gives the defaults).
struct SweepCaseSettings {
    int width = 128, height = 128;  // pixels
    std::vector<float> radii{1.f};  // AO radius R, world units, > 0; one case per radius
    int referenceSpp = 256;         // [1, 1048576]
    int timingRuns = 3;             // [1, 100]
    int voxelRes = 128;             // [4, 1024]
    uint64_t seed = 0;
    float sky = 1.f;                // uniform sky radiance, >= 0
    std::map<std::string, std::string> params;  // shared --param values for every variant
};

struct SweepScene {
    std::string entry;  // as written in the spec (may hold ${shared})
    std::string path;   // resolved file path (may not exist: its cases are skipped)
    std::string stem;   // file name without extension: the case id's first part
    std::vector<SweepCamera> cameras;  // never empty (a lone default camera)
    SweepCaseSettings settings;
    std::vector<MethodVariant> variants;  // the scene's methods, grid-expanded
};

struct SweepSpec {
    std::string specPath;  // where it was read from (for messages), may be empty
    std::string name;      // optional "name" of the spec
    std::vector<SweepScene> scenes;
    nlohmann::json source;  // the spec as read
};

// Where relative scene paths and ${shared} resolve.
struct SweepPaths {
    std::string specDir;    // directory of the spec file
    std::string repoDir;    // the repository (nearest ancestor of specDir with CMakeLists.txt, else cwd)
    std::string sharedDir;  // $VCT_SHARED_SCENES, else <repoDir>/../shared/scenes
};
SweepPaths defaultSweepPaths(const std::string& specPath);

// Parses and validates a spec; UsageError names the offending field as a path
// ("scenes[1].cameras[0].eye: ...").
SweepSpec parseSweepSpec(const nlohmann::json& spec, const SweepPaths& paths, const std::string& specPath = "");
SweepSpec loadSweepSpec(const std::string& specPath);

// "${shared}/x.glb" -> <sharedDir>/x.glb; relative paths: the spec's directory if the file
// exists there, else the repository's.
std::string resolveScenePath(const std::string& entry, const SweepPaths& paths);

// The cartesian product of grid values (keys in sorted order, the last varying fastest),
// each variant also carrying the fixed params. Grid values may be strings, numbers or bools.
std::vector<MethodVariant> expandMethodGrid(const std::string& kind, const std::string& method,
                                            const std::map<std::string, std::string>& fixed,
                                            const std::vector<std::pair<std::string, std::vector<std::string>>>& grid);

struct SweepCase {
    size_t index = 0;     // position in the deterministic case order
    std::string id;       // "<scene-stem>__<camera>__r<radius>", file-name safe, unique
    size_t scene = 0;     // index into SweepSpec::scenes
    SweepCamera camera;
    float radius = 1.f;
};

// Scenes in spec order, then cameras in order, then radii in order. Throws
// UsageError if two cases would share an id.
std::vector<SweepCase> enumerateSweepCases(const SweepSpec& spec);

// The metadata written next to a case's results (DIR/cases/<id>/case.json).
nlohmann::json caseJson(const SweepSpec& spec, const SweepCase& c);

}  // namespace vct
