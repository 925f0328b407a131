// Error against cost for VCT's variants, the ray-traced reference at 1..128 spp and the
// denoised ray tracers, measured in one run on one machine: AO at 512^2 and GI at 256^2 on
// the Cornell box, Sponza (when present) and an off-screen scene. Prints, per case, every
// point with frame_ms (what the next frame of the static scene, its camera moved, costs:
// core/timing.h; the G-buffer counts, and so do voxels fitted to the view) and time_ms (cold:
// G-buffer, voxels and the BVH built anew), the Pareto fronts of both, and for each VCT
// variant the reference's cost at the same error, interpolated on its own error-cost curve
// (error ~ 1 / sqrt(spp) between measured points): the equal-error ratio of frame_ms and of
// time_ms.
//
//   bench_pareto [--ao-size N] [--gi-size N] [--truth-spp N] [--max-spp N] [--runs N]
//                [--voxel-res N] [--case NAME]...   (cornell-ao, cornell-gi, sponza-ao,
//                sponza-gi, overhang-ao, emitter-gi; default all)
//                [--vct "KEY=VALUE ..."]...   VCT variants to measure instead of the default
//                ones (each a space-separated list of --param settings, and voxel-res=N for a
//                grid other than --voxel-res's; "" is the defaults)
//                [--passes]   also print each point's median time per pass (and, where the
//                driver's timer queries work, the GPU time of its per-frame passes)
// Where the timer queries work, the equal-error table also gives the reference's frame over
// VCT's per-frame GPU time ("GPU time"): VCT's frame on a GPU kept busy, without the glFinish
// each timed pass ends in.
//
// AO alone fits its voxels to the visible points by default (vct.region=auto), and on Sponza
// and the off-screen scene that region follows the camera, so the next frame voxelizes again
// and frame_ms counts it; the default vct.region=scene variants keep one grid over the scene
// for every frame (GI's region is the scene already: those run for AO only; a --vct variant runs
// for every case). The AO variants on a 512^3 scene grid show where VCT's error goes when the
// grid refines (its voxel error falls slowly, docs/convergence.md): the cold cost grows with the
// grid, the frame's cone pass much less (steps of two footprints, a trace scale of 4 or 6).
//
// The truth is the reference at --truth-spp (256) with another seed than the points', so a
// point's error is its own noise and bias, not shared samples. Sponza: the view of
// docs/results.md's study (eye (-11, 1.8, 0.5), target (4, 3.5, -0.5), 60 deg), R = 1, lit by
// a uniform sky of 0.5 alone for GI (it has no lights); the Cornell box and the off-screen
// scenes: their own cameras, R = 0.5, sky 0 for GI.
#include "bench_main.h"
#include "eval/comparison.h"
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace vct;

namespace {

struct Case {
    std::string name, path;
    bool gi = false;
    float radius = 0.5f, sky = 0.f;
    bool customCamera = false;
};

struct Point {
    std::string label;
    bool reference = false;  // a point of the reference's curve
    std::string passes;      // "name ms, ..." (median per pass)
    // The per-frame passes' GPU time (median), where every timed run had it.
    std::optional<double> gpuFrameMs;
    int spp = 0;
    double rmse = 0.0, frameMs = 0.0, timeMs = 0.0;
    bool frontFrame = false, frontTime = false;
};

// Marks the points no other point beats in both error and the cost `cost`.
template <class Cost, class Flag>
void markFront(std::vector<Point>& points, Cost cost, Flag flag) {
    for (Point& p : points) {
        p.*flag = true;
        for (const Point& q : points)
            if (&q != &p && q.rmse <= p.rmse && cost(q) <= cost(p) && (q.rmse < p.rmse || cost(q) < cost(p))) {
                p.*flag = false;
                break;
            }
    }
}

// The reference's cost at error `e` on its curve (points sorted by spp): log-log interpolation
// between the bracketing points; past the last point, cost ~ 1 / e^2 (error ~ 1 / sqrt(spp)).
// `extrapolated` says which; below the first point's error only.
double referenceCostAt(const std::vector<Point>& curve, double e, double Point::*cost, bool& extrapolated) {
    extrapolated = false;
    if (curve.empty()) return 0.0;
    if (e >= curve.front().rmse) return curve.front().*cost;  // 1 spp is already at least as accurate
    for (size_t i = 1; i < curve.size(); ++i) {
        const Point &a = curve[i - 1], &b = curve[i];
        if (e >= b.rmse) {
            const double t = std::log(a.rmse / e) / std::log(a.rmse / b.rmse);
            return std::exp(std::log(a.*cost) + t * std::log((b.*cost) / (a.*cost)));
        }
    }
    extrapolated = true;
    const Point& last = curve.back();
    return last.*cost * (last.rmse / e) * (last.rmse / e);
}

}  // namespace

