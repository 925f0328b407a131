// Running a sweep: the shard's cases one comparison each (a still one, or a sequence
// comparison along the case's camera path), skipping the cases done already (resume) and
// those whose scene file is absent.
#include "eval/sweep.h"

#include "core/errors.h"
#include "eval/sequence_comparison.h"
#include "scene/camera.h"
#include "scene/camera_path.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;
using nlohmann::json;

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
        throw UsageError("--shard '" + text + "': expected I/N, e.g. 0/2");
    }
    if (s.count < 1 || s.index < 0 || s.index >= s.count)
        throw UsageError("--shard '" + text + "': need N >= 1 and 0 <= I < N");
    return s;
}

namespace {

// The case's camera path: the file read while parsing the spec, or the loaded scene's camera
// animation for "gltf:NAME".
CameraPath casePath(const SweepCameraPath& p, const Scene& scene) {
    CameraPath path;
    if (p.animation.empty()) {
        path = p.file;
    } else {
        try {
            path = cameraAnimationPath(scene, p.animation);
        } catch (const std::invalid_argument& e) {
            throw UsageError("camera path " + p.entry + ": " + e.what());
        }
    }
    checkPathAnimation(path, scene);
    return path;
}

}  // namespace

std::vector<SweepCase> casesOfShard(const std::vector<SweepCase>& cases, const Shard& shard) {
    std::vector<SweepCase> out;
    for (const SweepCase& c : cases)
        if (c.index % size_t(shard.count) == size_t(shard.index)) out.push_back(c);
    return out;
}

SweepSummary runSweep(const SweepSpec& spec, const SweepRunOptions& o) {
    auto log = [&](const std::string& line) {
        if (o.log) o.log(line);
    };
    if (o.outDir.empty()) throw UsageError("sweep: no output directory");
    const fs::path out(o.outDir);
    fs::create_directories(out / "cases");
    const std::vector<SweepCase> all = enumerateSweepCases(spec);
    json ids = json::array();
    for (const SweepCase& c : all) ids.push_back(c.id);
    // Every shard writes the same content; the temporary's name is unique per process, so
    // shards writing into one directory at once do not clobber each other's half-written file.
    const json sweepIndex = {{"name", spec.name}, {"spec", spec.specPath}, {"source", spec.source}, {"cases", ids}};
    writeTextFileAtomic((out / "sweep.json").string(), sweepIndex.dump(2) + "\n");

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
        SequenceSettings seq;
        try {
            if (c.camera.isPath()) {
                seq.path = casePath(c.camera.path, *scene);
                seq.frames = c.camera.path.frames;
                seq.perFrameSeeds = c.camera.path.perFrameSeeds;
                cs.base.camera = cameraOnPath(seq.path, seq.path.startTime(), *scene);  // frame 0's
            } else {
                CameraRequest cam;
                cam.nameOrIndex = c.camera.nameOrIndex;
                cam.hasEye = c.camera.hasEye;
                cam.eye = c.camera.eye;
                cam.target = c.camera.target;
                cam.fovDeg = c.camera.fovDeg;
                cs.base.camera = resolveCamera(*scene, cam, float(cs.base.width) / float(cs.base.height));
            }
        } catch (const UsageError& e) {
            throw UsageError("case " + c.id + ": " + e.what());
        }
        cs.referenceSpp = s.settings.referenceSpp;
        cs.timingRuns = s.settings.timingRuns;
        cs.variants = s.variants;
        cs.outputDir = dir.string();
        cs.writeImages = o.writeImages;
        if (o.progress) cs.progress = [&](const std::string& line) { o.progress(c.id + ": " + line); };
        fs::create_directories(dir);
        writeTextFileAtomic((dir / "case.json").string(), caseJson(spec, c).dump(2) + "\n");
        try {
            // Both write results.json last, by rename: the "done" mark.
            if (c.camera.isPath()) {
                seq.comparison = cs;
                checkSequenceSettings(seq);
                runSequenceComparison(*scene, seq);
            } else {
                runComparison(*scene, cs);
            }
        } catch (const UsageError& e) {
            throw UsageError("case " + c.id + ": " + e.what());
        } catch (const InternalError&) {
            throw;  // the program's fault, not the case's: keep its kind
        } catch (const std::exception& e) {
            throw std::runtime_error("case " + c.id + ": " + e.what());
        }
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f", seconds);
        const std::string frames =
            c.camera.isPath() ? " over " + std::to_string(c.camera.path.frames) + " frames" : std::string();
        log(head + "ran " + std::to_string(s.variants.size()) + " variants" + frames + " in " + secs + " s");
        ++summary.ran;
    }
    return summary;
}

}  // namespace vct
