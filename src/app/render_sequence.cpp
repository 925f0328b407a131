// `vct render --path P --frames N`: one session renders every frame (the scene's voxels, BVH
// and shadow maps are built once), each frame is written whole under its own number, and a
// manifest beside the frames lets a killed run resume with the frames it already wrote.
#include "app/render_options.h"
#include "app/render_sequence.h"

#include "core/errors.h"
#include "eval/provenance.h"
#include "eval/sequence_comparison.h"
#include "gl/context.h"
#include "render/render_spec.h"
#include "render/renderer.h"
#include "scene/camera_path.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"
#include "util/progress.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace vct {

namespace fs = std::filesystem;

CameraPath resolveCameraPath(const std::string& spec, const Scene& scene) {
    if (spec.rfind("gltf:", 0) == 0) {
        try {
            return cameraAnimationPath(scene, spec.substr(5));
        } catch (const std::invalid_argument& e) {
            throw UsageError("--path " + spec + ": " + e.what());
        }
    }
    if (!fs::exists(spec)) throw UsageError("--path " + spec + ": no such file (or gltf:NAME for a camera animation)");
    return loadCameraPath(spec);
}

std::string sequenceLightsExplanation(const std::string& animation) {
    return "lights move with animation '" + animation +
           "': on each frame they moved, the shadow maps, the direct light, and VCT's injection, bounces and "
           "radiance mips rerun; the voxels themselves are kept (a clipmap or the sparse backend's grids are "
           "rebuilt whole); the reference reads the moved lights, its BVH stays";
}

std::string sequenceGeometryExplanation(const std::string& animation) {
    return "objects move with animation '" + animation +
           "': on each frame they moved, the scene's triangles are uploaded again and everything built from them "
           "is rebuilt in full, not only the region they touched: the G-buffer, the shadow maps, VCT's "
           "voxelization, injection, bounces and mips (dense grid, clipmap or sparse grids alike) and the "
           "reference's BVH; the voxel region is fitted within the bounds the animation sweeps, so the lattice "
           "of the static geometry stays put";
}

SequenceFiles sequenceFiles(const std::string& output, int frames) {
    const fs::path out(output);
    SequenceFiles files;
    const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
    const std::string stem = out.stem().string(), ext = out.extension().string();
    for (int f = 0; f < frames; ++f) {
        char number[16];
        std::snprintf(number, sizeof number, "_%04d", f);
        files.frames.push_back((dir / (stem + number + ext)).string());
    }
    files.manifest = (dir / (stem + ".sequence.json")).string();
    files.video = (dir / (stem + ".mp4")).string();
    files.framePattern = (dir / (stem + "_%04d" + ext)).string();
    return files;
}

namespace {

bool isTerminal() { return isatty(STDERR_FILENO) != 0; }

// Everything that decides a frame's pixels but the frame number: two runs with the same
// manifest produce the same frames, so a resumed run may keep the frames already written.
nlohmann::json sequenceManifest(const RenderOptions& o, const CameraPath& path) {
    nlohmann::json m;
    m["scene"] = o.scenePath;
    m["scene_sha256"] = fileSha256(o.scenePath);
    m["commit"] = buildCommit();
    m["path"] = cameraPathToJson(path);
    m["frames"] = o.frames;
    m["frame_seeds"] = o.frameSeeds;
    m["request"] = {{"size", o.size},         {"camera", o.camera}, {"fov", o.fovDeg},   {"ao", o.ao},
                    {"gi", o.gi},             {"radius", o.radius}, {"spp", o.spp},       {"seed", o.seed},
                    {"voxel_res", o.voxelRes}, {"backend", o.backend}, {"aovs", o.aovs}, {"params", o.params},
                    {"sky", o.sky},           {"exposure", o.exposure}, {"prune", !o.noPrune}};
    return m;
}

// A killed run can leave a frame's temporary file (util/atomic_file.h's NAME.tmpPID_K.ext).
void removeStaleTemporaries(const std::string& frame) {
    const fs::path p(frame);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::exists(dir)) return;
    const std::string prefix = p.stem().string() + ".tmp";
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && e.path().filename().string().rfind(prefix, 0) == 0 &&
            e.path().extension() == p.extension())
            fs::remove(e.path());
}

bool ffmpegAvailable() { return std::system("command -v ffmpeg > /dev/null 2>&1") == 0; }

// PNG frames to an H.264 video at the path's own rate; written under a temporary name.
void writeVideo(const SequenceFiles& files, double fps) {
    const std::string tmp = temporaryPathFor(files.video);
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    const std::string cmd = "ffmpeg -y -loglevel error -framerate " + std::string(rate) + " -i '" +
                            files.framePattern + "' -c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' '" +
                            tmp + "'";
    if (std::system(cmd.c_str()) != 0) {
        std::remove(tmp.c_str());
        std::cerr << "vct: warning: ffmpeg failed; the frames are written, the video " << files.video << " is not\n";
        return;
    }
    fs::rename(tmp, files.video);
    std::cerr << "vct: wrote " << files.video << "\n";
}

}  // namespace

