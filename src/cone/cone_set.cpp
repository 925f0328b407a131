#include "cone/cone_set.h"

#include "core/errors.h"
#include "cone/cone_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vct {

namespace {

std::vector<glm::vec4> villegasSix() {
    // Five cones evenly spaced in azimuth at polar angle 60 degrees.
    std::vector<glm::vec4> cones{{0.f, 0.f, 1.f, 0.25f}};
    const float sinT = std::sqrt(3.f) / 2.f, cosT = 0.5f;
    for (int i = 0; i < 5; ++i) {
        float phi = 2.f * float(M_PI) * float(i) / 5.f;
        cones.push_back({sinT * std::cos(phi), sinT * std::sin(phi), cosT, 0.15f});
    }
    return cones;
}

std::vector<glm::vec4> vogelDisc(int n) {
    // Radius sqrt((i + 0.5) / n) splits the disc into equal areas; the golden angle spreads
    // the azimuths. Lifting (x, y) to z = sqrt(1 - x^2 - y^2) maps area to cosine weight.
    const float golden = float(M_PI) * (3.f - std::sqrt(5.f));
    std::vector<glm::vec4> cones;
    for (int i = 0; i < n; ++i) {
        float r = std::sqrt((float(i) + 0.5f) / float(n));
        float phi = golden * float(i);
        cones.push_back({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.f, 1.f - r * r)),
                         1.f / float(n)});
    }
    return cones;
}

}  // namespace

std::vector<glm::vec4> diffuseConeSet(int coneCount) {
    if (coneCount == 6) return villegasSix();
    if (coneCount == 16 || coneCount == 32 || coneCount == 64) return vogelDisc(coneCount);
    throw InternalError("diffuseConeSet", std::to_string(coneCount) + " cones (expected 6, 16, 32 or 64)");
}

ConeLanes coneLanes(const std::vector<glm::vec4>& set, float apertureDeg, int lanes) {
    if (set.size() > size_t(gpu::CONE_MAX_SET_CONES))
        throw InternalError("coneLanes", std::to_string(set.size()) + " cones exceed " +
                                             std::to_string(gpu::CONE_MAX_SET_CONES));
    if (lanes < 1 || size_t(lanes) * set.size() > size_t(gpu::CONE_MAX_CONES))
        throw InternalError("coneLanes", std::to_string(lanes) + " lanes x " + std::to_string(set.size()) +
                                             " cones exceed " + std::to_string(gpu::CONE_MAX_CONES));
    ConeLanes out;
    out.lanesPerCone = lanes;
    out.axes = set;
    if (lanes == 1) {
        out.cones = set;
        out.apertureDeg = apertureDeg;
        return out;
    }
    const double half = 0.5 * double(apertureDeg) * M_PI / 180.0;
    const double capCos = 1.0 - std::cos(half);  // 1 - cos(alpha): the cap's solid angle / 2 pi
    // Equal solid angle per lane: 1 - cos(alpha_lane) = (1 - cos(alpha)) / lanes.
    out.apertureDeg = float(2.0 * std::acos(1.0 - capCos / double(lanes)) * 180.0 / M_PI);
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (const glm::vec4& c : set) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(c));
        // Any frame around the axis: the lanes' azimuths are a spiral, not tied to it.
        const glm::dvec3 helper = std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
        const glm::dvec3 t = glm::normalize(glm::cross(helper, axis));
        const glm::dvec3 b = glm::cross(axis, t);
        for (int i = 0; i < lanes; ++i) {
            // cos(theta) uniform in [cos(alpha), 1] is uniform in solid angle over the cap;
            // each lane sits at the centre of its share.
            const double cosT = 1.0 - capCos * (double(i) + 0.5) / double(lanes);
            const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
            const double phi = golden * double(i);
            const glm::dvec3 d = cosT * axis + sinT * (std::cos(phi) * t + std::sin(phi) * b);
            out.cones.push_back(glm::vec4(glm::vec3(glm::normalize(d)), c.w / float(lanes)));
        }
    }
    return out;
}

int resolveConeLanes(int lanes, int coneCount, int maxResolution, int baseResolution) {
    if (lanes > 0) return lanes;
    const double ratio = double(maxResolution) / double(std::max(1, baseResolution));
    const int maxLanes = std::max(1, gpu::CONE_MAX_CONES / std::max(1, coneCount));
    return std::clamp(int(std::lround(ratio * ratio)), 1, maxLanes);
}

}  // namespace vct
