#include "reference/reference_ao.h"

#include "reference/camera_rays.h"
#include "util/progress.h"
#include "reference/sampler.h"
#include "reference/sampling_math.h"
#include "core/errors.h"
#include "core/params.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vct {

void ReferenceSettings::validate() const {
    auto fail = [](const std::string& what) { throw InternalError("ReferenceSettings", what); };
    if (!(radius > 0.f) || !std::isfinite(radius)) fail("radius must be finite and > 0, got " + std::to_string(radius));
    if (spp < 1 || spp > (1 << 20)) fail("spp must be in [1, 2^20], got " + std::to_string(spp));
    if (!(targetStderr >= 0.f) || !std::isfinite(targetStderr)) fail("targetStderr must be finite and >= 0");
    if (minSpp < 1) fail("minSpp must be >= 1");
    if (replicates < 1 || replicates > kMaxReplicates) fail("replicates must be in [1, 8]");
    if (bounces < 1 || bounces > 1024) fail("bounces must be in [1, 1024], got " + std::to_string(bounces));
    if (rouletteBounce < 1) fail("rouletteBounce must be >= 1");
    if (!(sky >= 0.f) || !std::isfinite(sky)) fail("sky must be finite and >= 0");
}

const SettingsTable<ReferenceSettings>& referenceSettings() {
    static const std::vector<std::pair<std::string, RayMode>> modes = {
        {"single", RayMode::Single}, {"stream", RayMode::Stream}, {"packet8", RayMode::Packet8},
        {"packet16", RayMode::Packet16}};
    static const auto table =
        SettingsTable<ReferenceSettings>()
            .integer("reference.spp", &ReferenceSettings::spp, [](const ReferenceSettings& s) { return s.spp; }, "--spp",
                     1, 1 << 20, "reference samples per pixel (budget)")
            .custom({"reference.seed", "--seed", "[0, 2147483647]", "reference sample scramble seed"},
                    [](ReferenceSettings& s, const ParamMap& p) {
                        s.seed = uint64_t(p.getInt("reference.seed", int(s.seed), 0, std::numeric_limits<int>::max()));
                    })
            .real("reference.target-stderr", &ReferenceSettings::targetStderr, 0.f, 1e30f,
                  "stop once the image-mean standard error is below this (0 = off)")
            .integer("reference.min-spp", &ReferenceSettings::minSpp, 1, 1 << 20, "no early stop before this many spp")
            .integer("reference.replicates", &ReferenceSettings::replicates, 1, kMaxReplicates,
                     "independent sample scrambles behind the error bar (1 = one stream)")
            .integer("reference.bounces", &ReferenceSettings::bounces, 1, 1024, "GI: max diffuse reflections per path")
            .integer("reference.roulette-bounce", &ReferenceSettings::rouletteBounce, 1, 1 << 20,
                     "GI: Russian roulette from this bounce on")
            .choice("reference.ray-mode", &ReferenceSettings::rayMode, modes, "how occlusion rays are handed to Embree")
            .flag("reference.cone-model", &ReferenceSettings::coneModel,
                  "VCT's cone model (the cone set of vct.cones and vct.aperture, exact visibility and radiance in "
                  "each cone) instead of the hemisphere, for AO and for GI's every reflection: what VCT converges "
                  "to as its voxels refine")
            .choice("reference.pixel", &ReferenceSettings::pixelArea, {{"center", false}, {"area", true}},
                    "reference: AO at the G-buffer's pixel centres, or averaged over the pixel with jittered "
                    "primary rays (box filter, as Cycles)");
    return table;
}

ReferenceSettings referenceSettingsFromParams(const ParamMap& params, ReferenceSettings base) {
    return referenceSettings().read(params, base);
}

