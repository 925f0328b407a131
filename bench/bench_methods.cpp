// Error against time for every AO method (and VCT GI) on one view: prints one table with
// the GL renderer string. Default: 512x512, the Cornell box and, when present,
// ../shared/scenes/floor_suzanne.glb, R = 0.5, reference 256 spp.
//   bench_methods [--size N] [--spp N] [--runs N] [--scene PATH]...
#include "bench_main.h"
#include "eval/comparison.h"
#include "gl/context.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

using namespace vct;

static int benchRun(int argc, char** argv) {
    int size = 512, spp = 256, runs = 3;
    std::vector<std::string> scenes;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string a = argv[i];
        if (a == "--size") size = std::atoi(argv[i + 1]);
        else if (a == "--spp") spp = std::atoi(argv[i + 1]);
        else if (a == "--runs") runs = std::atoi(argv[i + 1]);
        else if (a == "--scene") scenes.push_back(argv[i + 1]);
    }
    if (scenes.empty()) {
        scenes.push_back(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf");
        const char* env = std::getenv("VCT_SHARED_SCENES");
        std::string shared = env ? env : std::string(VCT_SOURCE_DIR) + "/../shared/scenes";
        if (std::filesystem::exists(shared + "/floor_suzanne.glb")) scenes.push_back(shared + "/floor_suzanne.glb");
        else std::cerr << "floor_suzanne.glb not found in " << shared << ": skipped\n";
    }
    std::printf("renderer: %s, %u cores, %dx%d, reference %d spp, median of %d runs after a warm-up\n",
                GlContext::shared().info().renderer.c_str(), std::thread::hardware_concurrency(), size, size, spp, runs);
    for (const auto& path : scenes) {
        Scene scene = loadScene(path);
        ComparisonSettings cs;
        cs.base.width = cs.base.height = size;
        cs.base.camera = resolveCamera(scene, CameraRequest{}, 1.f);
        cs.base.radius = 0.5f;
        cs.base.voxelRes = 128;
        cs.referenceSpp = spp;
        cs.timingRuns = runs;
        cs.variants = parseMethodList("ssao-crytek,ssao-hemisphere,ssao-horizon,alchemy,hbao,gtao[gtao.preset=low],"
                                      "gtao[gtao.preset=medium],gtao,gtao[gtao.preset=ultra],vct",
                                      "ao");
        if (!scene.lights.empty() || path.find("cornell") != std::string::npos) {
            auto gi = parseMethodList("vct", "gi");
            cs.variants.insert(cs.variants.end(), gi.begin(), gi.end());
        }
        nlohmann::json doc = runComparison(scene, cs);
        std::printf("\n%s  (R = 0.5, reference AO stderr per pixel %.4f", path.c_str(),
                    doc["reference"].value("ao_rms_pixel_stderr", 0.0));
        if (doc["reference"].contains("gi_rms_pixel_stderr"))
            std::printf(", GI stderr per pixel %.4f", doc["reference"]["gi_rms_pixel_stderr"].get<double>());
        std::printf(")\n%-28s %4s %10s %9s %9s %9s %7s\n", "method", "kind", "time_ms", "rmse", "mae", "bias", "ssim");
        for (const auto& r : doc["records"])
            std::printf("%-28s %4s %10.2f %9.4f %9.4f %9.4f %7.4f\n", r["label"].get<std::string>().c_str(),
                        r["kind"].get<std::string>().c_str(), r["time_ms"].get<double>(), r["rmse"].get<double>(),
                        r["mae"].get<double>(), r["bias"].get<double>(), r["ssim"].get<double>());
    }
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_methods", benchRun, argc, argv); }
