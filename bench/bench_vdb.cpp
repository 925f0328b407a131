// The sparse (OpenVDB, CPU) voxel path on Sponza at 64, 128, 256 and 512 voxels: build time
// (voxelize, inject, levels), memory against the dense grid of the same float32 channels (both
// the real non-cubic grid and the res^3 convention), CPU cone-traced AO time at
// 256x256 (pixel centres, R = 1, default cones, isotropic), and the AO error against the
// ray-traced reference at the same points (64 spp, its standard error printed alongside).
// Camera down the nave as in bench_reference: eye (-10, 2, 0), target (10, 4, 0), fov 60 deg.
//
// The scene is looked up in $VCT_SHARED_SCENES, else VCT_SOURCE_DIR "/../shared/scenes"; the
// benchmark prints a note and exits 0 when it is missing. VCT_VDB_RES=64,128 picks resolutions.
#include "bench_main.h"
#include "core/memory_usage.h"
#include "core/view.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/gltf_loader.h"
#include "vdb/sparse_cone.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace vct;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string scenePath() {
    const char* env = std::getenv("VCT_SHARED_SCENES");
    std::string dir = env ? env : std::string(VCT_SOURCE_DIR) + "/../shared/scenes";
    return dir + "/mcguire_sponza.glb";
}

std::vector<int> resolutions() {
    const char* env = std::getenv("VCT_VDB_RES");
    if (!env) return {64, 128, 256, 512};
    std::vector<int> r;
    std::stringstream ss(env);
    for (std::string item; std::getline(ss, item, ',');) r.push_back(std::stoi(item));
    return r;
}

double mib(size_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

}  // namespace

static int benchRun(int, char**) {
    const std::string path = scenePath();
    if (!std::ifstream(path).good()) {
        std::printf("bench_vdb: %s not found; set VCT_SHARED_SCENES. Skipped.\n", path.c_str());
        return 0;
    }
    Scene scene = loadScene(path);
    EmbreeScene es(scene);
    Camera cam;
    cam.eye = {-10.f, 2.f, 0.f};
    cam.target = {10.f, 4.f, 0.f};
    cam.yfov = 60.f * 3.14159265f / 180.f;
    View view = makeView(cam, 256, 256);
    std::vector<SurfacePoint> surface = surfacePointsAtPixelCentres(es, view);
    std::vector<SparsePoint> points(surface.size());
    size_t valid = 0;
    for (size_t i = 0; i < surface.size(); ++i) {
        points[i] = {surface[i].position, surface[i].normal, surface[i].geomNormal, glm::vec3(0.5f), surface[i].valid};
        valid += surface[i].valid;
    }
    ReferenceSettings rs;
    rs.radius = 1.f;
    rs.spp = 64;
    rs.progress = false;
    auto t0 = Clock::now();
    ReferenceAO ref = referenceAO(es, surface, rs);
    std::printf("Sponza: %zu triangles, %zu lights, %zu/%zu pixels hit; reference AO 64 spp in %.2f s (mean "
                "stderr %.4f)\n",
                scene.triangleCount(), scene.lights.size(), valid, surface.size(), since(t0), ref.meanStderr);
    std::printf("%5s %15s %10s %8s %8s %8s %10s %10s %10s %7s %7s %9s %9s %8s %8s\n", "res", "grid", "active",
                "vox s", "inj s", "lvl s", "sparseMiB", "denseMiB", "cubeMiB", "%dense", "%cube", "peakMiB",
                "AO 256 s", "AO RMSE", "AO bias");
    ConeSettings cs;
    cs.anisotropic = false;
    ParamMap params;
    params.set("vct.bounces", "0");  // the table's columns: voxelize, inject, levels (direct light)
    for (int res : resolutions()) {
        SparseVoxelScene v = buildSparseVoxels(scene, res, true, 1.f, params);
        const SparseVoxelStats& s = v.stats;
        sparseConeAO(v, std::vector<SparsePoint>(points.begin(), points.begin() + 1024), rs.radius, cs);  // warm up
        t0 = Clock::now();
        std::vector<float> ao = sparseConeAO(v, points, rs.radius, cs);
        const double aoSeconds = since(t0);
        double sq = 0, bias = 0;
        for (size_t i = 0; i < ao.size(); ++i) {
            if (!points[i].valid) continue;
            const double d = double(ao[i]) - ref.ao[i];
            sq += d * d;
            bias += d;
        }
        char grid[32];
        std::snprintf(grid, sizeof grid, "%dx%dx%d", v.resolution.x, v.resolution.y, v.resolution.z);
        std::printf("%5d %15s %10zu %8.2f %8.2f %8.2f %10.1f %10.1f %10.1f %6.1f%% %6.1f%% %9.1f %9.3f %8.4f %+8.4f\n",
                    res, grid, s.activeVoxels, s.voxelizeSeconds, s.injectSeconds, s.levelsSeconds, mib(s.memoryBytes),
                    mib(s.denseBytes), mib(s.denseCubeBytes), 100.0 * double(s.memoryBytes) / double(s.denseBytes),
                    100.0 * double(s.memoryBytes) / double(s.denseCubeBytes), mib(peakResidentBytes()), aoSeconds,
                    std::sqrt(sq / double(valid)), bias / double(valid));
        std::fflush(stdout);
    }
    std::printf("memory: OpenVDB tree memUsage of every grid and level (opacity, albedo, normal, emission, radiance);"
                " dense: the same float32 channels over the non-cubic grid and its mips (denseMiB) or over res^3 "
                "(cubeMiB); peakMiB: the process's peak resident memory so far (the resolutions run in the order "
                "given, each grid freed before the next)\n");
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_vdb", benchRun, argc, argv); }