static int benchRun(int argc, char** argv) {
    int aoSize = 512, giSize = 256, truthSpp = 256, maxSpp = 128, runs = 3, voxelRes = 128;
    std::vector<std::string> only;
    using Settings = std::vector<std::pair<std::string, std::string>>;
    struct Variant {
        std::string label;
        Settings settings;
        bool aoOnly = false;  // GI's region is the scene already: a scene-wide variant repeats the default
        int voxelRes = 0;     // 0: --voxel-res
    };
    std::vector<Variant> vctVariants;
    bool printPasses = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--passes") {
            printPasses = true;
            continue;
        }
        if (i + 1 >= argc) {
            std::cerr << "bench_pareto: " << a << " needs a value\n";
            return 2;
        }
        const char* value = argv[++i];
        if (a == "--ao-size") aoSize = std::atoi(value);
        else if (a == "--gi-size") giSize = std::atoi(value);
        else if (a == "--truth-spp") truthSpp = std::atoi(value);
        else if (a == "--max-spp") maxSpp = std::atoi(value);
        else if (a == "--runs") runs = std::atoi(value);
        else if (a == "--voxel-res") voxelRes = std::atoi(value);
        else if (a == "--case") only.push_back(value);
        else if (a == "--vct") {
            // A variant named here runs for every case.
            Settings settings;
            int res = 0;
            std::istringstream words(value);
            for (std::string w; words >> w;) {
                const size_t eq = w.find('=');
                if (eq == std::string::npos || eq == 0) {
                    std::cerr << "bench_pareto: --vct expects KEY=VALUE words, got '" << w << "'\n";
                    return 2;
                }
                if (w.substr(0, eq) == "voxel-res") {
                    res = std::atoi(w.c_str() + eq + 1);
                    if (res < 8 || res > 1024) {
                        std::cerr << "bench_pareto: voxel-res must be in [8, 1024], got '" << w << "'\n";
                        return 2;
                    }
                    continue;
                }
                settings.push_back({w.substr(0, eq), w.substr(eq + 1)});
            }
            const std::string words0 = value;
            vctVariants.push_back({words0.empty() ? "vct" : "vct " + words0, settings, false, res});
        }
        else {
            std::cerr << "bench_pareto: unknown option " << a << "\n";
            return 2;
        }
    }
    if (vctVariants.empty())
        vctVariants = {{"vct", {}},
                       {"vct trace-scale=2", {{"vct.trace-scale", "2"}}},
                       {"vct trace-scale=4", {{"vct.trace-scale", "4"}}},
                       {"vct cones=16 trace-scale=4", {{"vct.cones", "16"}, {"vct.trace-scale", "4"}}},
                       {"vct region=scene trace-scale=4", {{"vct.region", "scene"}, {"vct.trace-scale", "4"}}, true},
                       {"vct region=scene cones=16 trace-scale=4",
                        {{"vct.region", "scene"}, {"vct.cones", "16"}, {"vct.trace-scale", "4"}},
                        true},
                       // Steps of one footprint instead of half: half the samples, and a wall
                       // thinner than a voxel may fall between two of them.
                       {"vct region=scene step=1 trace-scale=4",
                        {{"vct.region", "scene"}, {"vct.step", "1"}, {"vct.trace-scale", "4"}},
                        true},
                       {"vct region=scene step=1 trace-scale=8",
                        {{"vct.region", "scene"}, {"vct.step", "1"}, {"vct.trace-scale", "8"}},
                        true},
                       {"vct 512^3 region=scene step=2 trace-scale=4",
                        {{"vct.region", "scene"}, {"vct.step", "2"}, {"vct.trace-scale", "4"}},
                        true,
                        512},
                       {"vct 512^3 region=scene step=2 trace-scale=6",
                        {{"vct.region", "scene"}, {"vct.step", "2"}, {"vct.trace-scale", "6"}},
                        true,
                        512}};
    if (aoSize < 8 || giSize < 8 || truthSpp < 1 || maxSpp < 1 || runs < 1 || voxelRes < 8) {
        std::cerr << "bench_pareto: sizes >= 8, spp and runs >= 1\n";
        return 2;
    }
    const std::string src = VCT_SOURCE_DIR;
    const char* env = std::getenv("VCT_SHARED_SCENES");
    const std::string shared = env ? env : src + "/../shared/scenes";
    std::vector<Case> cases = {{"cornell-ao", src + "/scenes/cornell_box.gltf", false, 0.5f, 0.f},
                               {"cornell-gi", src + "/scenes/cornell_box.gltf", true, 0.5f, 0.f},
                               {"sponza-ao", shared + "/mcguire_sponza.glb", false, 1.f, 0.f, true},
                               {"sponza-gi", shared + "/mcguire_sponza.glb", true, 1.f, 0.5f, true},
                               {"overhang-ao", src + "/scenes/offscreen_overhang.gltf", false, 0.5f, 0.f},
                               {"emitter-gi", src + "/scenes/offscreen_gi_emitter.gltf", true, 0.5f, 0.f}};
    std::printf("renderer: %s, %u cores; AO %dx%d, GI %dx%d, %d^3 voxels (unless a variant says), truth %d spp, median of %d cold runs after "
                "a warm-up, in rounds of every point\n",
                GlContext::shared().info().renderer.c_str(), std::thread::hardware_concurrency(), aoSize, aoSize,
                giSize, giSize, voxelRes, truthSpp, runs);
    for (const Case& c : cases) {
        if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
        if (!std::filesystem::exists(c.path)) {
            std::printf("\n%s: %s not found, skipped\n", c.name.c_str(), c.path.c_str());
            continue;
        }
        const Scene scene = loadScene(c.path);
        RenderSession session(scene);
        RenderRequest base;
        base.width = base.height = c.gi ? giSize : aoSize;
        CameraRequest cam;
        if (c.customCamera) {
            cam.hasEye = true;
            cam.eye = glm::vec3(-11.f, 1.8f, 0.5f);
            cam.target = glm::vec3(4.f, 3.5f, -0.5f);
            cam.fovDeg = 60.f;
        }
        base.camera = resolveCamera(scene, cam, float(base.width) / float(base.height));
        base.radius = c.radius;
        base.sky = c.sky;
        base.voxelRes = voxelRes;
        base.params.set("reference.bounces", "3");  // GI: VCT's reflections, as the comparisons match them
        const std::string aov = c.gi ? "indirect" : "ao";
        auto request = [&](const std::string& method, int spp, uint64_t seed) {
            RenderRequest r = base;
            (c.gi ? r.gi : r.ao) = method;
            r.spp = spp;
            r.seed = seed;
            r.aovs = {aov};  // the estimate alone: another AOV (depth) would draw a G-buffer the method may not need
            return r;
        };
        // The truth: another seed than every point's (they use 0); its depth masks the sky.
        RenderRequest truthRequest = request("reference", truthSpp, 7919);
        truthRequest.aovs.push_back("depth");
        const RenderResult truthRun = session.render(truthRequest);
        const Image& truth = truthRun.aovs.at(aov);
        const Image valid = validMaskFromDepth(truthRun.aovs.at("depth"));

        std::vector<std::pair<std::string, RenderRequest>> variants;
        std::map<std::string, std::set<std::string>> ownKeys;  // each VCT variant's own settings
        std::vector<int> spps;
        for (int spp = 1; spp <= maxSpp; spp *= 2) spps.push_back(spp);
        for (int spp : spps) variants.push_back({"reference " + std::to_string(spp) + " spp", request("reference", spp, 0)});
        const std::string denoised = c.gi ? "pt-denoised" : "rtao-denoised";
        for (int spp : {1, 4}) {
            RenderRequest r = request(denoised, 1, 0);
            r.params.set(denoised + ".spp", std::to_string(spp));
            variants.push_back({denoised + " " + std::to_string(spp) + " spp", r});
        }
        for (const Variant& v : vctVariants) {
            if (c.gi && v.aoOnly) continue;
            RenderRequest r = request("vct", 1, 0);
            if (v.voxelRes > 0) r.voxelRes = v.voxelRes;
            for (const auto& [k, value] : v.settings) {
                r.params.set(k, value);
                ownKeys[v.label].insert(k);
            }
            variants.push_back({v.label, r});
        }

        // Every point's warm-up first (its image is the one scored), then the timed runs in
        // rounds, each round every point once: a machine whose speed drifts during the case
        // (a shared host, thermal limits) slows every point alike instead of the points that
        // happen to run late, so the equal-error ratios compare like with like.
        std::vector<Point> points;
        for (auto& [label, req] : variants) {
            std::fprintf(stderr, "%s: %s\n", c.name.c_str(), label.c_str());
            const RenderResult first = session.render(req);
            // A misspelt --vct key (region=scene for vct.region=scene) would time the default
            // march under the variant's name.
            for (const std::string& unused : first.unusedParams)
                if (ownKeys.count(label) && ownKeys.at(label).count(unused)) {
                    std::fprintf(stderr, "bench_pareto: %s: '%s' is not a parameter of this render (see vct render --help-params)\n",
                                 label.c_str(), unused.c_str());
                    return 2;
                }
            Point p;
            p.label = label;
            p.reference = req.ao == "reference" || req.gi == "reference";
            p.spp = req.spp;
            p.rmse = computeErrorMetrics(first.aovs.at(aov), truth, &valid).rmse;
            points.push_back(p);
        }
        std::vector<std::vector<double>> totals(variants.size()), frames(variants.size()), gpuFrames(variants.size());
        std::vector<std::map<std::string, std::vector<double>>> passTimes(variants.size());
        for (int run = 0; run < runs; ++run) {
            std::fprintf(stderr, "%s: timed round %d of %d\n", c.name.c_str(), run + 1, runs);
            for (size_t v = 0; v < variants.size(); ++v) {
                RenderRequest timed = variants[v].second;
                timed.reuseSceneData = false;  // its own voxels or BVH count in its cold time
                const RenderResult r = session.render(timed);
                totals[v].push_back(r.totalMs);
                frames[v].push_back(r.frameMs);
                if (r.frameGpuMs) gpuFrames[v].push_back(*r.frameGpuMs);
                for (const PassTiming& t : r.passes) passTimes[v][t.name].push_back(t.wallMs);
            }
        }
        for (size_t v = 0; v < variants.size(); ++v) {
            Point& p = points[v];
            p.frameMs = medianOf(frames[v]);
            p.timeMs = medianOf(totals[v]);
            p.gpuFrameMs = medianOfEveryRun(gpuFrames[v], frames[v].size());
            for (const auto& [name, t] : passTimes[v]) {
                char buf[64];
                std::snprintf(buf, sizeof buf, "%s%s %.1f", p.passes.empty() ? "" : ", ", name.c_str(), medianOf(t));
                p.passes += buf;
            }
        }
        markFront(points, [](const Point& p) { return p.frameMs; }, &Point::frontFrame);
        markFront(points, [](const Point& p) { return p.timeMs; }, &Point::frontTime);

        std::printf("\n%s: %s, %dx%d, R = %.2f, sky %.2f (%s against the reference at %d spp)\n", c.name.c_str(),
                    c.path.c_str(), base.width, base.height, c.radius, c.sky, c.gi ? "indirect radiance" : "AO",
                    truthSpp);
        std::printf("%-30s %9s %11s %11s  %s\n", "point", "rmse", "frame_ms", "time_ms", "Pareto (frame, cold)");
        for (const Point& p : points) {
            std::printf("%-30s %9.4f %11.1f %11.1f  %s %s\n", p.label.c_str(), p.rmse, p.frameMs, p.timeMs,
                        p.frontFrame ? "frame" : "     ", p.frontTime ? "cold" : "");
            if (printPasses) {
                std::printf("    passes (ms): %s", p.passes.c_str());
                if (p.gpuFrameMs) std::printf("; GPU time of the per-frame passes %.2f", *p.gpuFrameMs);
                std::printf("\n");
            }
        }
        std::vector<Point> curve;
        for (const Point& p : points)
            if (p.reference) curve.push_back(p);
        std::printf("equal error: the reference's cost at each VCT point's error, over the VCT point's\n");
        std::printf("%-30s %9s %13s %13s %9s %9s\n", "vct point", "rmse", "ref frame_ms", "ref time_ms", "frame x",
                    "cold x");
        for (const Point& p : points) {
            if (p.label.rfind("vct", 0) != 0) continue;
            bool extraFrame = false, extraTime = false;
            const double refFrame = referenceCostAt(curve, p.rmse, &Point::frameMs, extraFrame);
            const double refTime = referenceCostAt(curve, p.rmse, &Point::timeMs, extraTime);
            std::printf("%-30s %9.4f %13.1f %13.1f %9.2f %9.2f%s%s", p.label.c_str(), p.rmse, refFrame, refTime,
                        refFrame / p.frameMs, refTime / p.timeMs,
                        p.rmse >= curve.front().rmse ? "  (the reference at 1 spp is as accurate)" : "",
                        extraFrame ? "  (beyond the largest spp: extrapolated)" : "");
            // On a GPU: the reference's frame over VCT's per-frame GPU time, VCT's cost on a
            // GPU kept busy (no glFinish after every pass).
            if (p.gpuFrameMs && *p.gpuFrameMs > 0.0) std::printf("  (GPU time: %.2f)", refFrame / *p.gpuFrameMs);
            std::printf("\n");
        }
    }
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_pareto", benchRun, argc, argv); }
