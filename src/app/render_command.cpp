#include "app/render_options.h"

#include "core/errors.h"
#include "eval/image_io.h"
#include "gl/context.h"
#include "gl/program_limits.h"
#include "methods/registry.h"
#include "render/render_spec.h"
#include "render/renderer.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace vct {

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

void parseSize(const std::string& text, int& width, int& height) {
    auto parseInt = [&](const std::string& s) {
        size_t used = 0;
        int v = 0;
        try { v = std::stoi(s, &used); } catch (...) { used = 0; }
        if (used != s.size() || s.empty() || v < 1 || v > 16384)
            throw UsageError("--size '" + text + "': expected W or WxH with sides in [1, 16384]");
        return v;
    };
    size_t x = text.find('x');
    if (x == std::string::npos) { width = height = parseInt(text); return; }
    width = parseInt(text.substr(0, x));
    height = parseInt(text.substr(x + 1));
}

RenderRequest makeRenderRequest(const RenderOptions& o, const Scene& scene) {
    RenderSpec spec;
    parseSize(o.size, spec.width, spec.height);
    spec.ao = o.ao;
    spec.gi = o.gi;
    spec.radius = o.radius;
    spec.sky = o.sky;
    spec.spp = o.spp;
    spec.seed = o.seed;
    spec.voxelRes = o.voxelRes;
    spec.backend = o.backend;
    spec.prune = !o.noPrune;
    spec.aovs = splitList(o.aovs);
    spec.params = o.params;
    spec.camera.nameOrIndex = o.camera;
    spec.camera.fovDeg = o.fovDeg;
    if (!o.eye.empty() || !o.target.empty()) {
        if (o.eye.empty() || o.target.empty()) throw UsageError("--eye and --target go together");
        spec.camera.hasEye = true;
        spec.camera.eye = parseVec3(o.eye);
        spec.camera.target = parseVec3(o.target);
    }
    return makeRenderRequest(spec, scene);
}

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    std::string tail = s.substr(s.size() - suffix.size());
    std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
    return tail == suffix;
}

// How one AOV becomes 8-bit: radiance through exposure and sRGB; fractions (ao, opacity)
// and albedo as stored; normals as 0.5 + 0.5 n; depth and position scaled to their range.
Image displayable(const std::string& aov, const Image& img, float exposure) {
    if (aov == "beauty" || aov == "direct" || aov == "indirect" || aov == "emission" || aov == "voxel_radiance")
        return toneMapToSrgb(img, exposure);
    Image out = img;
    if (aov == "normal") {
        for (float& v : out.pixels) v = 0.5f + 0.5f * v;
    } else if (aov == "depth" || aov == "position" || aov == "ao_stderr" || aov == "indirect_stderr") {
        float lo = 1e30f, hi = -1e30f;
        for (float v : img.pixels) { lo = std::min(lo, v); hi = std::max(hi, v); }
        float span = hi > lo ? hi - lo : 1.f;
        for (float& v : out.pixels) v = (v - lo) / span;
    } else if (aov == "albedo" || aov == "voxel_albedo") {
        return toneMapToSrgb(img, 0.f);
    }
    for (float& v : out.pixels) v = std::clamp(v, 0.f, 1.f);
    return out;
}

}  // namespace

void writeRenderOutput(const std::string& path, const std::map<std::string, Image>& aovs,
                       const std::vector<std::string>& order, float exposure) {
    if (endsWith(path, ".exr")) {
        const Image& first = aovs.at(order.front());
        int channels = 0;
        for (const auto& name : order) channels += aovs.at(name).channels;
        Image all(first.width, first.height, channels);
        std::vector<std::string> names;
        int c0 = 0;
        for (const auto& name : order) {
            const Image& img = aovs.at(name);
            static const char* rgb[3] = {"R", "G", "B"};
            for (int c = 0; c < img.channels; ++c) {
                if (img.channels == 1) names.push_back(name);
                else names.push_back(name == "beauty" ? std::string(rgb[c]) : name + "." + rgb[c]);
            }
            for (size_t p = 0; p < size_t(img.width) * img.height; ++p)
                for (int c = 0; c < img.channels; ++c) all.pixels[p * channels + c0 + c] = img.pixels[p * img.channels + c];
            c0 += img.channels;
        }
        writeImage(path, all, names);
    } else if (endsWith(path, ".png")) {
        std::string which;
        if (order.size() == 1) which = order.front();
        else if (aovs.count("beauty")) which = "beauty";
        else throw UsageError(path + ": a PNG holds one AOV; request one --aov or write .exr");
        writeImage(path, displayable(which, aovs.at(which), exposure));
    } else {
        throw InternalError("writeRenderOutput", path + ": output must end in .png or .exr");
    }
}

