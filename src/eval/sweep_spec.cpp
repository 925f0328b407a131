// Reading a sweep spec: the JSON file to validated structs, with scene paths resolved and
// method grids expanded; every error names the offending field by its path.
#include "eval/sweep_spec.h"

#include "eval/sweep_detail.h"
#include "core/errors.h"
#include "core/request.h"
#include "methods/registry.h"
#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace sweep_detail;

namespace {

// Reads the overridable settings present in `obj` on top of `s`.
void readSettings(const json& obj, const std::string& where, SweepCaseSettings& s) {
    if (obj.contains("size")) sizeField(obj["size"], join(where, "size"), s.width, s.height);
    if (obj.contains("radius")) {
        const json& r = obj["radius"];
        const std::string w = join(where, "radius");
        s.radii.clear();
        if (r.is_array()) {
            if (r.empty()) fail(w, "expected at least one radius");
            for (size_t i = 0; i < r.size(); ++i) s.radii.push_back(positiveFloat(r[i], indexed(w, i), false));
        } else {
            s.radii.push_back(positiveFloat(r, w, false));
        }
    }
    if (obj.contains("ref_spp")) s.referenceSpp = intField(obj["ref_spp"], join(where, "ref_spp"), 1, 1 << 20);
    if (obj.contains("runs")) s.timingRuns = intField(obj["runs"], join(where, "runs"), 1, 100);
    if (obj.contains("voxel_res")) s.voxelRes = intField(obj["voxel_res"], join(where, "voxel_res"), 4, 1024);
    if (obj.contains("seed")) s.seed = uint64_t(intField(obj["seed"], join(where, "seed"), 0, 1 << 30));
    if (obj.contains("sky")) s.sky = positiveFloat(obj["sky"], join(where, "sky"), true);
    if (obj.contains("params"))
        for (const auto& [k, v] : paramsField(obj["params"], join(where, "params"))) s.params[k] = v;
}

std::vector<MethodVariant> parseMethods(const json& j, const std::string& where) {
    if (!j.is_array() || j.empty()) fail(where, "expected a non-empty list of {\"kind\", \"method\", \"grid\"}");
    std::vector<MethodVariant> out;
    std::set<std::string> labels;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string w = indexed(where, i);
        const json& m = j[i];
        if (!m.is_object()) fail(w, "expected an object {\"kind\", \"method\", \"params\", \"grid\"}");
        checkKnownFields(m, w, {"kind", "method", "params", "grid"});
        std::string kind = "ao";
        if (m.contains("kind")) {
            if (!m["kind"].is_string() || (m["kind"] != "ao" && m["kind"] != "gi"))
                fail(join(w, "kind"), "expected \"ao\" or \"gi\", got " + m["kind"].dump());
            kind = m["kind"].get<std::string>();
        }
        if (!m.contains("method") || !m["method"].is_string()) fail(join(w, "method"), "expected a method name");
        const std::string method = m["method"].get<std::string>();
        const MethodKind methodKind = kind == "gi" ? MethodKind::GI : MethodKind::AO;
        const Method* known = findMethod(methodKind, method);
        if (!known || known->groundTruth) {
            std::string all;
            for (const Method* k : scoredMethods(methodKind)) all += (all.empty() ? "" : ", ") + k->name;
            fail(join(w, "method"), "'" + method + "' is not a " + kind + " method to compare (known: " + all + ")");
        }
        std::map<std::string, std::string> fixed;
        if (m.contains("params")) fixed = paramsField(m["params"], join(w, "params"));
        std::vector<std::pair<std::string, std::vector<std::string>>> grid;
        if (m.contains("grid")) {
            const json& g = m["grid"];
            const std::string wg = join(w, "grid");
            if (!g.is_object()) fail(wg, "expected an object of KEY: [VALUES]");
            for (auto it = g.begin(); it != g.end(); ++it) {
                const std::string wk = join(wg, it.key());
                checkParamKey(it.key(), wk);
                if (fixed.count(it.key())) fail(wk, "also set in params");
                std::vector<std::string> values;
                if (it.value().is_array()) {
                    if (it.value().empty()) fail(wk, "expected at least one value");
                    for (size_t v = 0; v < it.value().size(); ++v) values.push_back(paramValue(it.value()[v], indexed(wk, v)));
                } else {
                    values.push_back(paramValue(it.value(), wk));
                }
                grid.emplace_back(it.key(), values);
            }
        }
        for (MethodVariant& v : expandMethodGrid(kind, method, fixed, grid)) {
            if (!labels.insert(v.kind + ":" + v.label()).second) fail(w, "duplicate variant " + v.label());
            out.push_back(std::move(v));
        }
    }
    return out;
}

