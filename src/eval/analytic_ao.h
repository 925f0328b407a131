// Ambient occlusion of analytic occluders (rectangles, discs, spheres) by deterministic
// quadrature with exact ray intersections: a path independent of the renderer, its voxels
// and its Monte Carlo reference, with no noise, for scoring estimators on closed-form cases.
//
// Two integrals at a point p with unit normal n and radius R (V_R: no occluder within R):
// - the exact AO, A_R = (1/pi) integral_hemisphere V_R(w) (n.w) dw;
// - the cone model of a cone set: A_cones = sum_c w_c V_c, where V_c is the visible fraction
//   of cone c's solid angle (directions uniform in the cone, those below the tangent plane
//   open; a cone whose axis is below it counts as closed), as reference/cone_model.h samples
//   it. It is what cone tracing
//   approximates with exact visibility: voxel cone tracing converges to it, not to A_R, and
//   A_cones - A_R is the cone set's own error.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace vct {

struct AnalyticRect {
    glm::vec3 center{0.f};
    glm::vec3 u{1.f, 0.f, 0.f}, v{0.f, 0.f, 1.f};  // half-extents, orthogonal
};

struct AnalyticDisc {
    glm::vec3 center{0.f};
    glm::vec3 normal{0.f, 1.f, 0.f};
    float radius = 1.f;
};

struct AnalyticSphere {
    glm::vec3 center{0.f};
    float radius = 1.f;
};

struct AnalyticOccluders {
    std::vector<AnalyticRect> rects;
    std::vector<AnalyticDisc> discs;
    std::vector<AnalyticSphere> spheres;
    // True if the ray origin + t dir (unit dir) meets an occluder for t in (0, tMax].
    bool occludes(const glm::vec3& origin, const glm::vec3& dir, float tMax) const;
    // The distance t in (0, tMax] of the nearest occluder along the ray, or infinity.
    float firstHit(const glm::vec3& origin, const glm::vec3& dir, float tMax) const;
};

// The quadrature's resolution: samples per axis of the unit square mapped to the hemisphere
// or a cone (midpoint rule). Its error on an occluder's silhouette is about 1/n.
constexpr int kAnalyticHemisphereSamples = 1024;
constexpr int kAnalyticConeSamples = 192;

double analyticAo(const AnalyticOccluders& occluders, const glm::vec3& p, const glm::vec3& n, float radius,
                  int samplesPerAxis = kAnalyticHemisphereSamples);

// `cones`: xyz = direction in the tangent frame of n (frame_fromZ, z = n), w = weight, as
// cone/cone_set.h gives them; `apertureDeg` the full apex angle. A cap's directions below the
// plane of n count open, or with `mirrorBelowPlane` (vct.below-plane=mirror) are reflected
// above it (cone_mirrored) and tested there.
double analyticConeModelAo(const AnalyticOccluders& occluders, const glm::vec3& p, const glm::vec3& n, float radius,
                           const std::vector<glm::vec4>& cones, float apertureDeg,
                           int samplesPerAxis = kAnalyticConeSamples, bool mirrorBelowPlane = false);

}  // namespace vct
