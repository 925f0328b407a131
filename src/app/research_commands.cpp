#include "app/commands.h"

#include "app/render_options.h"
#include "app/gallery_command.h"
#include "app/sweep_commands.h"
#include "core/errors.h"
#include "app/render_sequence.h"
#include "eval/comparison.h"
#include "eval/sequence_comparison.h"
#include "gl/context.h"
#include "methods/registry.h"
#include "render/renderer.h"
#include "core/params.h"
#include "render/plan.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"
#include "vdb/sparse_voxels.h"
#include "vdb/vdb_io.h"

#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace vct {

namespace {

// Every method of `kind` but the ground truth, comma-separated: what compare scores by default.
std::string defaultScoredMethods(MethodKind kind) {
    std::string list;
    for (const Method* m : scoredMethods(kind)) list += (list.empty() ? "" : ",") + m->name;
    return list;
}

struct CompareOptions {
    RenderOptions render;  // scene, camera, size, radius, seed, voxel-res, sky, params, gl-device
    std::string outDir;
    std::string aoMethods;  // default: defaultScoredMethods(AO), set when the command is registered
    std::string giMethods;
    int refSpp = 256;
    int runs = 3;
    std::string path;  // a camera path: compare every frame (eval/sequence_comparison.h)
    int frames = 0;
    std::string frameSeeds = "per-frame";
};

CompareOptions gCompare;
CLI::App* gCompareCmd = nullptr;

struct VoxelizeOptions {
    std::string scenePath;
    std::string output;
    int voxelRes = 128;
    float sky = 1.f;
    std::vector<std::string> params;
    std::string statsPath;
};
VoxelizeOptions gVoxelize;
CLI::App* gVoxelizeCmd = nullptr;

// `vct voxelize`: the sparse (OpenVDB) grids of a scene, written as a .vdb that Blender,
// Houdini and OpenVDB's tools open; radiance is injected when the scene has lights or
// emission.
int runVoxelize(const VoxelizeOptions& o) {
    if (o.output.size() < 4 || o.output.substr(o.output.size() - 4) != ".vdb")
        throw UsageError("-o " + o.output + ": output must end in .vdb");
    if (o.voxelRes < kMinVoxelRes || o.voxelRes > kMaxVoxelRes)
        throw UsageError("--voxel-res must be in [" + std::to_string(kMinVoxelRes) + ", " +
                         std::to_string(kMaxVoxelRes) + "]");
    Scene scene = loadScene(o.scenePath);
    ParamMap params;
    for (const auto& p : o.params) params.set(p);
    const SceneFeatures f = analyzeScene(scene);
    SparseVoxelScene sv = buildSparseVoxels(scene, o.voxelRes, f.lights > 0 || f.hasEmission, o.sky, params);
    auto unused = params.unusedKeys();
    if (!unused.empty()) throw UsageError("--param " + unused.front() + ": unknown parameter");
    std::string name = scene.path.substr(scene.path.find_last_of('/') + 1);
    writeVdb(sv, o.output, name);
    const auto& s = sv.stats;
    nlohmann::json j{{"scene", o.scenePath}, {"resolution", {sv.resolution.x, sv.resolution.y, sv.resolution.z}},
                     {"voxel_size", sv.voxelSize}, {"active_voxels", s.activeVoxels},
                     {"memory_bytes", s.memoryBytes}, {"dense_bytes", s.denseBytes},
                     {"dense_cube_bytes", s.denseCubeBytes}, {"voxelize_s", s.voxelizeSeconds},
                     {"inject_s", s.injectSeconds}, {"levels_s", s.levelsSeconds}};
    std::cout << "wrote " << o.output << ": " << s.activeVoxels << " active voxels, " << s.memoryBytes
              << " bytes (dense equivalent " << s.denseBytes << ")\n";
    if (!o.statsPath.empty()) writeTextFileAtomic(o.statsPath, j.dump(2) + "\n");
    return 0;
}

// Options that `render` and the research commands share.
void addViewOptions(CLI::App* cmd, RenderOptions& o) {
    cmd->add_option("--size", o.size, "image size W or WxH")->capture_default_str();
    cmd->add_option("--camera", o.camera, "camera NAME or INDEX from the file");
    cmd->add_option("--eye", o.eye, "camera position X,Y,Z (with --target)");
    cmd->add_option("--target", o.target, "camera target X,Y,Z (with --eye)");
    cmd->add_option("--fov", o.fovDeg, "vertical field of view in degrees")->capture_default_str();
    cmd->add_option("--radius", o.radius, "AO radius R in world units")->capture_default_str();
    cmd->add_option("--seed", o.seed, "seed of every random choice")->capture_default_str();
    cmd->add_option("--voxel-res", o.voxelRes, "voxels along the grid's longest axis")->capture_default_str();
    cmd->add_option("--sky", o.sky, "uniform sky radiance")->capture_default_str();
    cmd->add_option("--param", o.params, "parameter KEY=VALUE shared by every method (repeatable)");
    cmd->add_option("--gl-device", o.glDevice, "auto, surfaceless or device")->capture_default_str();
}

void progressLine(const std::string& line) {
    if (isatty(STDERR_FILENO)) std::cerr << "vct compare: " << line << "\n";
}

// `vct compare --path P --frames N`: the table of eval/sequence_comparison.h.
int runSequenceCompare(const CompareOptions& o, const Scene& scene, const ComparisonSettings& s) {
    SequenceSettings seq;
    seq.comparison = s;
    seq.path = resolveCameraPath(o.path, scene);
    checkPathAnimation(seq.path, scene);
    seq.frames = o.frames;
    if (o.frameSeeds != "per-frame" && o.frameSeeds != "fixed")
        throw UsageError("--frame-seeds " + o.frameSeeds + ": expected per-frame or fixed");
    seq.perFrameSeeds = o.frameSeeds == "per-frame";
    checkSequenceSettings(seq);
    GlContext::shared(parseGlDevice(o.render.glDevice));
    nlohmann::json doc = runSequenceComparison(scene, seq);
    std::cout << "label                                  frame_ms    time_ms  rmse_mean rmse_worst instability  change\n";
    for (const auto& r : doc["records"]) {
        char line[320];
        std::snprintf(line, sizeof line, "%-36s %10.2f %10.2f %10.4f %10.4f %11.4f %7.4f\n",
                      r["label"].get<std::string>().c_str(), r["frame_ms"].get<double>(), r["time_ms"].get<double>(),
                      r["rmse_mean"].get<double>(), r["rmse_worst"].get<double>(), r["instability"].get<double>(),
                      r["temporal"]["change_rms"].get<double>());
        std::cout << line;
    }
    const nlohmann::json& ref = doc["reference"];
    for (const char* k : {"ao_temporal", "gi_temporal"})
        if (ref.contains(k))
            std::cout << "reference " << std::string(k).substr(0, 2) << ": instability " << ref[k]["instability"].get<double>()
                      << " (its change " << ref[k]["change_rms"].get<double>() << ", noise "
                      << ref[k]["reference_noise_rms"].get<double>() << ")\n";
    std::cout << "wrote " << o.outDir << "/results.json and results.csv\n";
    return 0;
}

int runCompare(const CompareOptions& o) {
    if (o.path.empty() != (o.frames == 0)) throw UsageError("--path and --frames go together");
    Scene scene = loadScene(o.render.scenePath);
    ComparisonSettings s;
    s.base = makeRenderRequest(o.render, scene);
    s.referenceSpp = o.refSpp;
    s.timingRuns = o.runs;
    s.outputDir = o.outDir;
    s.variants = parseMethodList(o.aoMethods, "ao");
    auto gi = parseMethodList(o.giMethods, "gi");
    s.variants.insert(s.variants.end(), gi.begin(), gi.end());
    checkComparisonSettings(s);
    s.progress = progressLine;
    if (!o.path.empty()) return runSequenceCompare(o, scene, s);
    GlContext::shared(parseGlDevice(o.render.glDevice));
    nlohmann::json doc = runComparison(scene, s);
    std::cout << "label                                   time_ms   frame_ms     rmse   roi_rmse  cone_err  voxel_err\n";
    auto cell = [](const nlohmann::json& j) { return j.is_null() ? std::string("-") : std::to_string(j.get<double>()); };
    for (const auto& r : doc["records"]) {
        char line[320];
        std::snprintf(line, sizeof line, "%-36s %10.2f %10.2f %8.4f %10s %9s %10s\n", r["label"].get<std::string>().c_str(),
                      r["time_ms"].get<double>(), r["frame_ms"].get<double>(), r["rmse"].get<double>(), cell(r["roi_rmse"]).c_str(),
                      cell(r["cone_error_rmse"]).c_str(), cell(r["voxel_error_rmse"]).c_str());
        std::cout << line;
    }
    std::cout << "wrote " << o.outDir << "/results.json and results.csv\n";
    return 0;
}

}  // namespace