// A camera entry with "path": a path file (resolved like a scene, read and checked now, so a
// bad path stops the sweep before anything runs) or "gltf:NAME", the scene's own camera
// animation (checked when the scene loads). Its label defaults to the file's stem or NAME.
SweepCamera parsePathCamera(const json& c, const std::string& w, const SweepPaths& paths) {
    checkKnownFields(c, w, {"name", "label", "path", "frames", "frame_seeds"});
    SweepCamera cam;
    const std::string wp = join(w, "path");
    if (!c["path"].is_string() || c["path"].get<std::string>().empty())
        fail(wp, "expected a camera path file or \"gltf:NAME\", got " + c["path"].dump());
    cam.path.entry = c["path"].get<std::string>();
    const std::string gltf = "gltf:";
    if (cam.path.entry.compare(0, gltf.size(), gltf) == 0) {
        cam.path.animation = cam.path.entry.substr(gltf.size());
        if (cam.path.animation.empty()) fail(wp, "\"gltf:\" needs the name or index of a camera animation of the scene");
        cam.label = cam.path.animation;
    } else {
        std::string file;
        try {
            file = resolveScenePath(cam.path.entry, paths);
        } catch (const UsageError& e) {
            fail(wp, e.what());
        }
        if (!fs::exists(file))
            fail(wp, "no such file " + file + " (looked up beside the spec, then in the repository; "
                     "\"gltf:NAME\" plays a camera animation of the scene)");
        try {
            cam.path.file = loadCameraPath(file);
        } catch (const std::exception& e) {
            fail(wp, e.what());
        }
        cam.label = fs::path(cam.path.entry).stem().string();
    }
    if (!c.contains("frames")) fail(join(w, "frames"), "required with a path: the number of frames, in [1, 10000]");
    cam.path.frames = intField(c["frames"], join(w, "frames"), 1, 10000);
    if (c.contains("frame_seeds")) {
        const json& fsd = c["frame_seeds"];
        if (!fsd.is_string() || (fsd != "per-frame" && fsd != "fixed"))
            fail(join(w, "frame_seeds"), "expected \"per-frame\" or \"fixed\", got " + fsd.dump());
        cam.path.perFrameSeeds = fsd == "per-frame";
    }
    if (c.contains("name") && c.contains("label")) fail(join(w, "label"), "give \"name\" or \"label\", not both");
    for (const char* key : {"name", "label"})
        if (c.contains(key)) {
            if (!c[key].is_string() || c[key].get<std::string>().empty()) fail(join(w, key), "expected a name");
            cam.label = c[key].get<std::string>();
        }
    return cam;
}

std::vector<SweepCamera> parseCameras(const json& j, const std::string& where, const SweepPaths& paths) {
    if (!j.is_array() || j.empty())
        fail(where, "expected a non-empty list of camera names, indices, {eye, target} or {path, frames}");
    std::vector<SweepCamera> out;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string w = indexed(where, i);
        const json& c = j[i];
        SweepCamera cam;
        if (c.is_object() && c.contains("path")) {
            cam = parsePathCamera(c, w, paths);
        } else if (c.is_string()) {
            cam.nameOrIndex = cam.label = c.get<std::string>();
            if (cam.label.empty()) fail(w, "empty camera name");
        } else if (c.is_number_integer()) {
            int idx = intField(c, w, 0, 1 << 20);
            cam.nameOrIndex = std::to_string(idx);
            cam.label = "cam" + cam.nameOrIndex;
        } else if (c.is_object()) {
            for (const char* key : {"frames", "frame_seeds"})
                if (c.contains(key)) fail(join(w, "path"), std::string("required with \"") + key + "\"");
            checkKnownFields(c, w, {"name", "eye", "target", "fov"});
            auto vec3 = [&](const char* key) {
                const std::string wk = join(w, key);
                if (!c.contains(key)) fail(wk, "required with an explicit view");
                const json& v = c[key];
                if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
                    fail(wk, "expected [x, y, z], got " + v.dump());
                glm::vec3 p(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail(wk, "not finite");
                return p;
            };
            cam.hasEye = true;
            cam.eye = vec3("eye");
            cam.target = vec3("target");
            if (cam.eye == cam.target) fail(join(w, "target"), "equals eye");
            if (c.contains("fov")) {
                cam.fovDeg = positiveFloat(c["fov"], join(w, "fov"), false);
                if (cam.fovDeg >= 180.f) fail(join(w, "fov"), "must be < 180 degrees");
            }
            cam.label = "view" + std::to_string(i);
            if (c.contains("name")) {
                if (!c["name"].is_string() || c["name"].get<std::string>().empty()) fail(join(w, "name"), "expected a name");
                cam.label = c["name"].get<std::string>();
            }
        } else {
            fail(w, "expected a camera name, an index, {\"eye\", \"target\", \"fov\", \"name\"} or "
                    "{\"path\", \"frames\", \"frame_seeds\", \"name\"}");
        }
        out.push_back(cam);
    }
    return out;
}


}  // namespace

SweepPaths defaultSweepPaths(const std::string& specPath) {
    SweepPaths p;
    fs::path dir = fs::absolute(fs::path(specPath)).parent_path();
    p.specDir = dir.string();
    p.repoDir = fs::current_path().string();
    for (fs::path d = dir; !d.empty(); d = d.parent_path()) {
        if (fs::exists(d / "CMakeLists.txt")) {
            p.repoDir = d.string();
            break;
        }
        if (d == d.parent_path()) break;
    }
    const char* env = std::getenv("VCT_SHARED_SCENES");
    p.sharedDir = env && *env ? std::string(env) : (fs::path(p.repoDir).parent_path() / "shared" / "scenes").string();
    return p;
}

