#include "eval/sweep.h"

#include "methods/registry.h"
#include "render/renderer.h"
#include "core/params.h"
#include "core/request.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw std::invalid_argument("sweep spec: " + where + ": " + what);
}

std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
}

std::string indexed(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

// Fields whose name starts with "_" or is "description"/"comment" are notes, not settings.
bool isNote(const std::string& key) { return key.empty() || key[0] == '_' || key == "description" || key == "comment"; }

void checkKnownFields(const json& obj, const std::string& where, const std::set<std::string>& known) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (!isNote(it.key()) && !known.count(it.key())) {
            std::string all;
            for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
            fail(join(where, it.key()), "unknown field (known: " + all + ")");
        }
}

int intField(const json& j, const std::string& where, int lo, int hi) {
    if (!j.is_number_integer()) fail(where, "expected an integer, got " + j.dump());
    long long v = j.get<long long>();
    if (v < lo || v > hi) fail(where, std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return int(v);
}

float positiveFloat(const json& j, const std::string& where, bool allowZero) {
    if (!j.is_number()) fail(where, "expected a number, got " + j.dump());
    double v = j.get<double>();
    if (!std::isfinite(v) || v < 0 || (!allowZero && v == 0))
        fail(where, "expected a finite number " + std::string(allowZero ? ">= 0" : "> 0") + ", got " + j.dump());
    return float(v);
}

// A parameter value as --param would receive it.
std::string paramValue(const json& j, const std::string& where) {
    if (j.is_string()) return j.get<std::string>();
    if (j.is_boolean()) return j.get<bool>() ? "1" : "0";
    if (j.is_number()) return j.dump();
    fail(where, "expected a string, number or bool, got " + j.dump());
}

void checkParamKey(const std::string& key, const std::string& where) {
    const std::vector<SettingDoc> docs = allSettingDocs();
    if (std::none_of(docs.begin(), docs.end(), [&](const SettingDoc& d) { return d.key == key; }))
        fail(where, "unknown parameter '" + key + "' (see vct render --help-params)");
}

std::map<std::string, std::string> paramsField(const json& j, const std::string& where) {
    if (!j.is_object()) fail(where, "expected an object of KEY: VALUE, got " + j.dump());
    std::map<std::string, std::string> out;
    for (auto it = j.begin(); it != j.end(); ++it) {
        checkParamKey(it.key(), join(where, it.key()));
        out[it.key()] = paramValue(it.value(), join(where, it.key()));
    }
    return out;
}

void sizeField(const json& j, const std::string& where, int& w, int& h) {
    auto check = [&](long long v) {
        if (v < 1 || v > 16384) fail(where, "image size must be in [1, 16384], got " + std::to_string(v));
        return int(v);
    };
    if (j.is_number_integer()) {
        w = h = check(j.get<long long>());
    } else if (j.is_array() && j.size() == 2 && j[0].is_number_integer() && j[1].is_number_integer()) {
        w = check(j[0].get<long long>());
        h = check(j[1].get<long long>());
    } else if (j.is_string()) {
        const std::string s = j.get<std::string>();
        size_t x = s.find('x');
        try {
            size_t used = 0;
            long long a = std::stoll(s.substr(0, x), &used);
            if (used != (x == std::string::npos ? s.size() : x)) throw std::invalid_argument("trailing text");
            long long b = a;
            if (x != std::string::npos) {
                b = std::stoll(s.substr(x + 1), &used);
                if (used != s.size() - x - 1) throw std::invalid_argument("trailing text");
            }
            w = check(a);
            h = check(b);
        } catch (const std::logic_error&) {
            fail(where, "expected N, \"WxH\" or [W, H], got " + j.dump());
        }
    } else {
        fail(where, "expected N, \"WxH\" or [W, H], got " + j.dump());
    }
}

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

std::vector<SweepCamera> parseCameras(const json& j, const std::string& where) {
    if (!j.is_array() || j.empty()) fail(where, "expected a non-empty list of camera names, indices or {eye, target}");
    std::vector<SweepCamera> out;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string w = indexed(where, i);
        const json& c = j[i];
        SweepCamera cam;
        if (c.is_string()) {
            cam.nameOrIndex = cam.label = c.get<std::string>();
            if (cam.label.empty()) fail(w, "empty camera name");
        } else if (c.is_number_integer()) {
            int idx = intField(c, w, 0, 1 << 20);
            cam.nameOrIndex = std::to_string(idx);
            cam.label = "cam" + cam.nameOrIndex;
        } else if (c.is_object()) {
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
            fail(w, "expected a camera name, an index or {\"eye\", \"target\", \"fov\", \"name\"}");
        }
        out.push_back(cam);
    }
    return out;
}

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_')) c = '_';
    return s;
}