namespace {

Image toImage(const std::vector<float>& values, int width, int height) {
    if (width <= 0 || height <= 0) throw InternalError("ReferenceAO", "not an image (point mode result)");
    Image img(width, height, 1);
    img.pixels = values;
    return img;
}


// Per-point statistics from the replicate counts -> per-point standard error and that of
// the mean over valid points. `perReplicate` samples went into each replicate.
void finishStatistics(ReferenceAO& out, const std::vector<uint32_t>& open, int perReplicate, int replicates,
                      const std::vector<uint8_t>& valid) {
    double sumVar = 0.0;
    size_t validCount = 0;
    for (size_t i = 0; i < valid.size(); ++i) {
        if (!valid[i]) {
            out.ao[i] = 1.f;
            out.standardError[i] = 0.f;
            continue;
        }
        double se = 0.0, mean = 0.0;
        if (replicates > 1) {
            double m[kMaxReplicates];
            for (int r = 0; r < replicates; ++r) {
                m[r] = double(open[i * replicates + r]) / perReplicate;
                mean += m[r] / replicates;
            }
            double ss = 0.0;
            for (int r = 0; r < replicates; ++r) ss += (m[r] - mean) * (m[r] - mean);
            se = std::sqrt(ss / (replicates * (replicates - 1.0)));
        } else {  // one stream: i.i.d. Bernoulli formula
            double n = perReplicate;
            mean = open[i] / n;
            se = n > 1 ? std::sqrt(mean * (1.0 - mean) / (n - 1.0)) : 0.5;
        }
        out.ao[i] = float(mean);
        out.standardError[i] = float(se);
        sumVar += se * se;
        ++validCount;
    }
    out.meanStderr = validCount ? std::sqrt(sumVar) / double(validCount) : 0.0;
}

struct PointSetup {
    glm::vec3 origin;
    glm::vec3 geomNormal;
    Frame frame;
};

}  // namespace

Image ReferenceAO::aoImage() const { return toImage(ao, width, height); }
Image ReferenceAO::stderrImage() const { return toImage(standardError, width, height); }

