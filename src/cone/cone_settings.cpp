#include "cone/cone_settings.h"

#include "cone/cone_shared.h"

#include <cmath>
#include <stdexcept>

namespace vct {

namespace {
void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("ConeSettings: " + what);
}
}  // namespace

float defaultConeAperture(int coneCount) {
    if (coneCount == 6) return gpu::CONE_DEFAULT_APERTURE_6;
    if (coneCount == 16) return gpu::CONE_DEFAULT_APERTURE_16;
    throw std::invalid_argument("vct.cones = " + std::to_string(coneCount) + ": expected 6 or 16");
}

void ConeSettings::validate() const {
    require(coneCount == 6 || coneCount == 16, "coneCount " + std::to_string(coneCount) + " is not 6 or 16");
    require(std::isfinite(apertureDeg) && apertureDeg > 1.f && apertureDeg < 179.f,
            "apertureDeg " + std::to_string(apertureDeg) + " outside (1, 179)");
    require(std::isfinite(stepFactor) && stepFactor >= 0.05f && stepFactor <= 2.f,
            "stepFactor " + std::to_string(stepFactor) + " outside [0.05, 2]");
    require(std::isfinite(offsetVoxels) && offsetVoxels >= 0.f && offsetVoxels <= 8.f,
            "offsetVoxels " + std::to_string(offsetVoxels) + " outside [0, 8]");
    require(std::isfinite(maxAlpha) && maxAlpha >= 0.5f && maxAlpha <= 1.f,
            "maxAlpha " + std::to_string(maxAlpha) + " outside [0.5, 1]");
}

ConeSettings readConeSettings(const ParamMap& params) {
    ConeSettings s;
    std::string cones = params.getChoice("vct.cones", std::to_string(gpu::CONE_DEFAULT_COUNT), {"6", "16"},
                                         "diffuse cone set: 6 (6 x 60 deg, Villegas) or 16 (16 x 50 deg, "
                                         "cosine-stratified spiral)");
    s.coneCount = std::stoi(cones);
    s.apertureDeg = params.getFloat("vct.aperture", defaultConeAperture(s.coneCount), 1.f, 179.f,
                                    "full cone aperture in degrees, open range (1, 179); default 60 for "
                                    "6 cones, 50 for 16");
    if (!(s.apertureDeg > 1.f && s.apertureDeg < 179.f))
        throw std::invalid_argument("--param vct.aperture=" + std::to_string(s.apertureDeg) +
                                    ": out of range (1, 179)");
    s.stepFactor = params.getFloat("vct.step", gpu::CONE_DEFAULT_STEP, 0.05f, 2.f,
                                   "step factor beta: step = beta * cone diameter");
    s.offsetVoxels = params.getFloat("vct.offset", gpu::CONE_DEFAULT_OFFSET, 0.f, 8.f,
                                     "cone start offset along the geometric normal, in voxels");
    s.maxAlpha = params.getFloat("vct.max-alpha", gpu::CONE_DEFAULT_MAX_ALPHA, 0.5f, 1.f,
                                 "accumulated opacity at which a cone stops and counts as closed");
    s.anisotropic = params.getBool("vct.aniso", true,
                                   "sample the six directional mips (weights d^2) when the grid has them");
    s.aoMapping = params.getChoice("vct.ao-mapping", "linear", {"linear", "falloff"},
                                   "linear: A = 1 - sum w_c alpha_c (estimates A_R); falloff: Crassin's "
                                   "1/(1 + 4t/R) weighting (not an estimator of A_R)") == "falloff"
                      ? ConeAoMapping::Falloff
                      : ConeAoMapping::Linear;
    s.planeLimit = params.getBool("vct.plane-limit", true,
                                  "limit each sample's footprint to its height above the tangent plane "
                                  "/ 1.5 so a surface's own voxels never occlude it");
    s.validate();
    return s;
}

std::string toString(ConeAoMapping m) { return m == ConeAoMapping::Falloff ? "falloff" : "linear"; }

}  // namespace vct
