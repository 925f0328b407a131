#include "eval/analytic_ao.h"

#include "common/tangent_frame.h"
#include "cone/cone_shared.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace vct {

namespace {

// Each hit test gives the distance t in (0, tMax] at which origin o + t d meets the occluder,
// or kNoHit.
constexpr float kNoHit = INFINITY;

float hitRect(const AnalyticRect& r, const glm::vec3& o, const glm::vec3& d, float tMax) {
    const glm::vec3 n = glm::cross(r.u, r.v);
    const float denom = glm::dot(d, n);
    if (denom == 0.f) return kNoHit;
    const float t = glm::dot(r.center - o, n) / denom;
    if (!(t > 0.f && t <= tMax)) return kNoHit;
    const glm::vec3 q = o + t * d - r.center;
    const float uu = glm::dot(r.u, r.u), vv = glm::dot(r.v, r.v);
    return std::abs(glm::dot(q, r.u)) <= uu && std::abs(glm::dot(q, r.v)) <= vv ? t : kNoHit;
}

float hitDisc(const AnalyticDisc& c, const glm::vec3& o, const glm::vec3& d, float tMax) {
    const float denom = glm::dot(d, c.normal);
    if (denom == 0.f) return kNoHit;
    const float t = glm::dot(c.center - o, c.normal) / denom;
    if (!(t > 0.f && t <= tMax)) return kNoHit;
    const glm::vec3 q = o + t * d - c.center;
    return glm::dot(q, q) <= c.radius * c.radius ? t : kNoHit;
}

float hitSphere(const AnalyticSphere& s, const glm::vec3& o, const glm::vec3& d, float tMax) {
    const glm::vec3 oc = o - s.center;
    const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.radius * s.radius;
    const float disc = b * b - c;
    if (disc < 0.f) return kNoHit;
    const float root = std::sqrt(disc);
    const float t0 = -b - root, t1 = -b + root;
    const float t = t0 > 0.f ? t0 : t1;
    return t > 0.f && t <= tMax ? t : kNoHit;
}

// Mean of f over the midpoint grid of the unit square, rows in parallel (deterministic:
// each row's sum is reduced in a fixed tree by TBB's simple partitioner over fixed ranges).
double squareMean(int n, const std::function<double(double, double)>& f) {
    const double sum = tbb::parallel_deterministic_reduce(
        tbb::blocked_range<int>(0, n, 16), 0.0,
        [&](const tbb::blocked_range<int>& rows, double acc) {
            for (int i = rows.begin(); i < rows.end(); ++i)
                for (int j = 0; j < n; ++j) acc += f((i + 0.5) / n, (j + 0.5) / n);
            return acc;
        },
        std::plus<double>());
    return sum / (double(n) * n);
}

}  // namespace

bool AnalyticOccluders::occludes(const glm::vec3& o, const glm::vec3& d, float tMax) const {
    for (const auto& r : rects)
        if (hitRect(r, o, d, tMax) <= tMax) return true;
    for (const auto& c : discs)
        if (hitDisc(c, o, d, tMax) <= tMax) return true;
    for (const auto& s : spheres)
        if (hitSphere(s, o, d, tMax) <= tMax) return true;
    return false;
}

float AnalyticOccluders::firstHit(const glm::vec3& o, const glm::vec3& d, float tMax) const {
    float t = kNoHit;
    for (const auto& r : rects) t = std::min(t, hitRect(r, o, d, tMax));
    for (const auto& c : discs) t = std::min(t, hitDisc(c, o, d, tMax));
    for (const auto& s : spheres) t = std::min(t, hitSphere(s, o, d, tMax));
    return t;
}

double analyticAo(const AnalyticOccluders& occ, const glm::vec3& p, const glm::vec3& n, float radius,
                  int samplesPerAxis) {
    const glm::mat3 frame = gpu::frame_fromZ(n);
    // Malley: a uniform point of the unit disc lifted to the hemisphere is cosine-distributed,
    // so the mean visibility is A_R.
    return squareMean(samplesPerAxis, [&](double u1, double u2) {
        const double r = std::sqrt(u1), phi = 2.0 * M_PI * u2;
        const glm::vec3 local(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(1.0 - u1)));
        return occ.occludes(p, frame * local, radius) ? 0.0 : 1.0;
    });
}

double analyticConeModelAo(const AnalyticOccluders& occ, const glm::vec3& p, const glm::vec3& n, float radius,
                           const std::vector<glm::vec4>& cones, float apertureDeg, int samplesPerAxis,
                           bool mirrorBelowPlane) {
    const glm::mat3 frame = gpu::frame_fromZ(n);
    const double cosHalf = std::cos(0.5 * apertureDeg * M_PI / 180.0);
    double ao = 0.0;
    for (const glm::vec4& cone : cones) {
        const glm::vec3 axis = glm::normalize(frame * glm::vec3(cone));
        if (glm::dot(axis, n) <= 0.f) continue;  // closed, as the cone passes close it
        const glm::mat3 coneFrame = gpu::frame_fromZ(axis);
        // Uniform in solid angle: cos(theta) uniform in [cos(half aperture), 1]. Directions
        // below the plane are open, as for the cone passes, which never see their own surface,
        // or reflected above it (vct.below-plane=mirror, as the passes march their lanes).
        double visible = 0.0;
        const int m = samplesPerAxis;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const double cosT = 1.0 - (1.0 - cosHalf) * (i + 0.5) / m;
                const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT)), phi = 2.0 * M_PI * (j + 0.5) / m;
                const glm::vec3 d = coneFrame * glm::vec3(float(sinT * std::cos(phi)), float(sinT * std::sin(phi)),
                                                          float(cosT));
                if (glm::dot(d, n) <= 0.f && !mirrorBelowPlane) visible += 1.0;
                else if (!occ.occludes(p, gpu::cone_mirrored(d, n), radius)) visible += 1.0;
            }
        ao += cone.w * visible / (double(m) * m);
    }
    return ao;
}

}  // namespace vct
