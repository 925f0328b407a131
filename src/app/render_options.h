// `vct render` options in one struct with initializers (pbrt's Options): the CLI fills
// it, the usage text shows its defaults, and the resolved values are logged.
#pragma once

#include "image/image.h"
#include "core/request.h"
#include "scene/camera.h"

#include <map>
#include <string>
#include <vector>

namespace vct {

struct RenderOptions {
    std::string scenePath;
    std::string output = "out/render.png";
    std::string size = "256";              // W or WxH
    std::string camera;                    // NAME or INDEX
    std::string eye, target;               // "x,y,z"
    float fovDeg = 45.f;
    std::string ao = "none";
    std::string gi = "none";
    float radius = 1.f;
    int spp = 64;
    uint64_t seed = 0;
    int voxelRes = 128;
    std::string backend = "gl";
    std::string aovs;                      // comma-separated; empty = beauty
    std::vector<std::string> params;       // KEY=VALUE
    float sky = 1.f;
    float exposure = 0.f;                  // stops, PNG only
    std::string statsPath;
    bool explain = false;
    bool noPrune = false;
    std::string glDevice = "auto";
    // A sequence (app/render_sequence.cpp): a camera path file, or gltf:NAME|INDEX for one of
    // the scene's camera animations, sampled at `frames` evenly spaced times.
    std::string path;
    int frames = 0;                        // 0: a still image
    std::string frameSeeds = "per-frame";  // per-frame: frame f uses frameSeed(seed, f); fixed: seed
};

// Parses the option strings into a RenderSpec and checks it with the renderer's
// makeRenderRequest (render/render_spec.h, which the Python module calls too); throws
// UsageError naming the option for malformed values (exit code 2).
RenderRequest makeRenderRequest(const RenderOptions& o, const Scene& scene);
void parseSize(const std::string& text, int& width, int& height);
std::vector<std::string> splitList(const std::string& text);

// Writes the requested AOVs: EXR with every AOV as named channels (linear), PNG with the
// beauty image or the single requested AOV (8-bit sRGB; see README). Temp name + rename.
void writeRenderOutput(const std::string& path, const std::map<std::string, Image>& aovs,
                       const std::vector<std::string>& order, float exposure);

int runRender(const RenderOptions& o);
// `vct render --path P --frames N`: numbered frames beside -o (NAME_0000.png, ...), each written
// atomically; frames already there from the same sequence (NAME.sequence.json says which) are
// kept, so a killed run resumes; a video NAME.mp4 when ffmpeg is installed (PNG frames).
int runRenderSequence(const RenderOptions& o);
int runInfo(const std::string& scenePath, const std::string& glDevice);

}  // namespace vct
