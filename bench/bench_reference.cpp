// Throughput of the ray-traced AO reference on Sponza against Embree's raw occlusion speed
// on the very same rays (same origins and directions, generated here the way
// referenceAO generates them, traced in a bare loop). 256x256 pixel centres, 64 spp, R = 1,
// camera down the nave: eye (-10, 2, 0), target (10, 4, 0), vertical fov 60 degrees.
//
// The scene is looked up in $VCT_SHARED_SCENES, else VCT_SOURCE_DIR "/../shared/scenes";
// the benchmark prints a note and exits 0 when it is missing. Prints a table (no Google
// Benchmark fixtures: one scene, a few modes, medians of 3 runs).
#include "bench_main.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "reference/reference_gi.h"
#include "reference/sampler.h"
#include "reference/sampling_math.h"
#include "core/view.h"
#include "scene/gltf_loader.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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

// Optional 8-bit PGM of a [0, 1] image for eyeballing (VCT_REFERENCE_DUMP=prefix).
void writePgm(const std::string& path, const std::vector<float>& v, int w, int h) {
    std::ofstream f(path, std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n";
    for (float x : v) f.put(char(uint8_t(std::lround(std::clamp(x, 0.f, 1.f) * 255.f))));
}

// The occlusion rays referenceAO traces, in the same pass/point/sample order.
void generateRays(const EmbreeScene& es, const std::vector<SurfacePoint>& points, const ReferenceSettings& set,
                  std::vector<RTCRay>* rays) {
    SampleSchedule schedule = sampleSchedule(set.spp, set.replicates);
    const float errorFloor = es.sceneMaxAbs() * 0x1p-8f;
    int done = 0;
    for (int total : schedule.totals) {
        for (size_t i = 0; i < points.size(); ++i) {
            const SurfacePoint& p = points[i];
            if (!p.valid) continue;
            glm::vec3 ng = glm::dot(p.normal, p.geomNormal) < 0.f ? -p.geomNormal : p.geomNormal;
            glm::vec3 org = offsetRayOrigin(p.position, ng, std::max(maxAbsComponent(p.position), errorFloor));
            Frame frame = Frame::fromZ(p.normal);
            uint64_t stream = streamSeed(set.seed, i);
            for (int k = done; k < total; ++k) {
                glm::vec3 w = frame.toWorld(
                    sampleCosineHemisphere(replicatedSample(stream, schedule.replicates, 0, uint32_t(k))));
                if (glm::dot(w, ng) <= 0.f) continue;
                RTCRay r;
                r.org_x = org.x; r.org_y = org.y; r.org_z = org.z; r.tnear = 0.f;
                r.dir_x = w.x; r.dir_y = w.y; r.dir_z = w.z; r.time = 0.f;
                r.tfar = set.radius; r.mask = 0xFFFFFFFFu; r.id = 0; r.flags = 0;
                rays->push_back(r);
            }
        }
        done = total;
    }
}

// Bare Embree: rtcOccluded1 over the arrays, parallel over chunks like the reference.
double rawOcclusion(const EmbreeScene& es, const std::vector<RTCRay>& source, uint64_t* unoccluded) {
    std::vector<RTCRay> rays = source;  // fresh tfar
    std::atomic<uint64_t> open{0};
    auto t0 = Clock::now();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        uint64_t local = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            rtcOccluded1(es.handle(), &ctx, &rays[i]);
            local += rays[i].tfar >= 0.f;
        }
        open.fetch_add(local);
    });
    double s = since(t0);
    *unoccluded = open.load();
    return s;
}

}  // namespace

