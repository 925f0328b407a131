// VCT's indirect light on the Cornell box, surface by surface, against the path tracer with
// the same number of reflections (reference.bounces = vct.bounces + 2, cone_bounce.h): the
// mean indirect light of the floor, the ceiling, the left, right and back walls and the whole
// image, as a deviation from the path tracer's, with the path tracer's standard error of each
// mean, and the RMSE over the peak, per voxel resolution. A surface is the set of pixels whose
// G-buffer normal faces into the box from that wall and whose position lies on it (the boxes'
// faces are left out). --images writes each image (and the path tracer's) as PNG, to look for
// streaks and leaks. --cone-model adds a first row, "cones": the path tracer's cone model of
// VCT's cone set (reference.cone-model, every reflection gathered over the cone set's caps),
// what VCT converges to as its voxels refine; its deviation is the cone error, and VCT's
// distance from it the voxel error.
//
//   bench_cornell_gi [--res 32,64,128] [--size 96] [--spp 1024] [--param KEY=VALUE ...]
//                    [--images DIR] [--scene FILE] [--cone-model]
#include "bench_main.h"
#include "cone/cone_bounce.h"
#include "eval/image_io.h"
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

using namespace vct;

namespace {

struct Surface {
    const char* name;
    int axis;       // the wall's normal axis
    float inward;   // the sign of the normal that faces into the box
    float plane;    // the wall's coordinate on that axis
};

// scenes/cornell_box.gltf: the box [-1, 1] x [0, 2] x [-1, 1], open towards +z.
const Surface kSurfaces[] = {{"floor", 1, 1.f, 0.f},
                             {"ceiling", 1, -1.f, 2.f},
                             {"left", 0, 1.f, -1.f},
                             {"right", 0, -1.f, 1.f},
                             {"back", 2, 1.f, -1.f}};

bool onSurface(const Surface& s, const Image& normal, const Image& position, size_t i) {
    return normal.pixels[i * 3 + size_t(s.axis)] * s.inward > 0.9f &&
           std::abs(position.pixels[i * 3 + size_t(s.axis)] - s.plane) < 0.02f;
}

}  // namespace

static int benchRun(int argc, char** argv) {
    CLI::App app{"VCT GI on the Cornell box per surface against the bounce-matched path tracer"};
    std::string resList = "32,64,128", images, scenePath = std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf";
    int size = 96, spp = 1024;
    std::vector<std::string> params;
    app.add_option("--res", resList, "voxel resolutions, comma-separated")->capture_default_str();
    app.add_option("--size", size, "image size")->capture_default_str();
    app.add_option("--spp", spp, "path tracer samples per pixel")->capture_default_str();
    app.add_option("--param", params, "KEY=VALUE for VCT (repeatable)");
    app.add_option("--images", images, "write the images as PNG into this directory");
    bool coneModel = false;
    app.add_flag("--cone-model", coneModel, "also score the path tracer's cone model of VCT's cone set (the cone error)");
    app.add_option("--scene", scenePath, "the Cornell box or a variant of it (its walls where they are: other lights, "
                                         "materials or boxes)");
    CLI11_PARSE(app, argc, argv);
    std::vector<int> resolutions;
    std::stringstream ss(resList);
    for (std::string item; std::getline(ss, item, ',');) resolutions.push_back(std::stoi(item));

    const Scene scene = loadScene(scenePath);
    RenderSession session(scene);
    RenderRequest base;
    base.width = base.height = size;
    base.camera = resolveCamera(scene, CameraRequest{}, 1.f);
    base.sky = 0.f;
    for (const auto& p : params) base.params.set(p);
    const int bounces = readVctBounces(base.params);

    RenderRequest ref = base;
    ref.gi = "reference";
    ref.spp = spp;
    if (!ref.params.has("reference.bounces")) ref.params.set("reference.bounces", std::to_string(bounces + 2));
    const int reflections = std::stoi(ref.params.values().at("reference.bounces"));
    ref.aovs = {"indirect", "indirect_stderr", "normal", "position"};
    const RenderResult truth = session.render(ref);
    const Image& indirect = truth.aovs.at("indirect");
    const Image L = channelMean(indirect);
    const Image& se = truth.aovs.at("indirect_stderr");  // of the channel mean
    const Image& normal = truth.aovs.at("normal");
    const Image& position = truth.aovs.at("position");
    const size_t n = size_t(size) * size_t(size);
    const double peak = *std::max_element(L.pixels.begin(), L.pixels.end());

    std::printf("Cornell box, %dx%d, sky 0, VCT %d bounce(s) against the path tracer with %d reflections at %d spp\n",
                size, size, bounces, reflections, spp);
    std::printf("mean indirect light, VCT against the path tracer (+-: two of its standard errors)\n");
    std::printf("%-6s %16s", "res", "image");
    for (const Surface& s : kSurfaces) std::printf(" %16s", s.name);
    std::printf(" %10s\n", "rmse/peak");
    if (!images.empty()) {
        std::filesystem::create_directories(images);
        writeImage(images + "/cornell_gi_reference.png", toneMapToSrgb(indirect));
    }
    // One row: an image's mean indirect light per surface against the path tracer's.
    auto printRow = [&](const std::string& label, const Image& V) {
        auto deviation = [&](const Surface* s) {
            double sv = 0.0, sl = 0.0, var = 0.0;
            for (size_t i = 0; i < n; ++i) {
                if (s && !onSurface(*s, normal, position, i)) continue;
                sv += V.pixels[i];
                sl += L.pixels[i];
                var += double(se.pixels[i]) * double(se.pixels[i]);
            }
            char buf[64];
            if (!(sl > 0.0))  // the path tracer finds no light there: no relative deviation
                std::snprintf(buf, sizeof buf, "VCT %.3g, PT 0", sv);
            else
                std::snprintf(buf, sizeof buf, "%+6.1f%% +-%4.1f%%", 100.0 * (sv / sl - 1.0), 200.0 * std::sqrt(var) / sl);
            return std::string(buf);
        };
        std::printf("%-6s %16s", label.c_str(), deviation(nullptr).c_str());
        for (const Surface& s : kSurfaces) std::printf(" %16s", deviation(&s).c_str());
        std::printf(" %10.4f\n", computeErrorMetrics(V, L).rmse / peak);
        std::fflush(stdout);
    };
    if (coneModel) {
        RenderRequest cm = ref;
        cm.seed = ref.seed + 1;  // its own noise, not the truth's
        cm.params.set("reference.cone-model", "1");
        cm.aovs = {"indirect"};
        const Image model = session.render(cm).aovs.at("indirect");
        printRow("cones", channelMean(model));
        if (!images.empty()) writeImage(images + "/cornell_gi_cone_model.png", toneMapToSrgb(model));
    }
    for (int res : resolutions) {
        RenderRequest r = base;
        r.gi = "vct";
        r.voxelRes = res;
        r.aovs = {"indirect"};
        const Image vct = session.render(r).aovs.at("indirect");
        printRow(std::to_string(res) + "^3", channelMean(vct));
        if (!images.empty()) writeImage(images + "/cornell_gi_vct_" + std::to_string(res) + ".png", toneMapToSrgb(vct));
    }
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_cornell_gi", benchRun, argc, argv); }