int runRenderSequence(const RenderOptions& o) {
    if (o.frames < 1 || o.frames > 100000) throw UsageError("--frames must be in [1, 100000]");
    if (o.frameSeeds != "per-frame" && o.frameSeeds != "fixed")
        throw UsageError("--frame-seeds " + o.frameSeeds + ": expected per-frame or fixed");
    if (!o.eye.empty() || !o.target.empty()) throw UsageError("--path sets the camera: leave out --eye and --target");
    Scene scene = loadScene(o.scenePath);
    for (const auto& w : scene.warnings) std::cerr << "vct: warning: " << o.scenePath << ": " << w << '\n';
    const CameraPath path = resolveCameraPath(o.path, scene);
    checkPathAnimation(path, scene);
    RenderRequest base = makeRenderRequest(o, scene);
    const std::string out = o.output;
    const bool png = out.size() >= 4 && out.substr(out.size() - 4) == ".png";
    const bool exr = out.size() >= 4 && out.substr(out.size() - 4) == ".exr";
    if (!png && !exr) throw UsageError("-o " + out + ": output must end in .png or .exr");

    const SequenceFiles files = sequenceFiles(out, o.frames);
    if (fs::path(out).has_parent_path()) fs::create_directories(fs::path(out).parent_path());
    const nlohmann::json manifest = sequenceManifest(o, path);
    if (fs::exists(files.manifest)) {
        nlohmann::json old;
        try {
            std::ifstream in(files.manifest);
            old = nlohmann::json::parse(in);
        } catch (const std::exception&) {
            old = nullptr;
        }
        if (old != manifest)
            throw UsageError(files.manifest + ": the frames there belong to another sequence (other settings, "
                             "scene, path or build); remove them or choose another -o");
    } else {
        writeTextFileAtomic(files.manifest, manifest.dump(2) + "\n");
    }

    const bool lightsMove = !path.animation.empty() && animationMovesLights(scene, path.animation);
    const bool geometryMoves = !path.animation.empty() && animationMovesGeometry(scene, path.animation);
    if (geometryMoves) scene.bounds = animationBounds(scene, path.animation);  // bounds that hold every pose
    GlContext::shared(parseGlDevice(o.glDevice));
    RenderSession session(scene);
    const std::vector<double> times = pathFrameTimes(path, o.frames);
    if (o.explain) {
        RenderRequest first = base;
        first.camera = cameraOnPath(path, times.front(), scene);
        std::cout << describePlan(planRender(session.features(), first))
                  << "sequence: " << o.frames << " frames along " << path.source
                  << "; one session: the scene's voxels, BVH and shadow maps are built on the first frame and "
                     "kept while the scene stands still; a voxel region fitted to the view "
                     "(vct.region=fit) is rebuilt whole when the view changes it, a clipmap whole when a "
                     "cascade's snapped origin moves\n"
                  << (lightsMove ? sequenceLightsExplanation(path.animation) + "\n" : std::string())
                  << (geometryMoves ? sequenceGeometryExplanation(path.animation) + "\n" : std::string())
                  << std::flush;
    }
    int kept = 0;
    for (const std::string& f : files.frames) kept += fs::exists(f) ? 1 : 0;
    std::cerr << "vct: " << o.scenePath << ": " << o.frames << " frames along " << path.source
              << (kept ? " (" + std::to_string(kept) + " already written, kept)" : std::string()) << "\n";
    ProgressBar progress("frames", uint64_t(o.frames), isTerminal());
    progress.advance(uint64_t(kept));
    nlohmann::json frameStats = nlohmann::json::array();
    for (int f = 0; f < o.frames; ++f) {
        const std::string& name = files.frames[size_t(f)];
        removeStaleTemporaries(name);
        if (fs::exists(name)) continue;
        poseSequenceFrame(session, scene, path.animation, times[size_t(f)]);
        RenderRequest r = base;
        r.camera = cameraOnPath(path, times[size_t(f)], scene);
        r.seed = o.frameSeeds == "fixed" ? base.seed : frameSeed(base.seed, f);
        RenderResult result = session.render(r);
        checkRenderResult(result);
        writeRenderOutput(name, result.aovs, r.aovs, o.exposure);
        frameStats.push_back({{"frame", f}, {"time", times[size_t(f)]}, {"total_ms", result.totalMs},
                              {"frame_ms", result.frameMs}});
        progress.advance(1);
    }
    if (!o.statsPath.empty())
        writeTextFileAtomic(o.statsPath, nlohmann::json({{"frames", frameStats}, {"manifest", manifest}}).dump(2) + "\n");
    std::cerr << "vct: wrote " << o.frames << " frames " << files.framePattern << "\n";
    if (png && o.frames > 1) {
        if (ffmpegAvailable()) {
            const double span = path.endTime() - path.startTime();
            const double fps = span > 0.0 ? std::clamp(double(o.frames - 1) / span, 1.0, 240.0) : 30.0;
            writeVideo(files, fps);
        } else {
            std::cerr << "vct: ffmpeg not installed: no video (the frames play in any image viewer)\n";
        }
    }
    return 0;
}

}  // namespace vct
