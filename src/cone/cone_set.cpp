#include "cone/cone_set.h"

#include "core/errors.h"

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

}  // namespace vct
