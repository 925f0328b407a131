// Whole-scene grid vs AO region fit vs clipmap: AO error against the ray-traced reference and
// time, on Sponza (when present) and on a large-floor scene with a table near the camera.
// Dense grids run at --res; the clipmap's levels are sized so their total voxel count matches
// a cubic --res grid; one more dense row ("whole scene, equal memory") takes the largest
// dense resolution whose memory does not exceed the clipmap's. Time = the whole render
// (voxelize, mips, cones; the G-buffer is cached), median-free single run after a warm-up.
//   bench_clipmap [--size N] [--spp N] [--res N] [--levels L] [--scene PATH]
#include "bench_main.h"
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

using namespace vct;

namespace {

void addQuad(Scene& s, glm::vec3 c, glm::vec3 u, glm::vec3 v) {
    const uint32_t base = uint32_t(s.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (glm::vec3 p : {c, c + u, c + u + v, c + v}) {
        s.positions.push_back(p);
        s.normals.push_back(n);
        s.uvs.push_back(glm::vec2(0.f));
    }
    s.triangles.push_back({base, base + 1, base + 2});
    s.triangles.push_back({base, base + 2, base + 3});
    for (int i = 0; i < 2; ++i) {
        s.triangleMaterial.push_back(0);
        s.triangleOffscreen.push_back(0);
    }
}

void addBox(Scene& s, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 d = hi - lo, x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
    addQuad(s, lo, y, x);
    addQuad(s, lo + z, x, y);
    addQuad(s, lo, z, y);
    addQuad(s, lo + x, y, z);
    addQuad(s, lo, x, z);
    addQuad(s, lo + y, z, x);
}

// 40 m floor, a table and a stool; the camera looks down at the table from 1.3 m (the scene
// of tests/gpu/region_fit_test.cpp).
Scene tableScene(Camera& camera) {
    Scene s;
    Material m;
    m.baseColorFactor = glm::vec4(0.7f, 0.7f, 0.7f, 1.f);
    m.doubleSided = true;
    s.materials.push_back(m);
    addQuad(s, {-20.f, 0.f, -20.f}, {0.f, 0.f, 40.f}, {40.f, 0.f, 0.f});
    addBox(s, {-0.6f, 0.72f, -0.4f}, {0.6f, 0.77f, 0.4f});
    for (float x : {-0.55f, 0.5f})
        for (float z : {-0.35f, 0.3f}) addBox(s, {x, 0.f, z}, {x + 0.05f, 0.72f, z + 0.05f});
    addBox(s, {0.8f, 0.f, 0.2f}, {1.15f, 0.45f, 0.55f});
    for (const auto& p : s.positions) s.bounds.expand(p);
    camera.eye = {0.5f, 1.3f, 1.3f};
    camera.target = {0.2f, 0.3f, 0.f};
    camera.yfov = 0.8f;
    camera.znear = 0.05f;
    camera.zfar = 100.f;
    return s;
}

struct Row {
    std::string label;
    double rmse = 0, ms = 0, memoryMb = 0, voxel = 0;
};

}  // namespace

static int benchRun(int argc, char** argv) {
    int size = 128, spp = 256, res = 128, levels = 4;
    std::vector<std::string> scenes;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--size") size = std::atoi(argv[i + 1]);
        else if (a == "--spp") spp = std::atoi(argv[i + 1]);
        else if (a == "--res") res = std::atoi(argv[i + 1]);
        else if (a == "--levels") levels = std::atoi(argv[i + 1]);
        else if (a == "--scene") scenes.push_back(argv[i + 1]);
    }
    if (scenes.empty()) {
        scenes.push_back("table");
        const char* env = std::getenv("VCT_SHARED_SCENES");
        const std::string shared = env ? env : std::string(VCT_SOURCE_DIR) + "/../shared/scenes";
        if (std::filesystem::exists(shared + "/mcguire_sponza.glb")) scenes.push_back(shared + "/mcguire_sponza.glb");
        else std::fprintf(stderr, "mcguire_sponza.glb not found in %s: skipped\n", shared.c_str());
    }
    // Equal memory: L cubic levels of c^3 hold as many voxels as one res^3 grid.
    const int clipRes = std::max(32, int(std::lround(double(res) / std::cbrt(double(levels)))) / 4 * 4);
    std::printf("renderer: %s, %u cores, %dx%d, AO reference %d spp; dense %d^3, clipmap %d x %d^3, "
                "anisotropic mips on the dense grids, isotropic on the clipmap\n",
                GlContext::shared().info().renderer.c_str(), std::thread::hardware_concurrency(), size, size, spp,
                res, levels, clipRes);
    for (const std::string& path : scenes) {
        Camera camera;
        Scene scene;
        float radius = 0.5f;
        if (path == "table") {
            scene = tableScene(camera);
        } else {
            scene = loadScene(path);
            camera = resolveCamera(scene, CameraRequest{}, 1.f);
            radius = 0.05f * scene.bounds.maxExtent();
        }
        RenderRequest base;
        base.width = base.height = size;
        base.camera = camera;
        base.radius = radius;
        base.aovs = {"ao", "depth"};
        RenderSession session(scene);
        RenderRequest refReq = base;
        refReq.ao = "reference";
        refReq.spp = spp;
        RenderResult ref = session.render(refReq);
        Image mask(size, size, 1);
        for (size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = ref.aovs.at("depth").pixels[i] > 0.f;
        const double noise = ref.extra["reference_ao"].value("mean_stderr", 0.0);

        struct Variant {
            std::string label;
            int voxelRes;
            std::vector<std::pair<std::string, std::string>> params;
        };
        std::vector<Variant> variants = {
            {"whole scene", res, {{"vct.region", "scene"}}},
            {"region fit", res, {{"vct.region", "fit"}}},
            {"clipmap (scene)", clipRes, {{"vct.region", "scene"}, {"vct.clipmap.levels", std::to_string(levels)}}},
            {"clipmap (fit)", clipRes, {{"vct.region", "fit"}, {"vct.clipmap.levels", std::to_string(levels)}}},
        };
        std::vector<Row> rows;
        auto run = [&](const Variant& v) {
            RenderRequest r = base;
            r.ao = "vct";
            r.voxelRes = v.voxelRes;
            r.reuseSceneData = false;  // time the whole cost: voxelize + mips + cones
            for (const auto& [k, val] : v.params) r.params.set(k, val);
            session.render(r);  // warm-up (shader compilation)
            RenderResult out = session.render(r);
            GlContext::shared().checkErrors("bench_clipmap");
            const auto& vox = out.extra["voxels"];
            Row row;
            row.label = v.label;
            row.rmse = computeErrorMetrics(out.aovs.at("ao"), ref.aovs.at("ao"), &mask).rmse;
            row.ms = out.totalMs;
            row.memoryMb = vox["memory_bytes"].get<double>() / 1e6;
            row.voxel = vox.contains("levels") ? vox["levels"][0]["voxel_size"].get<double>()
                                               : vox["voxel_size"].get<double>();
            rows.push_back(row);
        };
        for (const Variant& v : variants) run(v);
        // Equal memory: the largest dense whole-scene grid that fits in the clipmap's memory.
        const double clipMemory = rows[2].memoryMb;
        int equalRes = 0;
        for (int candidate : {res, 3 * res / 2, 2 * res, 3 * res, 4 * res}) {
            if (candidate > 512) break;
            RenderRequest r = base;
            r.ao = "vct";
            r.voxelRes = candidate;
            r.params.set("vct.region", "scene");
            RenderResult out = session.render(r);
            if (out.extra["voxels"]["memory_bytes"].get<double>() / 1e6 <= clipMemory) equalRes = candidate;
        }
        if (equalRes > 0)
            run({"whole, equal mem (" + std::to_string(equalRes) + ")", equalRes, {{"vct.region", "scene"}}});
        std::printf("\n%s  (R = %.3g, reference %d spp, mean stderr %.4f)\n", path.c_str(), radius, spp, noise);
        std::printf("%-26s %9s %9s %10s %12s\n", "variant", "rmse", "time_ms", "memory_MB", "finest_voxel");
        for (const Row& r : rows)
            std::printf("%-26s %9.4f %9.1f %10.2f %12.4f\n", r.label.c_str(), r.rmse, r.ms, r.memoryMb, r.voxel);
    }
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_clipmap", benchRun, argc, argv); }
