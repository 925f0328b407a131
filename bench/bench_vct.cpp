// Voxel cone tracing's cost and error on one machine (issue 6): per-pass time (voxelize,
// inject, mips, cone_ao, cone_gi), AO and GI error against the ray-traced reference, and the
// cone passes' 3D-texture fetch rate beside a bare compute shader that does only the same
// number of trilinear fetches. Prints tables and the GL renderer string.
//
//   bench_vct [--size N] [--voxel-res N] [--spp N] [--runs N] [--scene cornell|sponza]...
//             [--param KEY=VALUE]...   (vct.* parameters of the VCT render, as vct render)
//
// Scenes: scenes/cornell_box.gltf (its camera, R = 0.5) and, when present,
// $VCT_SHARED_SCENES/mcguire_sponza.glb (or ../shared/scenes), which has no lights or
// camera: a sun (directional, 8 lux, from above and slightly to the side) and a camera down
// the atrium are added here, R = 1.
//
// Fetch count: shaders/bench/cone_count.glsl includes shaders/cone/cone_march.glsl
// unchanged with textureLod wrapped by a counter, and runs over a grid and G-buffer built by
// the same public calls the renderer makes (voxelizeScene, injectRadiance, buildMips,
// renderGBuffer) with the same uniforms as src/cone/cone_trace.cpp. Its output is checked
// against the renderer's cone pass (max |difference| printed; 0 means the copy is exact), so
// the per-pixel counts are those of the real pass, including early exits. The bare shader
// (shaders/bench/fetch.glsl) then does exactly that many textureLod calls per pixel on a
// 128^3 RGBA16F mipmapped texture (GL_LINEAR_MIPMAP_LINEAR, as the grid).
#include "bench_main.h"
#include "cone/cone_bounce.h"
#include "cone/cone_gpu.h"
#include "cone/cone_programs.h"
#include "cone/cone_set.h"
#include "cone/cone_settings.h"
#include "eval/metrics.h"
#include "gl/context.h"
#include "gl/program_cache.h"
#include "gl/readback.h"
#include "raster/gbuffer_pass.h"
#include "core/gpu_scene.h"
#include "render/renderer.h"
#include "core/view.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "voxelize/voxelize.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace vct;

