#include "reference/reference_gi.h"

#include "reference/camera_rays.h"
#include "util/progress.h"
#include "reference/sampler.h"
#include "reference/sampling_math.h"
#include "scene/texture_sampler.h"
#include "core/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vct {

namespace {

constexpr float kInvPi = 0.31830988618f;
constexpr float kInf = std::numeric_limits<float>::infinity();

float maxComponent(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

uint32_t materialOf(const Scene& s, uint32_t tri) {
    return tri < s.triangleMaterial.size() ? s.triangleMaterial[tri] : uint32_t(-1);
}

// Emitted radiance leaving hit `h` back along the ray. A single-sided glTF material's back
// face is culled, so it emits only from its front; doubleSided materials emit both ways.
glm::vec3 emissionTowardRay(const Scene& s, const SurfaceHit& h) {
    const uint32_t m = materialOf(s, h.triangle);
    const bool twoSided = m < s.materials.size() && s.materials[m].doubleSided;
    if (!h.frontFacing && !twoSided) return glm::vec3(0.f);
    return materialEmission(s, m, h.uv);
}

// Emissive triangles, chosen with probability proportional to area x max(emissiveFactor)
// (textures modulate emission but the factor bounds it, so the pdf is > 0 wherever Le > 0).
struct EmitterTable {
    std::vector<uint32_t> triangles;
    std::vector<double> cdf;          // inclusive, last = 1
    std::vector<float> areaPdf;       // per scene triangle: P(triangle) / area, 0 for non-emitters

    explicit EmitterTable(const Scene& s) : areaPdf(s.triangles.size(), 0.f) {
        std::vector<double> weights;
        double total = 0.0;
        for (uint32_t t = 0; t < s.triangles.size(); ++t) {
            uint32_t m = materialOf(s, t);
            if (m >= s.materials.size() || !s.materials[m].isEmissive()) continue;
            const glm::uvec3& tri = s.triangles[t];
            double area = 0.5 * double(glm::length(glm::cross(s.positions[tri.y] - s.positions[tri.x],
                                                              s.positions[tri.z] - s.positions[tri.x])));
            double w = area * double(maxComponent(s.materials[m].emissiveFactor));
            if (!(w > 0.0) || !std::isfinite(w)) continue;
            triangles.push_back(t);
            weights.push_back(w);
            total += w;
        }
        double running = 0.0;
        for (size_t i = 0; i < triangles.size(); ++i) {
            running += weights[i];
            cdf.push_back(running / total);
            const glm::uvec3& tri = s.triangles[triangles[i]];
            double area = 0.5 * double(glm::length(glm::cross(s.positions[tri.y] - s.positions[tri.x],
                                                              s.positions[tri.z] - s.positions[tri.x])));
            areaPdf[triangles[i]] = float(weights[i] / total / area);
        }
        if (!cdf.empty()) cdf.back() = 1.0;
    }
    bool empty() const { return triangles.empty(); }
    uint32_t pick(float u) const {
        size_t i = size_t(std::lower_bound(cdf.begin(), cdf.end(), double(u)) - cdf.begin());
        return triangles[std::min(i, triangles.size() - 1)];
    }
};

struct PathResult {
    glm::vec3 emission{0.f}, direct{0.f}, indirect{0.f};
    bool hit = false;
    uint32_t rays = 0;
};

float powerHeuristic(float a, float b) {
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.f ? a2 / (a2 + b2) : 0.f;
}

// Irradiance at p (unshadowed) and unit direction towards a punctual light.
bool punctualLight(const Light& light, const glm::vec3& p, glm::vec3* wi, float* distance, glm::vec3* irradiance) {
    if (light.type == LightType::Directional) {
        *wi = -glm::normalize(light.direction);
        *distance = kInf;
        *irradiance = light.color;
        return true;
    }
    glm::vec3 d = light.position - p;
    float d2 = glm::dot(d, d);
    if (!(d2 > 0.f)) return false;
    *distance = std::sqrt(d2);
    *wi = d / *distance;
    glm::vec3 e = light.color / d2;
    if (light.type == LightType::Spot) e *= spotAttenuation(light, glm::dot(glm::normalize(light.direction), -*wi));
    *irradiance = e;
    return maxComponent(e) > 0.f;
}

struct PathTracer {
    const EmbreeScene& scene;
    const Scene& s;
    const EmitterTable& emitters;
    const ReferenceSettings& settings;
    // GI's cone model (cone_model.h) in place of the cosine lobe at every reflection, or
    // empty: the rendering equation.
    const ConeModelSampler& cones;

    // Dimension pairs of the sampler: 0 = pixel jitter; bounce b uses 1 + 3b (light choice,
    // roulette), 2 + 3b (point on the emitter), 3 + 3b (BSDF direction).
    int replicates;

    glm::vec2 sample(uint64_t stream, int dimPair, uint32_t index) const {
        return replicatedSample(stream, replicates, uint32_t(dimPair), index);
    }

    // `rotation`: the cone model's turn of the cone set at the first reflection (vct.jitter's
    // per-pixel turn; the bounces' gathers never turn it).
    PathResult trace(const CameraRay& cr, uint64_t stream, uint32_t index, float rotation = 0.f) const {
        PathResult out;
        uint32_t tri;
        float u, v, t;
        ++out.rays;
        if (!scene.intersect(cr.origin, cr.direction, cr.tnear, kInf, &tri, &u, &v, &t)) return out;
        out.hit = true;
        SurfaceHit h = scene.surfaceAt(tri, u, v, cr.direction);
        out.emission = materialEmission(s, materialOf(s, tri), h.uv);

        glm::vec3 throughput(1.f);
        for (int bounce = 0; bounce < settings.bounces; ++bounce) {
            // The definition of indirect: Lo - Le - the direct term from (punctual) lights, so
            // light from emissive surfaces is indirect even after one reflection, as in every
            // renderer method (the raster direct pass sees punctual lights only).
            glm::vec3& target = bounce == 0 ? out.direct : out.indirect;
            const glm::vec3 albedo = materialAlbedo(s, materialOf(s, h.triangle), h.uv, h.color);
            if (maxComponent(albedo) <= 0.f) break;
            const glm::vec3 origin = offsetRayOrigin(h.position, h.geomNormal, h.errorScale);
            const glm::vec3 f = albedo * kInvPi;
            const bool model = !cones.empty();
            const float turn = bounce == 0 ? rotation : 0.f;
            glm::vec2 uChoice = sample(stream, 1 + 3 * bounce, index);

            // Next-event estimation: every punctual light.
            for (const Light& light : s.lights) {
                glm::vec3 wi, e;
                float dist;
                if (!punctualLight(light, h.position, &wi, &dist, &e)) continue;
                float cosS = glm::dot(h.shadingNormal, wi);
                if (cosS <= 0.f || glm::dot(h.geomNormal, wi) <= 0.f) continue;
                ++out.rays;
                bool blocked = std::isinf(dist) ? scene.occluded(origin, wi, kInf)
                                                : scene.occluded(origin, light.position - origin, 1.f);
                if (!blocked) target += throughput * f * e * cosS;
            }
            // Next-event estimation: one point on one emissive triangle, MIS-weighted.
            if (!emitters.empty()) {
                uint32_t lt = emitters.pick(uChoice.x);
                glm::vec3 b = sampleUniformTriangle(sample(stream, 2 + 3 * bounce, index));
                const glm::uvec3& ti = s.triangles[lt];
                glm::vec3 q = b.x * s.positions[ti.x] + b.y * s.positions[ti.y] + b.z * s.positions[ti.z];
                glm::vec3 d = q - h.position;
                float dist2 = glm::dot(d, d);
                if (dist2 > 0.f && lt != h.triangle) {
                    glm::vec3 wi = d / std::sqrt(dist2);
                    SurfaceHit lh = scene.surfaceAt(lt, b.y, b.z, wi);  // normals face p
                    float cosL = -glm::dot(lh.geomNormal, wi);
                    // The lobe: cos / pi, or the cone model's density (which is also its pdf).
                    float lobe = model ? cones.density(wi, h.shadingNormal, h.geomNormal, turn)
                                       : std::max(glm::dot(h.shadingNormal, wi), 0.f) * kInvPi;
                    if (lobe > 0.f && cosL > 0.f && glm::dot(h.geomNormal, wi) > 0.f) {
                        float pdfLight = emitters.areaPdf[lt] * dist2 / cosL;
                        glm::vec3 le = emissionTowardRay(s, lh);
                        if (maxComponent(le) > 0.f && pdfLight > 0.f && std::isfinite(pdfLight)) {
                            glm::vec3 end = offsetRayOrigin(lh.position, lh.geomNormal, lh.errorScale);
                            ++out.rays;
                            if (!scene.occluded(origin, end - origin, 1.f)) {
                                float w = powerHeuristic(pdfLight, lobe);
                                out.indirect += throughput * albedo * le * (lobe * w / pdfLight);
                            }
                        }
                    }
                }
            }

            // BSDF sampling: cosine-weighted, so f cos / pdf = albedo; the cone model samples
            // its own lobe, so lobe / pdf = 1 as well.
            glm::vec3 wi;
            float pdfBsdf;
            if (model) {
                const ConeModelSample c =
                    cones.sample(sample(stream, 3 + 3 * bounce, index), h.shadingNormal, h.geomNormal, turn);
                if (c.closed) break;  // a closed cone gathers nothing
                if (c.belowPlane) {   // open: the cone never sees its own surface, so the sky
                    out.indirect += throughput * albedo * settings.sky;
                    break;
                }
                wi = c.direction;
                pdfBsdf = cones.density(wi, h.shadingNormal, h.geomNormal, turn);
            } else {
                wi = Frame::fromZ(h.shadingNormal).toWorld(sampleCosineHemisphere(sample(stream, 3 + 3 * bounce, index)));
                if (glm::dot(wi, h.geomNormal) <= 0.f) break;  // below the surface
                pdfBsdf = glm::dot(wi, h.shadingNormal) * kInvPi;
            }
            throughput *= albedo;
            ++out.rays;
            if (!scene.intersect(origin, wi, 0.f, kInf, &tri, &u, &v, &t)) {
                out.indirect += throughput * settings.sky;  // sky light is indirect by definition
                break;
            }
            h = scene.surfaceAt(tri, u, v, wi);
            glm::vec3 le = emissionTowardRay(s, h);
            if (maxComponent(le) > 0.f) {
                float cosL = std::abs(glm::dot(h.geomNormal, wi));
                float pdfLight = cosL > 0.f ? emitters.areaPdf[tri] * t * t / cosL : 0.f;
                float w = std::isfinite(pdfLight) ? powerHeuristic(pdfBsdf, pdfLight) : 0.f;
                out.indirect += throughput * le * w;
            }
            // Russian roulette: survive with probability q, divide by q (unbiased).
            if (bounce + 1 >= settings.rouletteBounce) {
                float q = std::min(1.f, std::max(0.05f, maxComponent(throughput)));
                if (uChoice.y >= q) break;
                throughput /= q;
            }
        }
        return out;
    }
};

}  // namespace

float spotAttenuation(const Light& light, float cosAngle) {
    float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
    float scale = 1.f / std::max(0.001f, cosInner - cosOuter);
    float t = std::min(1.f, std::max(0.f, (cosAngle - cosOuter) * scale));
    return t * t;
}

ReferenceGI referenceGI(const EmbreeScene& scene, const View& view, const ReferenceSettings& settings,
                        bool pixelArea, const ConeModelSampler& cones) {
    settings.validate();
    if (view.width <= 0 || view.height <= 0) throw InternalError("referenceGI", "empty view");
    const Scene& s = scene.scene();
    for (size_t i = 0; i < s.lights.size(); ++i)
        if (!finite3(s.lights[i].color) || !finite3(s.lights[i].position) || !finite3(s.lights[i].direction))
            throw std::runtime_error("referenceGI: light " + std::to_string(i) + " ('" + s.lights[i].name +
                                     "') is not finite");
    const EmitterTable emitters(s);
    const SampleSchedule schedule = sampleSchedule(settings.spp, settings.replicates);
    const int K = schedule.replicates;
    const PathTracer tracer{scene, s, emitters, settings, cones, K};

    const int W = view.width, H = view.height;
    const size_t n = size_t(W) * size_t(H);
    // Per pixel running sums (double: thousands of samples of radiances up to 1e6).
    struct Sums {
        glm::dvec3 emission{0.0}, direct{0.0}, indirect{0.0}, indirectSq{0.0};
        double indirectMeanSq = 0.0;
        glm::dvec3 replicateIndirect[kMaxReplicates] = {};
        uint32_t hits = 0, samples = 0;
    };
    std::vector<Sums> sums(n);
    // Standard error of the indirect radiance per channel (and of the channel mean, as the
    // 4th component) from the replicate means, or the i.i.d. formula for one stream.
    auto indirectStderr = [&](const Sums& acc) {
        const double ns = std::max(1u, acc.samples);
        glm::dvec4 se(0.0);
        if (K > 1) {
            const double perRep = ns / K;
            glm::dvec4 mean(0.0), ss(0.0);
            for (int r = 0; r < K; ++r) {
                glm::dvec3 m = acc.replicateIndirect[r] / perRep;
                mean += glm::dvec4(m, (m.x + m.y + m.z) / 3.0) / double(K);
            }
            for (int r = 0; r < K; ++r) {
                glm::dvec3 m = acc.replicateIndirect[r] / perRep;
                glm::dvec4 d = glm::dvec4(m, (m.x + m.y + m.z) / 3.0) - mean;
                ss += d * d;
            }
            se = glm::sqrt(ss / (K * (K - 1.0)));
        } else if (ns > 1) {
            glm::dvec3 mean = acc.indirect / ns;
            double mm = (mean.x + mean.y + mean.z) / 3.0;
            glm::dvec3 var = glm::max(acc.indirectSq / ns - mean * mean, 0.0) * ns / (ns - 1);
            double varM = std::max(0.0, acc.indirectMeanSq / ns - mm * mm) * ns / (ns - 1);
            se = glm::sqrt(glm::dvec4(var, varM) / ns);
        }
        return se;
    };
    std::atomic<uint64_t> rays{0};
    ProgressBar progress("reference GI", uint64_t(n) * uint64_t(schedule.spp), settings.progress);
    auto start = std::chrono::steady_clock::now();

    ReferenceGI out;
    out.width = W;
    out.height = H;
    int done = 0;
    for (int total : schedule.totals) {
        progress.setTotal(uint64_t(n) * uint64_t(schedule.spp), "spp " + std::to_string(total));
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 16), [&](const tbb::blocked_range<size_t>& r) {
            uint64_t localRays = 0;
            for (size_t i = r.begin(); i != r.end(); ++i) {
                const int x = int(i % size_t(W)), y = int(i / size_t(W));
                uint64_t stream = streamSeed(settings.seed, i);
                Sums& acc = sums[i];
                for (int k = done; k < total; ++k) {
                    glm::vec2 jitter = pixelArea ? tracer.sample(stream, 0, uint32_t(k)) : glm::vec2(0.5f);
                    PathResult p = tracer.trace(cameraRay(view, float(x) + jitter.x, float(y) + jitter.y), stream,
                                                uint32_t(k), cones.rotationOf(i));
                    localRays += p.rays;
                    ++acc.samples;
                    if (!p.hit) continue;
                    ++acc.hits;
                    glm::dvec3 ind(p.indirect);
                    acc.emission += glm::dvec3(p.emission);
                    acc.direct += glm::dvec3(p.direct);
                    acc.indirect += ind;
                    acc.indirectSq += ind * ind;
                    acc.replicateIndirect[k % K] += ind;
                    double m = (ind.x + ind.y + ind.z) / 3.0;
                    acc.indirectMeanSq += m * m;
                }
            }
            rays.fetch_add(localRays);
            progress.advance(uint64_t(r.size()) * uint64_t(total - done));
        });
        done = total;