ReferenceAO referenceAO(const EmbreeScene& scene, const std::vector<SurfacePoint>& points,
                        const ReferenceSettings& settings, const ConeModelSampler& cones) {
    settings.validate();
    const size_t n = points.size();
    std::vector<PointSetup> setup(n);
    std::vector<uint8_t> valid(n, 0);
    // G-buffer positions carry the rasterizer's interpolation error and we do not know their
    // triangle: floor the offset scale at a small fraction of the scene's coordinate range.
    const float errorFloor = scene.sceneMaxAbs() * 0x1p-8f;
    for (size_t i = 0; i < n; ++i) {
        const SurfacePoint& sp = points[i];
        if (!sp.valid) continue;
        if (!finite3(sp.position) || !finite3(sp.normal) || !finite3(sp.geomNormal))
            throw InternalError("referenceAO", "surface point " + std::to_string(i) + " is not finite");
        float ln = glm::length(sp.normal), lg = glm::length(sp.geomNormal);
        if (!(ln > 0.f) || !(lg > 0.f))
            throw InternalError("referenceAO", "surface point " + std::to_string(i) + " has a zero normal");
        glm::vec3 ns = sp.normal / ln, ng = sp.geomNormal / lg;
        if (glm::dot(ns, ng) < 0.f) ng = -ng;
        float scale = std::max(maxAbsComponent(sp.position), errorFloor);
        setup[i] = {offsetRayOrigin(sp.position, ng, scale), ng, Frame::fromZ(ns)};
        valid[i] = 1;
    }

    ReferenceAO out;
    out.ao.assign(n, 1.f);
    out.standardError.assign(n, 0.f);
    const SampleSchedule schedule = sampleSchedule(settings.spp, settings.replicates);
    const int K = schedule.replicates;
    std::vector<uint32_t> open(n * size_t(K), 0);
    std::atomic<uint64_t> rays{0};
    const float radius = settings.radius;
    ProgressBar progress("reference AO", uint64_t(n) * uint64_t(schedule.spp), settings.progress);
    auto start = std::chrono::steady_clock::now();

    int done = 0;
    for (int total : schedule.totals) {
        progress.setTotal(uint64_t(n) * uint64_t(schedule.spp), "spp " + std::to_string(total));
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& r) {
            OcclusionBatch batch(scene, settings.rayMode);
            // Owner = point * K + replicate.
            auto visit = [&](uint32_t owner, bool visible) { open[owner] += visible ? 1u : 0u; };
            for (size_t i = r.begin(); i != r.end(); ++i) {
                if (!valid[i]) continue;
                const PointSetup& ps = setup[i];
                const ReplicatedPair directions(streamSeed(settings.seed, i), K, 0);
                for (int k = done; k < total; ++k) {
                    const glm::vec2 u = directions.sample(uint32_t(k));
                    const uint32_t owner = uint32_t(i * size_t(K) + size_t(k % K));
                    glm::vec3 w;
                    if (cones.empty()) {
                        w = ps.frame.toWorld(sampleCosineHemisphere(u));
                        if (glm::dot(w, ps.geomNormal) <= 0.f) continue;  // below the surface: occluded
                    } else {
                        const ConeModelSample cs = cones.sample(u, ps.frame.z, ps.geomNormal, cones.rotationOf(i));
                        if (cs.closed) continue;
                        if (cs.belowPlane) {
                            visit(owner, true);
                            continue;
                        }
                        w = cs.direction;
                    }
                    batch.add(ps.origin, w, radius, owner, visit);
                }
            }
            batch.flush(visit);
            rays.fetch_add(batch.raysTraced());
            progress.advance(uint64_t(r.size()) * uint64_t(total - done));
        });
        done = total;
        finishStatistics(out, open, total / K, K, valid);
        if (settings.targetStderr > 0.f && done >= settings.minSpp && out.meanStderr < settings.targetStderr) break;
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.sppUsed = done;
    out.raysTraced = rays.load();
    out.raysPerSecond = out.seconds > 0 ? double(out.raysTraced) / out.seconds : 0.0;
    return out;
}

ReferenceAO referenceAO(const Scene& scene, const std::vector<SurfacePoint>& points,
                        const ReferenceSettings& settings, const ConeModelSampler& cones) {
    EmbreeScene embree(scene);
    return referenceAO(embree, points, settings, cones);
}