std::string radiusText(float r) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(r));
    return buf;
}

json readJsonFile(const fs::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    try {
        return json::parse(in);
    } catch (const json::parse_error& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

void writeTextAtomic(const fs::path& path, const std::string& text, const std::string& tmpSuffix = ".tmp") {
    fs::path tmp = path;
    tmp += tmpSuffix;
    {
        std::ofstream out(tmp);
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
        out << text;
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
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
    if (entry.find(token) != std::string::npos) throw std::invalid_argument("'" + entry + "': ${shared} must come first");
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
        s.cameras = {SweepCamera{"default", "", false, {}, {}, 45.f}};
        if (e.is_string()) {
            s.entry = e.get<std::string>();
        } else if (e.is_object()) {
            checkKnownFields(e, w, {"path", "cameras", "methods", "size", "radius", "ref_spp", "runs", "voxel_res", "seed",
                                    "sky", "params"});
            if (!e.contains("path") || !e["path"].is_string()) fail(join(w, "path"), "expected the scene file");
            s.entry = e["path"].get<std::string>();
            readSettings(e, w, s.settings);
            if (e.contains("cameras")) s.cameras = parseCameras(e["cameras"], join(w, "cameras"));
            if (e.contains("methods")) s.variants = parseMethods(e["methods"], join(w, "methods"));
        } else {
            fail(w, "expected a scene path or {\"path\", ...}");
        }
        if (s.entry.empty()) fail(w, "empty scene path");
        if (s.variants.empty()) fail(w, "no methods: give \"methods\" at the top level or in the scene");
        try {
            s.path = resolveScenePath(s.entry, paths);
        } catch (const std::invalid_argument& ex) {
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
    if (!in) throw std::invalid_argument("sweep spec " + specPath + ": cannot read the file");
    json j;
    try {
        j = json::parse(in);
    } catch (const json::parse_error& e) {
        throw std::invalid_argument("sweep spec " + specPath + ": not valid JSON: " + e.what());
    }
    try {
        return parseSweepSpec(j, defaultSweepPaths(specPath), specPath);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(specPath + ": " + e.what());
    }
}

std::vector<SweepCase> enumerateSweepCases(const SweepSpec& spec) {
    std::vector<SweepCase> out;
    std::map<std::string, std::string> seen;  // id -> what made it
    for (size_t si = 0; si < spec.scenes.size(); ++si) {
        const SweepScene& s = spec.scenes[si];
        for (const SweepCamera& cam : s.cameras)
            for (float r : s.settings.radii) {
                SweepCase c;
                c.index = out.size();
                c.scene = si;
                c.camera = cam;
                c.radius = r;
                c.id = fileSafe(s.stem + "__" + cam.label + "__r" + radiusText(r));
                const std::string what = "scene '" + s.entry + "' camera '" + cam.label + "' radius " + radiusText(r);
                auto [it, fresh] = seen.emplace(c.id, what);
                if (!fresh)
                    fail("scenes", "two cases share the id '" + c.id + "' (" + it->second + "; " + what +
                                       "): rename a camera or a scene file");
                out.push_back(c);
            }
    }
    return out;
}

Shard parseShard(const std::string& text) {
    Shard s;
    size_t slash = text.find('/');
    try {
        if (slash == std::string::npos) throw std::invalid_argument("no slash");
        size_t used = 0;
        s.index = std::stoi(text.substr(0, slash), &used);
        if (used != slash) throw std::invalid_argument("trailing");
        s.count = std::stoi(text.substr(slash + 1), &used);
        if (used != text.size() - slash - 1) throw std::invalid_argument("trailing");
    } catch (const std::logic_error&) {
        throw std::invalid_argument("--shard '" + text + "': expected I/N, e.g. 0/2");
    }
    if (s.count < 1 || s.index < 0 || s.index >= s.count)
        throw std::invalid_argument("--shard '" + text + "': need N >= 1 and 0 <= I < N");
    return s;
}

std::vector<SweepCase> casesOfShard(const std::vector<SweepCase>& cases, const Shard& shard) {
    std::vector<SweepCase> out;
    for (const SweepCase& c : cases)
        if (c.index % size_t(shard.count) == size_t(shard.index)) out.push_back(c);
    return out;
}

json caseJson(const SweepSpec& spec, const SweepCase& c) {
    const SweepScene& s = spec.scenes.at(c.scene);
    json cam = {{"label", c.camera.label}};
    if (c.camera.hasEye) {
        cam["eye"] = {c.camera.eye.x, c.camera.eye.y, c.camera.eye.z};
        cam["target"] = {c.camera.target.x, c.camera.target.y, c.camera.target.z};
        cam["fov_deg"] = c.camera.fovDeg;
    } else {
        cam["name_or_index"] = c.camera.nameOrIndex;
    }
    json variants = json::array();
    for (const MethodVariant& v : s.variants) variants.push_back({{"kind", v.kind}, {"label", v.label()}});
    return {{"id", c.id},
            {"index", c.index},
            {"scene", s.stem},
            {"scene_entry", s.entry},
            {"scene_path", s.path},
            {"camera", cam},
            {"radius", c.radius},
            {"width", s.settings.width},
            {"height", s.settings.height},
            {"ref_spp", s.settings.referenceSpp},
            {"runs", s.settings.timingRuns},
            {"voxel_res", s.settings.voxelRes},
            {"seed", s.settings.seed},
            {"sky", s.settings.sky},
            {"params", s.settings.params},
            {"variants", variants},
            {"spec", spec.specPath},
            {"spec_name", spec.name}};
}

SweepSummary runSweep(const SweepSpec& spec, const SweepRunOptions& o) {
    auto log = [&](const std::string& line) {
        if (o.log) o.log(line);
    };
    if (o.outDir.empty()) throw std::invalid_argument("sweep: no output directory");
    const fs::path out(o.outDir);
    fs::create_directories(out / "cases");
    const std::vector<SweepCase> all = enumerateSweepCases(spec);
    json ids = json::array();
    for (const SweepCase& c : all) ids.push_back(c.id);
    // Every shard writes the same content; a per-shard temp name keeps concurrent writers apart.
    writeTextAtomic(out / "sweep.json",
                    json{{"name", spec.name}, {"spec", spec.specPath}, {"source", spec.source}, {"cases", ids}}.dump(2) +
                        "\n",
                    ".tmp" + std::to_string(o.shard.index));

    const std::vector<SweepCase> mine = casesOfShard(all, o.shard);
    SweepSummary summary;
    std::unique_ptr<Scene> scene;  // cases come grouped by scene: load each once
    size_t loadedScene = size_t(-1);
    for (size_t k = 0; k < mine.size(); ++k) {
        const SweepCase& c = mine[k];
        const SweepScene& s = spec.scenes[c.scene];
        const std::string head = "[" + std::to_string(k + 1) + "/" + std::to_string(mine.size()) + "] " + c.id + ": ";
        const fs::path dir = out / "cases" / c.id;
        if (fs::exists(dir / "results.json")) {
            log(head + "skipped, done already (results.json exists)");
            ++summary.skippedDone;
            continue;
        }
        if (!fs::exists(s.path)) {
            log(head + "skipped, scene file " + s.path + " not found");
            ++summary.skippedMissing;
            continue;
        }
        auto t0 = std::chrono::steady_clock::now();
        if (loadedScene != c.scene) {
            scene = std::make_unique<Scene>(loadScene(s.path));
            loadedScene = c.scene;
        }
        ComparisonSettings cs;
        cs.base.width = s.settings.width;
        cs.base.height = s.settings.height;
        cs.base.radius = c.radius;
        cs.base.seed = s.settings.seed;
        cs.base.voxelRes = s.settings.voxelRes;
        cs.base.sky = s.settings.sky;
        for (const auto& [key, value] : s.settings.params) cs.base.params.set(key, value);
        CameraRequest cam;
        cam.nameOrIndex = c.camera.nameOrIndex;
        cam.hasEye = c.camera.hasEye;
        cam.eye = c.camera.eye;
        cam.target = c.camera.target;
        cam.fovDeg = c.camera.fovDeg;
        try {
            cs.base.camera = resolveCamera(*scene, cam, float(cs.base.width) / float(cs.base.height));
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("case " + c.id + ": " + e.what());
        }
        cs.referenceSpp = s.settings.referenceSpp;
        cs.timingRuns = s.settings.timingRuns;
        cs.variants = s.variants;
        cs.outputDir = dir.string();
        cs.writeImages = o.writeImages;
        if (o.progress) cs.progress = [&](const std::string& line) { o.progress(c.id + ": " + line); };
        fs::create_directories(dir);
        writeTextAtomic(dir / "case.json", caseJson(spec, c).dump(2) + "\n");
        try {
            runComparison(*scene, cs);  // writes results.json last, by rename: the "done" mark
        } catch (const std::exception& e) {
            throw std::runtime_error("case " + c.id + ": " + e.what());
        }
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f", seconds);
        log(head + "ran " + std::to_string(s.variants.size()) + " variants in " + secs + " s");
        ++summary.ran;
    }
    return summary;
}

namespace {

struct LoadedCase {
    json caseInfo;  // case.json, or what can be derived without it
    json results;   // results.json
    std::string dir;
};

void loadCaseDir(const fs::path& dir, std::vector<LoadedCase>& out, const std::function<void(const std::string&)>& warn) {
    LoadedCase lc;
    lc.dir = dir.string();
    lc.results = readJsonFile(dir / "results.json");
    if (fs::exists(dir / "case.json")) {
        lc.caseInfo = readJsonFile(dir / "case.json");
    } else {  // a plain `vct compare` directory
        const std::string scene = lc.results.value("scene", std::string());
        lc.caseInfo = {{"id", dir.filename().string()},
                       {"scene", fs::path(scene).stem().string()},
                       {"scene_path", scene},
                       {"camera", {{"label", "default"}}},
                       {"radius", lc.results.value("radius", 0.0)}};
        if (warn) warn(dir.string() + ": no case.json, using results.json alone");
    }
    out.push_back(std::move(lc));
}

bool lessRecordTime(const json& a, const json& b, const char* metric) {
    return a["time_ms"].get<double>() <= b["time_ms"].get<double>() && a[metric].get<double>() <= b[metric].get<double>() &&
           (a["time_ms"].get<double>() < b["time_ms"].get<double>() || a[metric].get<double>() < b[metric].get<double>());
}

}  // namespace

void markParetoFronts(json& records) {
    std::map<std::string, std::vector<size_t>> groups;
    for (size_t i = 0; i < records.size(); ++i)
        groups[records[i].value("case", std::string()) + "\n" + records[i].value("kind", std::string())].push_back(i);
    for (const char* metric : {"rmse", "roi_rmse"}) {
        const std::string flag = std::string(metric) == "rmse" ? "pareto" : "pareto_roi";
        for (const auto& [key, members] : groups)
            for (size_t i : members) {
                json& r = records[i];
                if (!r.contains(metric) || !r[metric].is_number() || !r["time_ms"].is_number()) {
                    r[flag] = nullptr;
                    continue;
                }
                bool dominated = false;
                for (size_t j : members)
                    if (j != i && records[j].contains(metric) && records[j][metric].is_number() &&
                        lessRecordTime(records[j], r, metric)) {
                        dominated = true;
                        break;
                    }
                r[flag] = !dominated;
            }
    }
}

json mergeSweepResults(const std::vector<std::string>& dirs, const std::function<void(const std::string&)>& warn) {
    std::vector<LoadedCase> cases;
    for (const std::string& d : dirs) {
        const fs::path dir(d);
        if (fs::is_directory(dir / "cases")) {
            std::vector<fs::path> subs;
            for (const auto& e : fs::directory_iterator(dir / "cases"))
                if (e.is_directory()) subs.push_back(e.path());
            std::sort(subs.begin(), subs.end());
            for (const fs::path& sub : subs) {
                if (fs::exists(sub / "results.json")) loadCaseDir(sub, cases, warn);
                else if (warn) warn(sub.string() + ": no results.json (not run yet, or interrupted): left out");
            }
            if (fs::exists(dir / "sweep.json") && warn) {
                json sw = readJsonFile(dir / "sweep.json");
                size_t present = 0;
                for (const auto& id : sw["cases"])
                    present += fs::exists(dir / "cases" / id.get<std::string>() / "results.json");
                if (present < sw["cases"].size())
                    warn(d + ": " + std::to_string(present) + " of " + std::to_string(sw["cases"].size()) +
                         " cases have results (other shards, absent scenes or unfinished cases)");
            }
        } else if (fs::exists(dir / "results.json")) {
            loadCaseDir(dir, cases, warn);
        } else {
            throw std::invalid_argument("merge: " + d + " holds neither cases/ nor results.json");
        }
    }
    std::stable_sort(cases.begin(), cases.end(), [](const LoadedCase& a, const LoadedCase& b) {
        const long long ia = a.caseInfo.value("index", -1LL), ib = b.caseInfo.value("index", -1LL);
        const std::string ida = a.caseInfo.value("id", std::string()), idb = b.caseInfo.value("id", std::string());
        // Plain comparison dirs (no index) go last.
        if ((ia < 0) != (ib < 0)) return ib < 0;
        return ia != ib ? ia < ib : ida < idb;
    });

    json merged = {{"cases", json::array()}, {"records", json::array()}, {"sources", dirs}};
    std::set<std::string> seen;
    for (LoadedCase& lc : cases) {
        const std::string id = lc.caseInfo.value("id", std::string());
        if (!seen.insert(id).second) {
            if (warn) warn(lc.dir + ": case " + id + " seen already in an earlier directory: left out");
            continue;
        }
        json doc = lc.results;
        doc["case"] = lc.caseInfo;
        doc["case_dir"] = lc.dir;
        const json& ref = doc.value("reference", json::object());
        for (const json& r : lc.results["records"]) {
            json flat = r;
            const bool ao = r.value("kind", std::string("ao")) == "ao";
            flat["case"] = id;
            flat["scene"] = lc.caseInfo.value("scene", std::string());
            flat["scene_path"] = lc.results.value("scene", std::string());
            flat["camera"] = lc.caseInfo.contains("camera") ? lc.caseInfo["camera"].value("label", std::string()) : "";
            flat["radius"] = lc.results.value("radius", 0.0);
            flat["width"] = lc.results.value("width", 0);
            flat["height"] = lc.results.value("height", 0);
            flat["gl_renderer"] = lc.results.value("gl_renderer", std::string());
            flat["ref_spp"] = ref.value("spp", 0);
            const char* stderrKey = ao ? "ao_rms_pixel_stderr" : "gi_rms_pixel_stderr";
            flat["ref_stderr"] = ref.contains(stderrKey) ? ref[stderrKey] : json(nullptr);
            if (flat.contains("images") && flat["images"].is_object())
                for (auto it = flat["images"].begin(); it != flat["images"].end(); ++it)
                    if (it.value().is_string()) it.value() = (fs::path(lc.dir) / it.value().get<std::string>()).string();
            merged["records"].push_back(std::move(flat));
        }
        merged["cases"].push_back(std::move(doc));
    }
    markParetoFronts(merged["records"]);
    return merged;
}

std::string mergedCsv(const json& merged) {
    static const std::vector<std::string> columns = {
        "case",  "scene",       "camera", "radius",   "width",     "height",     "kind",   "method",   "label",
        "params", "time_ms",    "rmse",   "mae",      "bias",      "max_abs",    "psnr",   "ssim",     "roi_rmse",
        "nonroi_rmse", "ref_spp", "ref_stderr", "pareto", "pareto_roi", "gl_renderer"};
    auto quote = [](const std::string& s) {
        if (s.find_first_of(",\"\n") == std::string::npos) return s;
        std::string q = "\"";
        for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    std::ostringstream out;
    for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
    for (const json& r : merged["records"]) {
        for (size_t i = 0; i < columns.size(); ++i) {
            const std::string& col = columns[i];
            std::string cell;
            if (col == "params") {
                if (r.contains("params"))
                    for (auto it = r["params"].begin(); it != r["params"].end(); ++it)
                        cell += (cell.empty() ? "" : ";") + it.key() + "=" + it.value().get<std::string>();
            } else if (r.contains(col) && !r[col].is_null()) {
                cell = r[col].is_string() ? r[col].get<std::string>() : r[col].dump();
            }
            out << (i ? "," : "") << quote(cell);
        }
        out << "\n";
    }
    return out.str();
}

void writeMerged(const json& merged, const std::string& outDir) {
    fs::create_directories(outDir);
    writeTextAtomic(fs::path(outDir) / "results.json", merged.dump(2) + "\n");
    writeTextAtomic(fs::path(outDir) / "results.csv", mergedCsv(merged));
}

}  // namespace vct
