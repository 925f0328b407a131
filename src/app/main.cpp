// vct: the headless command line. Parses options with CLI11 into option structs and hands
// them to the commands in src/app; exit codes: 0 success, 1 runtime failure (bad scene,
// GL error) or internal error, 2 usage (unknown option, malformed or out-of-range value,
// unimplemented); see app/exit_codes.h.
#include "app/commands.h"
#include "app/exit_codes.h"
#include "app/render_options.h"
#include "core/errors.h"
#include "methods/registry.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <stdexcept>

namespace {

std::string methodsHelp(const std::vector<std::string>& m) {
    std::string s;
    for (const auto& x : m) s += (s.empty() ? "" : ", ") + x;
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace vct;
    CLI::App app{"vct: voxel cone tracing, screen-space AO and a ray-traced reference, scored against each other"};
    app.require_subcommand(1);
    // Parse errors are usage errors: the same prefix as those the commands throw.
    app.failure_message(
        [](const CLI::App* a, const CLI::Error& e) { return "vct: error: " + CLI::FailureMessage::simple(a, e); });
    app.set_help_all_flag("--help-all", "Show help for every subcommand");

    RenderOptions ro;
    bool helpParams = false;
    CLI::App* render = app.add_subcommand("render", "Render a glTF scene to PNG or EXR");
    render->add_option("scene", ro.scenePath, "glTF 2.0 scene (.gltf or .glb)")->required();
    render->add_option("-o,--output", ro.output, "output image (.png: 8-bit sRGB; .exr: linear float AOVs)")
        ->capture_default_str();
    render->add_option("--size", ro.size, "image size W or WxH")->capture_default_str();
    render->add_option("--camera", ro.camera, "camera NAME or INDEX from the file (default: first, else a framing)");
    render->add_option("--eye", ro.eye, "camera position X,Y,Z (with --target)");
    render->add_option("--target", ro.target, "camera target X,Y,Z (with --eye)");
    render->add_option("--fov", ro.fovDeg, "vertical field of view in degrees (with --eye, or the default framing)")
        ->capture_default_str()->check(CLI::Range(0.01f, 179.9f));
    render->add_option("--ao", ro.ao, "AO method: " + methodsHelp(methodNames(MethodKind::AO)))->capture_default_str();
    render->add_option("--gi", ro.gi, "GI method: " + methodsHelp(methodNames(MethodKind::GI)))->capture_default_str();
    render->add_option("--radius", ro.radius, "AO radius R in world units (shared by every AO method)")
        ->capture_default_str();
    render->add_option("--spp", ro.spp, "reference samples per pixel")->capture_default_str();
    render->add_option("--seed", ro.seed, "seed of every random choice")->capture_default_str();
    render->add_option("--voxel-res", ro.voxelRes, "voxels along the grid's longest axis")->capture_default_str();
    render->add_option("--backend", ro.backend, "voxel backend: gl (dense GPU) or vdb (sparse CPU)")
        ->capture_default_str();
    render->add_option("--aov", ro.aovs,
                       "outputs, comma-separated: beauty, ao, direct, indirect, normal, depth, albedo, position, "
                       "emission, ao_stderr, indirect_stderr, voxel_albedo, voxel_radiance, voxel_opacity");
    render->add_option("--param", ro.params, "method parameter KEY=VALUE (repeatable; see --help-params)");
    render->add_option("--sky", ro.sky, "uniform sky radiance")->capture_default_str();
    render->add_option("--exposure", ro.exposure, "exposure in stops for PNG output")->capture_default_str();
    render->add_option("--stats", ro.statsPath, "write timings and plan as JSON");
    render->add_flag("--explain", ro.explain, "print the pass plan: what runs and why, what is left out and why");
    render->add_flag("--no-prune", ro.noPrune, "run every applicable pass even if nothing reads its output");
    render->add_option("--gl-device", ro.glDevice, "auto, surfaceless (Mesa, no GPU) or device (EGL device)")
        ->capture_default_str();
    render->add_option("--path", ro.path,
                       "camera path: a JSON file of keyframes (docs/sequences.md) or gltf:NAME|INDEX, a camera "
                       "animation of the scene; with --frames");
    render->add_option("--frames", ro.frames, "frames along --path: writes NAME_0000.ext ... beside -o");
    render->add_option("--frame-seeds", ro.frameSeeds,
                       "per-frame (each frame its own seed) or fixed (every frame --seed)")
        ->capture_default_str();
    render->add_flag("--help-params", helpParams, "list every --param key with its default and range");

    std::string infoScene, infoDevice = "auto";
    CLI::App* info = app.add_subcommand("info", "Describe a scene and the GL renderer");
    info->add_option("scene", infoScene, "glTF 2.0 scene")->required();
    info->add_option("--gl-device", infoDevice, "auto, surfaceless or device")->capture_default_str();

    registerResearchCommands(app);

    // --help-params works without a scene.
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--help-params") {
            std::cout << paramsHelpText();
            return 0;
        }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        if (*render) {
            if (ro.path.empty() != (ro.frames == 0)) throw UsageError("--path and --frames go together");
            return ro.path.empty() ? runRender(ro) : runRenderSequence(ro);
        }
        if (*info) return runInfo(infoScene, infoDevice);
        return runResearchCommand(app);
    } catch (const std::exception& e) {
        std::cerr << errorLineFor(e) << "\n";
        return exitCodeFor(e);
    }
}