void registerResearchCommands(CLI::App& app) {
    registerSweepCommands(app);
    registerGalleryCommand(app);
    CompareOptions& o = gCompare;
    o.aoMethods = defaultScoredMethods(MethodKind::AO);
    gCompareCmd = app.add_subcommand("compare", "Score methods against the ray-traced reference on one view");
    gCompareCmd->add_option("scene", o.render.scenePath, "glTF 2.0 scene")->required();
    gCompareCmd->add_option("-o,--output", o.outDir, "output directory (images, results.json, results.csv)")
        ->required();
    gCompareCmd->add_option("--methods", o.aoMethods,
                            "AO methods, comma-separated; parameters in brackets: gtao[gtao.preset=low;blur=0]")
        ->capture_default_str();
    gCompareCmd->add_option("--gi", o.giMethods, "GI methods to score against the path tracer (e.g. vct)");
    gCompareCmd->add_option("--ref-spp", o.refSpp, "reference samples per pixel")->capture_default_str();
    gCompareCmd->add_option("--runs", o.runs, "timed runs after a warm-up (time_ms, the cold cost, and frame_ms, the next frame's, are their medians)")
        ->capture_default_str();
    gCompareCmd->add_option("--path", o.path, "camera path file or gltf:NAME|INDEX: compare every frame (with --frames)");
    gCompareCmd->add_option("--frames", o.frames, "frames along --path");
    gCompareCmd->add_option("--frame-seeds", o.frameSeeds,
                            "the methods' seeds: per-frame (each frame its own) or fixed (the reference is always per-frame)")
        ->capture_default_str();
    addViewOptions(gCompareCmd, o.render);

    VoxelizeOptions& v = gVoxelize;
    gVoxelizeCmd = app.add_subcommand("voxelize", "Voxelize a scene into sparse OpenVDB grids (.vdb)");
    gVoxelizeCmd->add_option("scene", v.scenePath, "glTF 2.0 scene")->required();
    gVoxelizeCmd->add_option("-o,--output", v.output, "output .vdb file")->required();
    gVoxelizeCmd->add_option("--voxel-res", v.voxelRes, "voxels along the longest axis")->capture_default_str();
    gVoxelizeCmd->add_option("--sky", v.sky, "uniform sky radiance")->capture_default_str();
    gVoxelizeCmd->add_option("--param", v.params, "parameter KEY=VALUE (vct.inject.offset, ...)");
    gVoxelizeCmd->add_option("--stats", v.statsPath, "write voxel counts, memory and times as JSON");
}

int runResearchCommand(CLI::App& app) {
    if (int rc = runSweepCommand(app); rc != -1) return rc;
    if (int rc = runGalleryCommand(app); rc >= 0) return rc;
    if (gCompareCmd && *gCompareCmd) return runCompare(gCompare);
    if (gVoxelizeCmd && *gVoxelizeCmd) return runVoxelize(gVoxelize);
    return 2;
}

std::string paramsHelpText() {
    std::vector<SettingDoc> docs = allSettingDocs();
    std::sort(docs.begin(), docs.end(), [](const SettingDoc& a, const SettingDoc& b) { return a.key < b.key; });
    std::ostringstream out;
    out << "--param keys (KEY=VALUE):\n";
    for (const SettingDoc& d : docs)
        out << "  " << d.key << "  default " << d.defaultValue << "  range " << d.range
            << (d.doc.empty() ? "" : "  " + d.doc) << "\n";
    return out.str();
}

}  // namespace vct