        // Image-mean standard error of the channel-mean indirect over covered pixels.
        double sumVar = 0.0;
        size_t covered = 0;
        for (const Sums& acc : sums) {
            if (!acc.hits) continue;  // sky samples contribute 0 to indirect
            double se = indirectStderr(acc).w;
            sumVar += se * se;
            ++covered;
        }
        out.meanStderr = covered ? std::sqrt(sumVar) / double(covered) : 0.0;
        if (settings.targetStderr > 0.f && done >= settings.minSpp && out.meanStderr < settings.targetStderr) break;
    }

    out.emission = Image(W, H, 3);
    out.direct = Image(W, H, 3);
    out.indirect = Image(W, H, 3);
    out.beauty = Image(W, H, 3);
    out.indirectStderr = Image(W, H, 3);
    out.coverage = Image(W, H, 1);
    for (size_t i = 0; i < n; ++i) {
        const Sums& acc = sums[i];
        const int x = int(i % size_t(W)), y = int(i / size_t(W));
        double ns = std::max(1u, acc.samples);
        double skyFraction = 1.0 - acc.hits / ns;
        out.coverage.at(x, y) = float(acc.hits / ns);
        glm::dvec4 se = indirectStderr(acc);
        for (int c = 0; c < 3; ++c) {
            double le = acc.emission[c] / ns, di = acc.direct[c] / ns, in = acc.indirect[c] / ns;
            out.emission.at(x, y, c) = float(le);
            out.direct.at(x, y, c) = float(di);
            out.indirect.at(x, y, c) = float(in);
            out.beauty.at(x, y, c) = float(le + di + in + skyFraction * settings.sky);
            out.indirectStderr.at(x, y, c) = float(se[c]);
        }
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.sppUsed = done;
    out.raysTraced = rays.load();
    out.raysPerSecond = out.seconds > 0 ? double(out.raysTraced) / out.seconds : 0.0;
    return out;
}

ReferenceGI referenceGI(const Scene& scene, const View& view, const ReferenceSettings& settings, bool pixelArea,
                        const ConeModelSampler& cones) {
    EmbreeScene embree(scene);
    return referenceGI(embree, view, settings, pixelArea, cones);
}

}  // namespace vct