static int benchRun(int, char**) {
    const std::string path = scenePath();
    if (!std::ifstream(path).good()) {
        std::printf("bench_reference: %s not found; set VCT_SHARED_SCENES. Skipped.\n", path.c_str());
        return 0;
    }
    auto t0 = Clock::now();
    Scene scene = loadScene(path);
    double loadSeconds = since(t0);
    t0 = Clock::now();
    EmbreeScene es(scene);
    double buildSeconds = since(t0);

    Camera cam;
    cam.eye = {-10.f, 2.f, 0.f};
    cam.target = {10.f, 4.f, 0.f};
    cam.yfov = 60.f * 3.14159265f / 180.f;
    View view = makeView(cam, 256, 256);
    t0 = Clock::now();
    std::vector<SurfacePoint> points = surfacePointsAtPixelCentres(es, view);
    double primarySeconds = since(t0);
    size_t valid = 0;
    for (const SurfacePoint& p : points) valid += p.valid;

    std::printf("Sponza: %zu triangles, load %.2f s, Embree build %.3f s, 256x256 primary rays %.3f s, %zu/%zu "
                "pixels hit\n",
                scene.triangleCount(), loadSeconds, buildSeconds, primarySeconds, valid, points.size());

    ReferenceSettings set;
    set.radius = 1.f;
    set.spp = 64;
    set.progress = false;

    std::vector<RTCRay> rays;
    t0 = Clock::now();
    generateRays(es, points, set, &rays);
    double generateSeconds = since(t0);

    // Raw loop and the four ray modes, interleaved run by run so that load from other
    // processes hits all alike; the minimum over runs is the least disturbed figure.
    const int runs = 5;
    const char* names[] = {"referenceAO single", "referenceAO stream (1M)", "referenceAO packet8",
                           "referenceAO packet16"};
    std::vector<double> rawTimes, modeTimes[4];
    ReferenceAO results[4];
    uint64_t rawOpen = 0;
    for (int run = 0; run < runs; ++run) {
        rawTimes.push_back(rawOcclusion(es, rays, &rawOpen));
        for (int mode = 0; mode < 4; ++mode) {
            set.rayMode = RayMode(mode);
            results[mode] = referenceAO(es, points, set);
            modeTimes[mode].push_back(results[mode].seconds);
        }
    }
    double raw = *std::min_element(rawTimes.begin(), rawTimes.end());
    std::printf("\nmin of %d interleaved runs, 2 threads (TBB default)\n", runs);
    std::printf("%-28s %10s %12s %12s %10s\n", "what", "seconds", "rays", "Mrays/s", "vs raw");
    std::printf("%-28s %10.3f %12zu %12.2f %10s\n", "raw rtcOccluded1 loop", raw, rays.size(),
                rays.size() / raw * 1e-6, "1.00x");
    for (int mode = 0; mode < 4; ++mode) {
        const ReferenceAO& ao = results[mode];
        double t = *std::min_element(modeTimes[mode].begin(), modeTimes[mode].end());
        std::printf("%-28s %10.3f %12llu %12.2f %9.2fx\n", names[mode], t, (unsigned long long)ao.raysTraced,
                    ao.raysTraced / t * 1e-6, t / raw);
        if (ao.raysTraced != rays.size())
            std::printf("  !! ray count differs from the generated arrays (%zu)\n", rays.size());
    }
    std::printf("(ray generation alone, 1 thread: %.3f s)\n", generateSeconds);
    if (const char* dump = std::getenv("VCT_REFERENCE_DUMP"))
        writePgm(std::string(dump) + "_ao.pgm", results[1].ao, 256, 256);
    {
        const ReferenceAO& ao = results[0];
        double meanA = 0;
        uint64_t open = 0;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i].valid) {
                meanA += ao.ao[i] / double(valid);
                open += uint64_t(std::llround(ao.ao[i] * ao.sppUsed));
            }
        std::printf("mean A %.4f, image-mean stderr %.5f; unoccluded rays: reference %llu, raw loop %llu\n", meanA,
                    ao.meanStderr, (unsigned long long)open, (unsigned long long)rawOpen);
    }

    // Self-intersection check: how many of these rays hit something closer than 1e-4 R?
    {
        std::atomic<uint64_t> close{0};
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i != r.end(); ++i) {
                uint32_t tri;
                float u, v, t;
                const RTCRay& ray = rays[i];
                if (es.intersect({ray.org_x, ray.org_y, ray.org_z}, {ray.dir_x, ray.dir_y, ray.dir_z}, 0.f,
                                 1e-4f * set.radius, &tri, &u, &v, &t))
                    close.fetch_add(1);
            }
        });
        std::printf("\nrays hitting within 1e-4 R of their origin (self-intersection suspects): %llu of %zu\n",
                    (unsigned long long)close.load(), rays.size());
    }

    // Pixel-area AO and GI for orientation.
    set.rayMode = RayMode::Single;
    ReferenceAO area = referenceAOPixelArea(es, view, set);
    std::printf("referenceAOPixelArea 256x256 64 spp: %.3f s, %.2f Mrays/s (primary + occlusion), mean stderr %.5f\n",
                area.seconds, area.raysPerSecond * 1e-6, area.meanStderr);
    ReferenceSettings gi = set;
    gi.spp = 16;
    gi.sky = 1.f;
    View small = makeView(cam, 128, 128);
    ReferenceGI g = referenceGI(es, small, gi);
    std::printf("referenceGI 128x128 16 spp 4 bounces: %.3f s, %.2f Mrays/s, indirect mean stderr %.5f\n", g.seconds,
                g.raysPerSecond * 1e-6, g.meanStderr);
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_reference", benchRun, argc, argv); }