int runRender(const RenderOptions& o) {
    Scene scene = loadScene(o.scenePath);
    for (const auto& w : scene.warnings) std::cerr << "vct: warning: " << o.scenePath << ": " << w << '\n';
    RenderRequest request = makeRenderRequest(o, scene);
    // Validate the output name before any work.
    if (!endsWith(o.output, ".png") && !endsWith(o.output, ".exr"))
        throw UsageError("-o " + o.output + ": output must end in .png or .exr");
    // Tone mapping checks it too, but only after the render and as the program's own contract.
    if (!std::isfinite(o.exposure)) throw UsageError("--exposure must be finite");

    GlContext::shared(parseGlDevice(o.glDevice));
    RenderSession session(scene);
    if (o.explain) std::cout << describePlan(planRender(session.features(), request)) << std::flush;
    const Camera& c = request.camera;
    std::cerr << "vct: " << o.scenePath << " (" << scene.triangles.size() << " triangles) " << request.width << "x"
              << request.height << " ao=" << request.ao << " gi=" << request.gi << " R=" << request.radius
              << " seed=" << request.seed << " eye=(" << c.eye.x << "," << c.eye.y << "," << c.eye.z << ") target=("
              << c.target.x << "," << c.target.y << "," << c.target.z << ") fov=" << glm::degrees(c.yfov) << "\n";
    RenderResult result = session.render(request);
    checkRenderResult(result);

    std::filesystem::path out(o.output);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    writeRenderOutput(o.output, result.aovs, request.aovs, o.exposure);
    if (!o.statsPath.empty()) writeTextFileAtomic(o.statsPath, statsJson(result, request, scene).dump(2) + "\n");
    std::cerr << "vct: wrote " << o.output << " in " << result.totalMs << " ms\n";
    return 0;
}

int runInfo(const std::string& scenePath, const std::string& glDevice) {
    Scene scene = loadScene(scenePath);
    SceneFeatures f = analyzeScene(scene);
    std::cout << "scene: " << scenePath << "\n"
              << "triangles: " << f.triangles << "\nvertices: " << scene.positions.size()
              << "\nmaterials: " << f.materials << " (alpha-masked: "
              << std::count_if(scene.materials.begin(), scene.materials.end(),
                               [](const Material& m) { return m.alphaMask; })
              << ")\ntextures: " << scene.textures.size()
              << "\nvertex colours: " << (scene.colors.empty() ? "no" : "yes")
              << "\nlights: " << f.lights << "\nemissive: " << (f.hasEmission ? "yes" : "no")
              << "\noff-screen occluders: " << (f.hasOffscreenOccluders ? "yes" : "no") << "\nbounds: ("
              << scene.bounds.min.x << ", " << scene.bounds.min.y << ", " << scene.bounds.min.z << ") .. ("
              << scene.bounds.max.x << ", " << scene.bounds.max.y << ", " << scene.bounds.max.z << ")\n"
              << "cameras: " << describeCameras(scene) << "\n"
              << "camera animations: " << describeCameraAnimations(scene) << "\n"
              << "light animations: " << describeLightAnimations(scene) << "\n"
              << "object animations: " << describeMeshAnimations(scene) << "\n";
    for (const auto& l : scene.lights)
        std::cout << "light '" << l.name << "': " << (l.type == LightType::Directional ? "directional" :
                                                      l.type == LightType::Point ? "point" : "spot")
                  << "\n";
    for (const auto& w : scene.warnings) std::cout << "warning: " << w << "\n";
    GlContext& gl = GlContext::shared(parseGlDevice(glDevice));
    std::cout << "gl_renderer: " << gl.info().renderer << "\ngl_version: " << gl.info().version
              << "\ngl_platform: " << gl.info().platform << "\n";
    for (const std::string& line : describeDeviceLimits()) std::cout << line << "\n";
    return 0;
}

}  // namespace vct
