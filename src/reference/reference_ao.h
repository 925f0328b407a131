// Ray-traced ground truth for ambient occlusion, the definition every AO method is scored against:
//
//   A_R(p) = (1/pi) * integral_hemisphere V_R(p, w) max(0, n.w) dw
//
// estimated with cosine-weighted directions about the shading normal n, so the estimate is
// the fraction of unoccluded rays. V_R is binary visibility within distance R (ray tfar = R,
// back faces occlude); directions below the geometric normal count as occluded.
//
// Samples: Owen-scrambled, index-shuffled Sobol (sampler.h), one stream per point/pixel
// hashed from (seed, index): deterministic for a seed and independent of the thread count.
// Progressive: passes to 8, 16, 32, ... spp (then `spp`), stopping early once the standard
// error of the image mean drops below `targetStderr`.
//
// Standard errors: by default from 4 independently scrambled replicates of the samples
// (randomized QMC, sampler.h): per point sqrt(sum (m_r - A)^2 / (K (K - 1))) over the
// replicate means m_r, an unbiased variance estimate (K - 1 degrees of freedom per point, so
// noisy for one point, accurate summed over an image). With replicates = 1 (or below 8 spp):
// the i.i.d. Bernoulli formula, an over-estimate for a single scrambled Sobol stream.
// tests/cpu/reference_ao_test.cpp checks both against the measured spread.
#pragma once

#include "image/image.h"
#include "reference/embree_scene.h"
#include "core/settings.h"
#include "core/view.h"
#include "reference/cone_model.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vct {


struct SurfacePoint {
    glm::vec3 position{0.f};     // world space
    glm::vec3 normal{0.f, 0.f, 1.f};      // shading normal, unit
    glm::vec3 geomNormal{0.f, 0.f, 1.f};  // geometric normal, unit; flipped to the shading normal's side
    bool valid = false;                   // false = sky: A = 1, standard error 0
};

struct ReferenceSettings {
    float radius = 1.f;        // AO radius R, world units, (0, inf)
    int spp = 64;              // samples per point / pixel (budget, rounded up to a multiple of replicates), [1, 1<<20]
    uint64_t seed = 0;         // sample scramble seed
    float targetStderr = 0.f;  // stop early once the image-mean standard error < this; 0 = off
    int replicates = 4;        // independent scrambles behind the error bar, [1, 8]; 1 = one stream:
                               // less noise, error bar over-stated (see sampler.h)
    int minSpp = 16;           // no early stop before this many spp, [1, spp]
    bool progress = true;      // progress bar on stderr (only when it is a terminal)
    int bounces = 4;           // GI: max diffuse reflections per path (1 = direct light only), [1, 1024]
    int rouletteBounce = 3;    // GI: Russian roulette (unbiased) from this bounce on, [1, inf)
    float sky = 1.f;           // GI: uniform sky radiance, [0, inf)
    RayMode rayMode = RayMode::Stream;  // how occlusion rays reach Embree (bench_reference)
    // Render modes: false = evaluate at the G-buffer's pixel centres, true = average over the
    // pixel with jittered primary rays (box filter, as Cycles).
    bool pixelArea = false;
    // AO of the cone model instead of the hemisphere (reference/cone_model.h): the cone set of
    // the request's vct.cones and vct.aperture, what voxel cone tracing converges to.
    bool coneModel = false;

    void validate() const;  // throws InternalError naming the bad field
};

// The reference.* keys (spp, seed, target-stderr, min-spp, replicates, bounces,
// roulette-bounce, ray-mode, pixel). The AO radius and the sky radiance are shared by every
// method: the caller sets them; spp and seed default to the request's.
const SettingsTable<ReferenceSettings>& referenceSettings();
ReferenceSettings referenceSettingsFromParams(const ParamMap& params, ReferenceSettings base = {});

struct ReferenceAO {
    int width = 0, height = 0;           // image modes: pixel (x, y) is element y * width + x, top row first
    std::vector<float> ao;               // per point / pixel, in [0, 1]
    std::vector<float> standardError;    // per point / pixel
    double meanStderr = 0.0;  // standard error of the mean A over valid points (pixels with any hit)
    int sppUsed = 0;
    uint64_t raysTraced = 0;  // occlusion rays given to Embree (below-horizon samples are not traced)
    uint64_t primaryRays = 0; // pixel-area mode only
    double seconds = 0.0;     // wall clock of the sampling loop (Embree BVH build excluded)
    double raysPerSecond = 0.0;  // (raysTraced + primaryRays) / seconds

    Image aoImage() const;      // 1 channel, width x height (image modes)
    Image stderrImage() const;
};

// AO at given points (e.g. the G-buffer's pixel centres); with `cones`, the cone model of
// that cone set (directions from it instead of the cosine hemisphere).
ReferenceAO referenceAO(const EmbreeScene& scene, const std::vector<SurfacePoint>& points,
                        const ReferenceSettings& settings, const ConeModelSampler& cones = {});
ReferenceAO referenceAO(const Scene& scene, const std::vector<SurfacePoint>& points,
                        const ReferenceSettings& settings, const ConeModelSampler& cones = {});

// Pixel-area AO: jittered primary rays over each pixel, box filter (what Cycles' AO pass
// computes); samples that miss every surface count A = 1 (sky).
ReferenceAO referenceAOPixelArea(const EmbreeScene& scene, const View& view, const ReferenceSettings& settings);
ReferenceAO referenceAOPixelArea(const Scene& scene, const View& view, const ReferenceSettings& settings);

// The surfaces seen through the pixel centres, top row first (element y * width + x);
// sky pixels are invalid. Normals face the camera.
std::vector<SurfacePoint> surfacePointsAtPixelCentres(const EmbreeScene& scene, const View& view);

}  // namespace vct