namespace {

struct Options {
    int size = 512;
    int voxelRes = 128;
    int spp = 64;
    int runs = 3;
    std::vector<std::string> scenes;
    ParamMap params;  // --param KEY=VALUE for the VCT render and the counted passes
};

struct BenchScene {
    std::string name;
    Scene scene;
    Camera camera;
    float radius = 0.5f;
};

std::string sharedScenesDir() {
    const char* env = std::getenv("VCT_SHARED_SCENES");
    return env ? env : std::string(VCT_SOURCE_DIR) + "/../shared/scenes";
}

bool loadBenchScene(const std::string& name, BenchScene& out) {
    out.name = name;
    if (name == "cornell") {
        out.scene = loadScene(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf");
        out.camera = resolveCamera(out.scene, CameraRequest{}, 1.f);
        out.radius = 0.5f;
        return true;
    }
    if (name == "sponza") {
        const std::string path = sharedScenesDir() + "/mcguire_sponza.glb";
        if (!std::filesystem::exists(path)) {
            std::fprintf(stderr, "sponza: %s not found, skipped\n", path.c_str());
            return false;
        }
        out.scene = loadScene(path);
        Light sun;
        sun.name = "bench_sun";
        sun.type = LightType::Directional;
        sun.color = glm::vec3(8.f, 7.6f, 7.0f);  // lux, warm white
        sun.direction = glm::normalize(glm::vec3(0.25f, -1.f, 0.15f));
        out.scene.lights.push_back(sun);
        CameraRequest cam;
        cam.hasEye = true;
        cam.eye = glm::vec3(11.f, 2.5f, -0.5f);
        cam.target = glm::vec3(-6.f, 4.5f, 0.5f);
        cam.fovDeg = 60.f;
        out.camera = resolveCamera(out.scene, cam, 1.f);
        out.radius = 1.f;
        return true;
    }
    throw std::invalid_argument("bench_vct: unknown scene '" + name + "' (cornell|sponza)");
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

Image surfaceMask(const Image& depth) {
    Image m(depth.width, depth.height, 1);
    for (size_t i = 0; i < depth.pixels.size(); ++i) m.pixels[i] = depth.pixels[i] > 0.f ? 1.f : 0.f;
    return m;
}

double maxAbsDiff(const Image& a, const Image& b, int channelsOfA) {
    // a may carry more channels than b (RGBA readback against an RGB AOV).
    double m = 0.0;
    const size_t n = size_t(b.width) * b.height;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < b.channels; ++c)
            m = std::max(m, double(std::abs(a.pixels[i * channelsOfA + c] - b.pixels[i * b.channels + c])));
    return m;
}

// The cone pass with a fetch counter (see the file comment). Returns per-pixel counts in an
// R32UI texture and the pass's output as an RGBA32F image (AO in channel 0 or GI rgb).
struct CountedPass {
    GlTexture counts;
    Image value;     // RGBA, top row first
    uint64_t totalFetches = 0;
    size_t surfacePixels = 0;
};

CountedPass countConeFetches(bool gi, const VoxelGrid& grid, const GBuffer& gbuffer, float radius, float sky,
                             const ParamMap& params) {
    // The renderer's own binding of the pass (src/cone/cone_trace.cpp), so the copy matches it.
    const float diagonal = glm::length(glm::vec3(grid.resolution)) * grid.voxelSize;
    conedetail::BoundConePass bound =
        conedetail::bindConePass(gi, grid, gbuffer, gi ? 2.f * diagonal : radius, sky, readConeSettings(params));
    if (bound.slices.count() > 1)
        throw UsageError("the fetch count marches all cones in one dispatch; these settings need " +
                         std::to_string(bound.slices.count()) + " (CONE_LOOP_BUDGET)");
    const GLuint program = cachedProgram(coneCountProgramKey(gi, bound.directional, bound.depthLevels, bound.sharpen, bound.sheets));
    CountedPass out;
    GlTexture value = createTexture2D(GL_RGBA32F, gbuffer.width, gbuffer.height);
    out.counts = createTexture2D(GL_R32UI, gbuffer.width, gbuffer.height);
    glBindImageTexture(0, value.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, out.counts.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glUseProgram(program);
    glDispatchCompute(groupCount(gbuffer.width, gpu::CONE_LOCAL_SIZE), groupCount(gbuffer.height, gpu::CONE_LOCAL_SIZE),
                      1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    glUseProgram(0);
    GlContext::shared().checkErrors("bench cone_count");

    out.value = readTexture2D(value.id(), gbuffer.width, gbuffer.height, 4);
    std::vector<uint32_t> counts(size_t(gbuffer.width) * gbuffer.height);
    glGetTextureImage(out.counts.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(counts.size() * 4), counts.data());
    GlContext::shared().checkErrors("bench cone_count readback");
    for (uint32_t c : counts) {
        out.totalFetches += c;
        out.surfacePixels += c > 0;
    }
    return out;
}

// A 128^3 RGBA16F texture with a full mip chain of pseudo-random values (fixed seed).
GlTexture makeFetchVolume(int size) {
    int levels = 1;
    while ((size >> levels) > 0) ++levels;
    GlTexture t = createTexture3D(GL_RGBA16F, size, size, size, levels);
    std::vector<float> data(size_t(size) * size * size * 4);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uni(0.f, 1.f);
    for (float& v : data) v = uni(rng);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, size, size, size, GL_RGBA, GL_FLOAT, data.data());
    glGenerateTextureMipmap(t.id());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return t;
}

// Median wall time (ms, after glFinish) of the bare fetch shader doing `counts` fetches per pixel.
double timeBareFetches(const GlTexture& volume, int volumeSize, const GlTexture& counts, int width, int height,
                       int runs) {
    const GLuint program = cachedProgram(fetchBenchProgramKey());
    GlTexture out = createTexture2D(GL_R32F, width, height);
    int maxLod = 0;
    while ((volumeSize >> (maxLod + 1)) > 0) ++maxLod;
    std::vector<double> ms;
    for (int run = 0; run <= runs; ++run) {  // run 0 warms up
        glUseProgram(program);
        glProgramUniform4i(program, 0, width, height, volumeSize, maxLod);
        glBindTextureUnit(0, volume.id());
        glBindImageTexture(1, counts.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        glFinish();
        const double start = nowMs();
        glDispatchCompute(groupCount(width, 8), groupCount(height, 8), 1);
        glFinish();
        if (run > 0) ms.push_back(nowMs() - start);
        glUseProgram(0);
    }
    GlContext::shared().checkErrors("bench fetch");
    return median(ms);
}

void benchScene(const BenchScene& bs, const Options& opt) {
    std::printf("\n== %s: %zu triangles, %zu lights, %dx%d, voxelRes %d, R = %.2f, reference %d spp\n",
                bs.name.c_str(), bs.scene.triangleCount(), bs.scene.lights.size(), opt.size, opt.size,
                opt.voxelRes, bs.radius, opt.spp);
    std::fflush(stdout);
    RenderSession session(bs.scene);
    RenderRequest r;
    r.camera = bs.camera;
    r.width = r.height = opt.size;
    r.radius = bs.radius;
    r.voxelRes = opt.voxelRes;

    // Reference AO and GI (timed once).
    r.ao = "reference";
    r.gi = "reference";
    r.spp = opt.spp;
    r.aovs = {"ao", "indirect", "depth", "ao_stderr", "indirect_stderr"};
    const double refStart = nowMs();
    RenderResult ref = session.render(r);
    const double refMs = nowMs() - refStart;
    GlContext::shared().checkErrors("bench reference");
    const Image mask = surfaceMask(ref.aovs.at("depth"));

    // VCT: every pass anew each run (reuseSceneData = false), one warm-up, median of the runs.
    r.ao = "vct";
    r.gi = "vct";
    r.reuseSceneData = false;
    r.aovs = {"ao", "indirect"};
    r.params = opt.params;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<double> totalMs;
    RenderResult vctResult;
    for (int run = 0; run <= opt.runs; ++run) {
        vctResult = session.render(r);
        GlContext::shared().checkErrors("bench vct");
        if (run == 0) continue;
        totalMs.push_back(vctResult.totalMs);
        for (const auto& p : vctResult.passes) passMs[p.name].push_back(p.wallMs);
    }
    const Image& ao = vctResult.aovs.at("ao");
    const Image& gi = vctResult.aovs.at("indirect");
    const ErrorMetrics aoErr = computeErrorMetrics(ao, ref.aovs.at("ao"), &mask);
    const ErrorMetrics giErr = computeErrorMetrics(gi, ref.aovs.at("indirect"), &mask, -1, 1.0);
    const double giMean = imageMean(gi, &mask), refGiMean = imageMean(ref.aovs.at("indirect"), &mask);

    std::printf("passes (median ms of %d runs):", opt.runs);
    for (const char* name : {"voxelize", "inject", "bounce", "mips", "cone_ao", "cone_gi"})
        std::printf("  %s %.1f", name, passMs.count(name) ? median(passMs[name]) : -1.0);
    std::printf("  | whole render %.1f  | reference (AO + GI, %d spp) %.0f\n", median(totalMs), opt.spp, refMs);
    std::printf("AO  vs reference: rmse %.4f  mae %.4f  bias %+.4f  ssim %.3f  (reference stderr/pixel %.4f)\n",
                aoErr.rmse, aoErr.mae, aoErr.bias, aoErr.ssim, imageMean(ref.aovs.at("ao_stderr"), &mask));
    std::printf("GI  vs reference: rmse %.4f  mae %.4f  bias %+.4f  mean %.4f vs %.4f (%+.1f%%)  "
                "(reference stderr/pixel %.4f)\n",
                giErr.rmse, giErr.mae, giErr.bias, giMean, refGiMean, 100.0 * (giMean / refGiMean - 1.0),
                imageMean(ref.aovs.at("indirect_stderr"), &mask));
    std::fflush(stdout);

    // Fetch counts over a grid and G-buffer built as the renderer builds them.
    const GpuScene gpu = uploadScene(bs.scene);
    const View view = makeView(bs.camera, opt.size, opt.size);
    PassTimer timer;
    const GBuffer gbuffer = renderGBuffer(gpu, view, timer);
    VoxelGrid grid = voxelizeScene(gpu, bs.scene.bounds, opt.voxelRes, opt.params, timer);
    injectRadiance(grid, gpu, bs.scene, opt.params, timer);
    traceVoxelBounces(grid, r.sky, readConeSettings(opt.params), opt.params, timer);
    buildMips(grid, readConeSettings(opt.params).anisotropic, timer);
    GlContext::shared().checkErrors("bench grid");

    const int volumeSize = 128;
    const GlTexture volume = makeFetchVolume(volumeSize);
    std::printf("%-8s %13s %12s %10s %12s | %10s %12s | %6s %s\n", "pass", "fetches", "per surf px", "pass ms",
                "Mfetch/s", "bare ms", "Mfetch/s", "ratio", "copy check (max |diff|)");
    for (bool isGi : {false, true}) {
        const char* name = isGi ? "cone_gi" : "cone_ao";
        CountedPass counted = countConeFetches(isGi, grid, gbuffer, bs.radius, r.sky, opt.params);
        const double diff = maxAbsDiff(counted.value, isGi ? gi : ao, 4);
        const double passTime = median(passMs[name]);
        const double bareTime = timeBareFetches(volume, volumeSize, counted.counts, opt.size, opt.size, opt.runs);
        const double passRate = counted.totalFetches / (passTime * 1e3);
        const double bareRate = counted.totalFetches / (bareTime * 1e3);
        std::printf("%-8s %13llu %12.1f %10.1f %12.1f | %10.1f %12.1f | %6.2f %.3g\n", name,
                    (unsigned long long)counted.totalFetches,
                    counted.surfacePixels ? double(counted.totalFetches) / counted.surfacePixels : 0.0, passTime,
                    passRate, bareTime, bareRate, passRate / bareRate, diff);
        std::fflush(stdout);
    }
}

}  // namespace

static int benchRun(int argc, char** argv) {
    Options opt;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--size") opt.size = std::atoi(argv[i + 1]);
        else if (a == "--voxel-res") opt.voxelRes = std::atoi(argv[i + 1]);
        else if (a == "--spp") opt.spp = std::atoi(argv[i + 1]);
        else if (a == "--runs") opt.runs = std::max(1, std::atoi(argv[i + 1]));
        else if (a == "--scene") opt.scenes.push_back(argv[i + 1]);
        else if (a == "--param") opt.params.set(argv[i + 1]);
        else {
            std::fprintf(stderr, "bench_vct: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    if (opt.scenes.empty()) opt.scenes = {"cornell", "sponza"};
    const GlContextInfo& info = GlContext::shared().info();
    std::printf("bench_vct: GL renderer '%s' (%s), %u cores; ratio = cone pass fetch rate / bare fetch rate\n",
                info.renderer.c_str(), info.version.c_str(), std::thread::hardware_concurrency());
    for (const auto& name : opt.scenes) {
        BenchScene bs;
        if (loadBenchScene(name, bs)) benchScene(bs, opt);
    }
    return 0;
}

int main(int argc, char** argv) { return vct::benchMain("bench_vct", benchRun, argc, argv); }
