// vct-scenegen OUTDIR: writes every project scene (src/scene/scene_library.h) as OUTDIR/<name>.gltf,
// JSON with the buffer embedded as base64, after checking that it loads back.
#include "scene/gltf_loader.h"
#include "scene/scene_library.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
    const std::string arg = argc == 2 ? argv[1] : "";
    if (arg == "-h" || arg == "--help") {
        std::printf("usage: %s OUTDIR\n  writes OUTDIR/<name>.gltf for every project scene\n", argv[0]);
        return 0;
    }
    // An option is not a directory: "--help/" or "-o/" would be created and filled.
    if (argc != 2 || arg.empty() || arg[0] == '-') {
        std::fprintf(stderr, "usage: %s OUTDIR\n  writes OUTDIR/<name>.gltf for every project scene\n",
                     argv[0]);
        return 2;
    }
    const std::filesystem::path outDir = argv[1];
    try {
        std::filesystem::create_directories(outDir);
        for (const std::string& name : vct::projectSceneNames()) {
            const std::string path = (outDir / (name + ".gltf")).string();
            vct::makeProjectScene(name).write(path);
            const vct::Scene scene = vct::loadScene(path);  // the file must load as the library built it
            std::printf("%-24s %6zu triangles %2zu lights %zu cameras -> %s\n", name.c_str(),
                        scene.triangleCount(), scene.lights.size(), scene.cameras.size(), path.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vct-scenegen: %s\n", e.what());
        return 1;
    }
    return 0;
}
