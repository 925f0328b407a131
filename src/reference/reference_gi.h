// Ray-traced ground truth for diffuse global illumination (the rendering equation, Kajiya 1986):
//
//   Lo = Le + (rho / pi) * integral Li(w) max(0, n.w) dw
//
// A unidirectional path tracer over Lambertian surfaces (albedo = baseColorFactor x sRGB-
// decoded base colour texture), KHR_lights_punctual lights, emissive triangles and a uniform
// sky of radiance `sky`:
// - punctual lights by next-event estimation with shadow rays, all lights at every vertex:
//   directional irradiance = color (lux), point/spot = color (candela) / d^2, spots with the
//   glTF spec's smooth falloff t^2, t = saturate((cos - cos_outer) / (cos_inner - cos_outer));
// - emissive triangles (Lambertian emitters, from their front face only unless the material
//   is doubleSided: glTF culls a single-sided back face) sampled by area x max(emissiveFactor)
//   and combined with BSDF-sampled emitter hits by MIS (power heuristic, Veach 1997);
// - escaped rays see the sky (not light-sampled: cosine sampling is already ideal for it);
// - `bounces` = B is the maximum number of diffuse reflections along a path (pbrt's
//   maxdepth), so a closed box of albedo rho and emission Le converges to
//   sum_{k=0..B} rho^k Le; Russian roulette from `rouletteBounce` on divides by the
//   survival probability, so it adds noise, not bias.
// - `cones` not empty: GI's cone model (cone_model.h), what voxel cone tracing converges to
//   as its voxels refine: every reflection gathers over the cone set's caps (weights w_c,
//   directions uniform in each cap) instead of the cosine lobe, emitter sampling weighted by
//   the same lobe; an open direction below the surface's plane sees the sky, a closed cone
//   nothing. Punctual lights keep their shadow rays, as the voxels' injection does.
// Outputs, RGB, top row first:
//   emission  Le of the first surface seen;
//   direct    light reaching the eye after exactly one reflection from punctual lights;
//   indirect  Lo - Le - direct: light from emissive surfaces (after one
//             reflection or more), the sky (seen after >= 1 reflection) and every longer
//             path. The renderer's direct pass sees punctual lights only, so emitters are
//             the GI methods' job, and their `indirect` is compared with this one;
//   beauty    Le + direct + indirect, and the sky radiance where the camera ray escapes.
#pragma once

#include "image/image.h"
#include "reference/cone_model.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "core/view.h"
#include "scene/scene.h"

#include <cstdint>

namespace vct {

struct ReferenceGI {
    int width = 0, height = 0;
    Image emission, direct, indirect, beauty;  // RGB, top row first
    Image indirectStderr;  // RGB per-pixel standard error of `indirect` (replicates, see reference_ao.h)
    Image coverage;        // 1 channel: fraction of primary samples that hit a surface (0 = sky pixel)
    double meanStderr = 0.0;  // standard error of the mean of (r+g+b)/3 of `indirect` over covered pixels
    int sppUsed = 0;
    uint64_t raysTraced = 0;  // primary + path + shadow rays
    double seconds = 0.0;
    double raysPerSecond = 0.0;
};

// `pixelArea` jitters primary rays over each pixel (box filter); otherwise they go through
// the pixel centres, like the G-buffer. `cones` (its rotations by pixel, top row first): the
// cone model.
ReferenceGI referenceGI(const EmbreeScene& scene, const View& view, const ReferenceSettings& settings,
                        bool pixelArea = false, const ConeModelSampler& cones = {});
ReferenceGI referenceGI(const Scene& scene, const View& view, const ReferenceSettings& settings,
                        bool pixelArea = false, const ConeModelSampler& cones = {});

// Spot light angular attenuation of the glTF KHR_lights_punctual spec (squared smoothstep-
// like ramp); `cosAngle` is between the spot direction and the direction light -> point.
float spotAttenuation(const Light& light, float cosAngle);

}  // namespace vct