std::string resolveScenePath(const std::string& entry, const SweepPaths& paths) {
    const std::string token = "${shared}";
    if (entry.compare(0, token.size(), token) == 0) {
        std::string rest = entry.substr(token.size());
        while (!rest.empty() && rest[0] == '/') rest.erase(0, 1);
        return (fs::path(paths.sharedDir) / rest).lexically_normal().string();
    }
    if (entry.find(token) != std::string::npos) throw UsageError("'" + entry + "': ${shared} must come first");
    const fs::path p(entry);
    if (p.is_absolute()) return entry;
    const fs::path inSpec = fs::path(paths.specDir) / p;
    if (!paths.specDir.empty() && fs::exists(inSpec)) return inSpec.lexically_normal().string();
    return (fs::path(paths.repoDir) / p).lexically_normal().string();
}

std::vector<MethodVariant> expandMethodGrid(const std::string& kind, const std::string& method,
                                            const std::map<std::string, std::string>& fixed,
                                            const std::vector<std::pair<std::string, std::vector<std::string>>>& grid) {
    std::vector<MethodVariant> out;
    MethodVariant base;
    base.kind = kind;
    base.method = method;
    base.params = fixed;
    out.push_back(base);
    for (const auto& [key, values] : grid) {  // each key multiplies the list; later keys vary fastest
        std::vector<MethodVariant> next;
        for (const MethodVariant& v : out)
            for (const std::string& value : values) {
                MethodVariant w = v;
                w.params[key] = value;
                next.push_back(w);
            }
        out = std::move(next);
    }
    return out;
}

SweepSpec parseSweepSpec(const json& j, const SweepPaths& paths, const std::string& specPath) {
    if (!j.is_object()) fail("(top)", "expected a JSON object");
    checkKnownFields(j, "", {"name", "scenes", "methods", "size", "radius", "ref_spp", "runs", "voxel_res", "seed", "sky",
                             "params"});
    SweepSpec spec;
    spec.specPath = specPath;
    spec.source = j;
    if (j.contains("name")) {
        if (!j["name"].is_string()) fail("name", "expected a string");
        spec.name = j["name"].get<std::string>();
    }
    SweepCaseSettings defaults;
    readSettings(j, "", defaults);
    std::vector<MethodVariant> methods;
    const bool hasMethods = j.contains("methods");
    if (hasMethods) methods = parseMethods(j["methods"], "methods");
    if (!j.contains("scenes") || !j["scenes"].is_array() || j["scenes"].empty())
        fail("scenes", "expected a non-empty list of scene paths or {\"path\", ...}");
    for (size_t i = 0; i < j["scenes"].size(); ++i) {
        const std::string w = indexed("scenes", i);
        const json& e = j["scenes"][i];
        SweepScene s;
        s.settings = defaults;
        s.variants = methods;
        s.cameras = {SweepCamera{"default", "", false, {}, {}, 45.f, {}}};
        if (e.is_string()) {
            s.entry = e.get<std::string>();
        } else if (e.is_object()) {
            checkKnownFields(e, w, {"path", "cameras", "methods", "size", "radius", "ref_spp", "runs", "voxel_res", "seed",
                                    "sky", "params"});
            if (!e.contains("path") || !e["path"].is_string()) fail(join(w, "path"), "expected the scene file");
            s.entry = e["path"].get<std::string>();
            readSettings(e, w, s.settings);
            if (e.contains("cameras")) s.cameras = parseCameras(e["cameras"], join(w, "cameras"), paths);
            if (e.contains("methods")) s.variants = parseMethods(e["methods"], join(w, "methods"));
        } else {
            fail(w, "expected a scene path or {\"path\", ...}");
        }
        if (s.entry.empty()) fail(w, "empty scene path");
        if (s.variants.empty()) fail(w, "no methods: give \"methods\" at the top level or in the scene");
        try {
            s.path = resolveScenePath(s.entry, paths);
        } catch (const UsageError& ex) {
            fail(w, ex.what());
        }
        s.stem = fs::path(s.entry).stem().string();
        spec.scenes.push_back(std::move(s));
    }
    // Catch duplicate case ids while the message can still name the spec.
    enumerateSweepCases(spec);
    return spec;
}

SweepSpec loadSweepSpec(const std::string& specPath) {
    std::ifstream in(specPath);
    if (!in) throw UsageError("sweep spec " + specPath + ": cannot read the file");
    json j;
    try {
        j = json::parse(in);
    } catch (const json::parse_error& e) {
        throw UsageError("sweep spec " + specPath + ": not valid JSON: " + e.what());
    }
    try {
        return parseSweepSpec(j, defaultSweepPaths(specPath), specPath);
    } catch (const UsageError& e) {
        throw UsageError(specPath + ": " + e.what());
    }
}

}  // namespace vct