ReferenceAO referenceAOPixelArea(const EmbreeScene& scene, const View& view, const ReferenceSettings& settings) {
    settings.validate();
    if (view.width <= 0 || view.height <= 0) throw InternalError("referenceAOPixelArea", "empty view");
    const size_t n = size_t(view.width) * size_t(view.height);
    ReferenceAO out;
    out.width = view.width;
    out.height = view.height;
    out.ao.assign(n, 1.f);
    out.standardError.assign(n, 0.f);
    const SampleSchedule schedule = sampleSchedule(settings.spp, settings.replicates);
    const int K = schedule.replicates;
    std::vector<uint32_t> open(n * size_t(K), 0);
    std::vector<uint8_t> valid(n, 0);  // any sample hit a surface
    std::atomic<uint64_t> rays{0}, primary{0};
    const float radius = settings.radius;
    const float inf = std::numeric_limits<float>::infinity();
    ProgressBar progress("reference AO (pixel area)", uint64_t(n) * uint64_t(schedule.spp), settings.progress);
    auto start = std::chrono::steady_clock::now();

    int done = 0;
    for (int total : schedule.totals) {
        progress.setTotal(uint64_t(n) * uint64_t(schedule.spp), "spp " + std::to_string(total));
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& r) {
            OcclusionBatch batch(scene, settings.rayMode);
            auto visit = [&](uint32_t owner, bool visible) { open[owner] += visible ? 1u : 0u; };
            uint64_t primaryCount = 0;
            // A pixel's primary rays leave the eye through one pixel: traced as coherent
            // streams of up to kPrimaryBatch rays, they share their BVH traversal.
            constexpr int kPrimaryBatch = 64;
            RTCRayHit primaries[kPrimaryBatch];
            for (size_t i = r.begin(); i != r.end(); ++i) {
                const int x = int(i % size_t(view.width)), y = int(i / size_t(view.width));
                const uint64_t stream = streamSeed(settings.seed, i);
                const ReplicatedPair jitters(stream, K, 0), directions(stream, K, 1);
                for (int first = done; first < total; first += kPrimaryBatch) {
                    const int count = std::min(kPrimaryBatch, total - first);
                    for (int j = 0; j < count; ++j) {
                        const glm::vec2 jitter = jitters.sample(uint32_t(first + j));
                        const CameraRay cr = cameraRay(view, float(x) + jitter.x, float(y) + jitter.y);
                        primaries[j] = rayHit(cr.origin, cr.direction, cr.tnear, inf);
                    }
                    scene.intersectCoherent(primaries, unsigned(count));
                    primaryCount += uint64_t(count);
                    for (int j = 0; j < count; ++j) {
                        const int k = first + j;
                        const uint32_t owner = uint32_t(i * size_t(K) + size_t(k % K));
                        const RTCRayHit& p = primaries[j];
                        if (p.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
                            open[owner] += 1;  // sky sample: A = 1
                            continue;
                        }
                        valid[i] = 1;
                        const glm::vec3 incoming(p.ray.dir_x, p.ray.dir_y, p.ray.dir_z);
                        SurfaceHit h = scene.surfaceAt(p.hit.primID, p.hit.u, p.hit.v, incoming);
                        glm::vec3 w = Frame::fromZ(h.shadingNormal)
                                          .toWorld(sampleCosineHemisphere(directions.sample(uint32_t(k))));
                        if (glm::dot(w, h.geomNormal) <= 0.f) continue;
                        batch.add(offsetRayOrigin(h.position, h.geomNormal, h.errorScale), w, radius, owner, visit);
                    }
                }
            }
            batch.flush(visit);
            rays.fetch_add(batch.raysTraced());
            primary.fetch_add(primaryCount);
            progress.advance(uint64_t(r.size()) * uint64_t(total - done));
        });
        done = total;
        // Pixels where no sample hit are sky (A = 1 exactly); partly covered pixels keep their
        // sky samples as 1s in the Bernoulli mean.
        finishStatistics(out, open, total / K, K, valid);
        if (settings.targetStderr > 0.f && done >= settings.minSpp && out.meanStderr < settings.targetStderr) break;
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.sppUsed = done;
    out.raysTraced = rays.load();
    out.primaryRays = primary.load();
    out.raysPerSecond = out.seconds > 0 ? double(out.raysTraced + out.primaryRays) / out.seconds : 0.0;
    return out;
}

ReferenceAO referenceAOPixelArea(const Scene& scene, const View& view, const ReferenceSettings& settings) {
    EmbreeScene embree(scene);
    return referenceAOPixelArea(embree, view, settings);
}

std::vector<SurfacePoint> surfacePointsAtPixelCentres(const EmbreeScene& scene, const View& view) {
    const size_t n = size_t(std::max(0, view.width)) * size_t(std::max(0, view.height));
    std::vector<SurfacePoint> points(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const int x = int(i % size_t(view.width)), y = int(i / size_t(view.width));
            CameraRay cr = cameraRay(view, float(x) + 0.5f, float(y) + 0.5f);
            uint32_t tri;
            float u, v, t;
            if (!scene.intersect(cr.origin, cr.direction, cr.tnear, std::numeric_limits<float>::infinity(), &tri,
                                 &u, &v, &t))
                continue;
            SurfaceHit h = scene.surfaceAt(tri, u, v, cr.direction);
            points[i] = {h.position, h.shadingNormal, h.geomNormal, true};
        }
    });
    return points;
}

}  // namespace vct
