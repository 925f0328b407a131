#include "cone/cone_settings.h"

#include "cone/cone_set.h"
#include "cone/cone_shared.h"
#include "voxelize/voxel_settings.h"

#include <cmath>
#include <stdexcept>

namespace vct {

namespace {
void require(bool ok, const std::string& what) {
    if (!ok) throw InternalError("ConeSettings", what);
}

// vct.preset=converge's cone settings, the march of docs/convergence.md's tables whose voxel
// error falls with the voxels: each cone marched as auto lanes of base 16 ((res / 16)^2 lanes,
// their footprint a fixed number of voxels), the directional levels sharpened along their axis
// (no trilinear leak through a one-voxel sheet), the lanes aimed at their rays' points at R, and
// texels of a quarter of the footprint (the tent no wider than the lane).
constexpr int kConvergeLanesBase = 16;
constexpr float kConvergeSharpen = 4.f;
constexpr float kConvergeLevelBias = -2.f;
}  // namespace

float defaultConeAperture(int coneCount) {
    if (coneCount == 6) return gpu::CONE_DEFAULT_APERTURE_6;
    if (coneCount == 16) return gpu::CONE_DEFAULT_APERTURE_16;
    if (coneCount == 32) return gpu::CONE_DEFAULT_APERTURE_32;
    if (coneCount == 64) return gpu::CONE_DEFAULT_APERTURE_64;
    throw InternalError("defaultConeAperture", "vct.cones = " + std::to_string(coneCount) + ": expected 6, 16, 32 or 64");
}

void ConeSettings::validate() const {
    require(coneCount == 6 || coneCount == 16 || coneCount == 32 || coneCount == 64,
            "coneCount " + std::to_string(coneCount) + " is not 6, 16, 32 or 64");
    require(std::isfinite(apertureDeg) && apertureDeg > 1.f && apertureDeg < 179.f,
            "apertureDeg " + std::to_string(apertureDeg) + " outside (1, 179)");
    require(std::isfinite(stepFactor) && stepFactor >= 0.05f && stepFactor <= 2.f,
            "stepFactor " + std::to_string(stepFactor) + " outside [0.05, 2]");
    require(std::isfinite(offsetVoxels) && offsetVoxels >= 0.f && offsetVoxels <= 8.f,
            "offsetVoxels " + std::to_string(offsetVoxels) + " outside [0, 8]");
    require(std::isfinite(maxAlpha) && maxAlpha >= 0.5f && maxAlpha <= 1.f,
            "maxAlpha " + std::to_string(maxAlpha) + " outside [0.5, 1]");
    require(traceScale >= 1 && traceScale <= gpu::CONE_MAX_TRACE_SCALE,
            "traceScale " + std::to_string(traceScale) + " outside [1, " + std::to_string(gpu::CONE_MAX_TRACE_SCALE) +
                "]");
    require(lanes >= 0 && lanes * coneCount <= gpu::CONE_MAX_CONES,
            "lanes " + std::to_string(lanes) + " x " + std::to_string(coneCount) + " cones outside [0, " +
                std::to_string(gpu::CONE_MAX_CONES) + "]");
    require(lanesBase >= gpu::CONE_LANES_BASE_MIN && lanesBase <= gpu::CONE_LANES_BASE_MAX,
            "lanesBase " + std::to_string(lanesBase) + " outside [" + std::to_string(gpu::CONE_LANES_BASE_MIN) + ", " +
                std::to_string(gpu::CONE_LANES_BASE_MAX) + "]");
    require(std::isfinite(sharpen) && sharpen >= 1.f && sharpen <= gpu::CONE_SHARPEN_MAX,
            "sharpen " + std::to_string(sharpen) + " outside [1, " + std::to_string(gpu::CONE_SHARPEN_MAX) + "]");
    require(std::isfinite(levelBias) && levelBias >= gpu::CONE_LEVEL_BIAS_MIN && levelBias <= gpu::CONE_LEVEL_BIAS_MAX,
            "levelBias " + std::to_string(levelBias) + " outside [" + std::to_string(gpu::CONE_LEVEL_BIAS_MIN) + ", " +
                std::to_string(gpu::CONE_LEVEL_BIAS_MAX) + "]");
    require(dispatchCones >= 0 && dispatchCones <= gpu::CONE_MAX_CONES,
            "dispatchCones " + std::to_string(dispatchCones) + " outside [0, " + std::to_string(gpu::CONE_MAX_CONES) +
                "]");
}

ConeLanes coneMarchLanes(const ConeSettings& s, int maxResolution) {
    return coneLanes(diffuseConeSet(s.coneCount), s.apertureDeg,
                     resolveConeLanes(s.lanes, s.coneCount, maxResolution, s.lanesBase));
}

const SettingsTable<ConeSettings>& coneSettings() {
    static const auto table =
        SettingsTable<ConeSettings>()
            .derive([](ConeSettings& s, const ParamMap& p) {
                if (readVctPreset(p) != VctPreset::Converge) return;
                s.lanes = 0;
                s.sharpen = kConvergeSharpen;
                s.aim = true;
                s.levelBias = kConvergeLevelBias;
            })
            .choice("vct.cones", &ConeSettings::coneCount, {{"6", 6}, {"16", 16}, {"32", 32}, {"64", 64}},
                    "diffuse cone set: 6 (6 x 60 deg, Villegas), or 16, 32, 64 cones of a cosine-stratified spiral "
                    "(50, 35, 25 deg)")
            .real("vct.aperture", &ConeSettings::apertureDeg,
                  [](const ConeSettings& s) { return defaultConeAperture(s.coneCount); },
                  "60 (6 cones), 50 (16), 35 (32), 25 (64)", 1.f,
                  179.f, "full cone aperture in degrees, open range (1, 179)")
            .check([](const ConeSettings& s) {
                if (!(s.apertureDeg > 1.f && s.apertureDeg < 179.f))
                    throw UsageError("--param vct.aperture=" + std::to_string(s.apertureDeg) +
                                     ": out of range (1, 179)");
            })
            .real("vct.step", &ConeSettings::stepFactor, 0.05f, 2.f, "step factor beta: step = beta * cone diameter")
            .real("vct.offset", &ConeSettings::offsetVoxels, 0.f, 8.f,
                  "cone start offset along the geometric normal, in voxels")
            .real("vct.max-alpha", &ConeSettings::maxAlpha, 0.5f, 1.f,
                  "accumulated opacity at which a cone stops and counts as closed")
            .flag("vct.aniso", &ConeSettings::anisotropic,
                  "sample the six directional mips (weights d^2) when the grid has them")
            .choice("vct.ao-mapping", &ConeSettings::aoMapping,
                    {{"linear", ConeAoMapping::Linear}, {"falloff", ConeAoMapping::Falloff}},
                    "linear: A = 1 - sum w_c alpha_c (estimates A_R); falloff: Crassin's 1/(1 + 4t/R) weighting "
                    "(not an estimator of A_R)")
            .flag("vct.plane-limit", &ConeSettings::planeLimit,
                  "limit each sample's footprint to its height above the tangent plane / 1.5 so a surface's own "
                  "voxels never occlude it")
            .integer("vct.lanes", &ConeSettings::lanes, 0, gpu::CONE_MAX_CONES,
                     "lanes per cone: each cone marched as this many narrower cones spread over its cap (its weight "
                     "and solid angle shared); 0 = auto, (voxel res / vct.lanes-base)^2, so a lane's footprint stays "
                     "the same number of voxels as the grid refines and the march converges to the cone's exact "
                     "visibility (cost grows with the lanes)")
            .derive([](ConeSettings& s, const ParamMap& p) {
                // The preset's base is auto's: lanes given on their own keep the default base.
                if (readVctPreset(p) == VctPreset::Converge && s.lanes == 0) s.lanesBase = kConvergeLanesBase;
            })
            .integer("vct.lanes-base", &ConeSettings::lanesBase, gpu::CONE_LANES_BASE_MIN, gpu::CONE_LANES_BASE_MAX,
                     "with vct.lanes=0: the resolution at which a cone is marched whole; auto gives (voxel res / "
                     "this)^2 lanes per cone. 32 keeps a 6-cone lane's footprint at R about 4.6 voxels; 16 marches "
                     "four times the lanes, their footprint half the voxels: on the closed-form families (6 cones on "
                     "a cube, vct.sharpen=4, vct.aim=1) the mean voxel error at 256^3 0.018 -> 0.016 and the small "
                     "closed room's leak 0.046 -> 0.016, at about 4.8 times the cone pass's samples (128^3, sparse)")
            .flag("vct.jitter", &ConeSettings::jitter,
                  "turn the cone set about the normal by an angle per pixel drawn from the seed: the fixed set's "
                  "streaks become noise (a new pattern per seed, so per frame with per-frame seeds); 0 keeps one "
                  "set for every pixel (dense grid and clipmap; not the sparse backend)")
            .choice("vct.opacity", &ConeSettings::opacity, {{"alpha", ConeOpacity::Alpha}, {"depth", ConeOpacity::Depth}},
                    "what the directional levels hold and filter: alpha (opacity, Crassin 2011), or depth (optical "
                    "depth: a march through a one-voxel wall passes the wall's own transmittance, where alpha's "
                    "trilinear tent passes ~13% of the light at any resolution); needs vct.aniso=1, dense grid or "
                    "sparse backend")
            .real("vct.sharpen", &ConeSettings::sharpen, 1.f, gpu::CONE_SHARPEN_MAX,
                  "filter of each directional level along the axis it is crossed along: linear weight f becomes "
                  "clamp((f - 1/2) s + 1/2, 0, 1), the axes across keep theirs; the isotropic base level is "
                  "fetched once per axis, each sharpened along it, blended as the directional axes. 1 = trilinear "
                  "(Crassin 2011), whose "
                  "tent passes exp(-2) = 13% of a cone crossing a one-voxel sheet at every resolution, so narrow "
                  "cones (vct.lanes=0, vct.grid=cube) stop converging past 256^3; 4 removes that leak and they "
                  "converge to 512^3, while the default 6 wide cones, whose footprint error the leak offsets, turn "
                  "darker. Needs vct.aniso=1 (dense grid or sparse backend); costs one fetch per axis and level a "
                  "sample blends (up to 6, against 1 on an AO grid or 3 on a lit one; 3 on the base level against 1)")
            .flag("vct.aim", &ConeSettings::aim,
                  "march each cone from its start (vct.offset voxels up the geometric normal) towards the point "
                  "its ray from the surface reaches at the maximum distance (R for AO), not parallel to that ray, "
                  "and as far as that point (|R d - offset n|, not R past its start): "
                  "the offset then displaces a cone by offset (1 - t / R) instead of offset all the way, so an "
                  "occluder near R is seen where it is (under a sheet, the cones whose rays end just below it "
                  "no longer end inside it). A direction that would aim below the tangent plane stays level. "
                  "Measured on the closed-form families with 6 cones in auto lanes on a cube (vct.sharpen=4): "
                  "mean voxel error at 256^3 0.025 -> 0.018 (measured before the march ended at that point). 0 = "
                  "parallel (Crassin 2011). All backends")
            .real("vct.level-bias", &ConeSettings::levelBias, gpu::CONE_LEVEL_BIAS_MIN, gpu::CONE_LEVEL_BIAS_MAX,
                  "the level a footprint of diameter D samples is log2(D) + b (texels of D 2^b voxels, at least one). "
                  "A trilinear sample's tent spans two texels, twice the footprint at b = 0, so a lane sees what "
                  "lies up to a footprint beside its cap (a wall beside a point, past an occluder's edge); -1 makes "
                  "the tent the footprint's width, at up to twice the samples (a step is beta texels). Measured on the "
                  "closed-form families with 6 cones in auto lanes on a cube, sharpened and aimed: mean voxel error "
                  "at 256^3 0.0178 -> 0.0166 (base 32) and 0.0157 -> 0.0135 (vct.lanes-base=16), the voxel error's rule "
                  "in 7 and 8 of 16 open cases against 5 and 7, at +21% samples (base 32, 128^3). The default wide "
                  "cones do not gain (0.0465 -> 0.045 at 256^3). 0 = Crassin 2011. All backends")
            .flag("vct.end-taper", &ConeSettings::endTaper,
                  "near the maximum distance (R for AO) sample whole levels whose texels reach no further than R: "
                  "a trilinear sample sees a texel past its centre, so the last samples of a footprint-sized "
                  "texel hold occluders up to a footprint beyond R. Tapered, the reach past R is a voxel or two "
                  "and the march takes a few more, finer steps at its end (+8% samples with 6 cones in auto lanes at "
                  "128^3). Measured on the closed-form families (6 cones in auto lanes on a cube, sharpened, aimed): "
                  "a wall's points 0.5 R..0.85 R from it 3x closer to the cone model, but the mean voxel error "
                  "unchanged, the end's fine texels sampling each lane's cap on its axis alone. 0 = the footprint's "
                  "level up to R (Crassin 2011). All backends")
            .choice("vct.below-plane", &ConeSettings::belowPlane,
                    {{"open", ConeBelowPlane::Open}, {"mirror", ConeBelowPlane::Mirror}},
                    "what the part of a cone's cap below the surface's geometric plane stands for, in the march's "
                    "lanes and in the cone model: open (the sky in GI; a cone never sees the surface it starts "
                    "from), or mirror (those directions reflected above the plane and marched). The Vogel sets' "
                    "outer caps reach below the plane (2.2% of the 16-cone set's weight, 1.1% of the 32's), and "
                    "counted open that weight reads as light in a room closed above the plane: 0.022 with 16 cones, "
                    "an error of the set that finer voxels do not remove. Mirrored, the set's weight stays on the "
                    "hemisphere. The 6-cone set's caps touch the plane, so with the shading normal on the geometric "
                    "one it is the same either way; a cone marched whole (vct.lanes=1) is marched the same either "
                    "way, only its cone model differs. All backends")
            .integer("vct.trace-scale", &ConeSettings::traceScale, 1, gpu::CONE_MAX_TRACE_SCALE,
                     "trace the cones of one pixel per s x s block and resolve the others from the nearest blocks "
                     "that share their surface (normal and tangent plane; a pixel sharing none traces its own): "
                     "the cone pass costs about 1 / s^2 (dense grid and clipmap; not the sparse backend)")
            .integer("vct.dispatch-cones", &ConeSettings::dispatchCones, 0, gpu::CONE_MAX_CONES,
                     "at most this many cones per GPU dispatch; 0 = as many as fit the loop budget a driver allows "
                     "one invocation (llvmpipe ends an invocation's loops after 65535 iterations). The gathers carry "
                     "their sums across dispatches, so the image is the same for any value; a smaller one only "
                     "shortens each dispatch (dense grid, clipmap and bounces)")
            .check([](const ConeSettings& s) {
                if (s.opacity == ConeOpacity::Depth && !s.anisotropic)
                    throw UsageError("--param vct.opacity=depth: optical depth is held by the directional levels; it "
                                     "needs vct.aniso=1");
            })
            .derive([](const ConeSettings& s, const ParamMap& p) {
                if (readVctPreset(p) == VctPreset::Converge && s.sharpen > 1.f && !s.anisotropic &&
                    !p.has("vct.sharpen"))
                    throw UsageError("--param vct.preset=converge: it sharpens the directional levels "
                                     "(vct.sharpen=4), and vct.aniso=0 has none; add --param vct.sharpen=1");
            })
            .check([](const ConeSettings& s) {
                if (s.sharpen > 1.f && !s.anisotropic)
                    throw UsageError("--param vct.sharpen=" + std::to_string(s.sharpen) +
                                     ": it filters the directional levels; it needs vct.aniso=1");
            })
            .check([](const ConeSettings& s) {
                if (s.lanesBase != gpu::CONE_LANES_BASE_RES && s.lanes != 0)
                    throw UsageError("--param vct.lanes-base=" + std::to_string(s.lanesBase) +
                                     ": it sets how many lanes auto marches; it needs vct.lanes=0");
            })
            .check([](const ConeSettings& s) {
                if (s.lanes * s.coneCount > gpu::CONE_MAX_CONES)
                    throw UsageError("--param vct.lanes=" + std::to_string(s.lanes) + ": " + std::to_string(s.lanes) +
                                     " x " + std::to_string(s.coneCount) + " cones exceed " +
                                     std::to_string(gpu::CONE_MAX_CONES));
            });
    return table;
}

float coneTanHalfAperture(float apertureDeg) { return std::tan(0.5f * apertureDeg * float(M_PI) / 180.f); }

float coneFootprintTangent(const ConeSettings& s, float apertureDeg) {
    return coneTanHalfAperture(apertureDeg) * std::exp2(s.levelBias);
}

float laneCapTangent(int lanesPerCone, float apertureDeg) {
    return lanesPerCone > 1 ? coneTanHalfAperture(apertureDeg) : 0.f;
}

ConeSettings readConeSettings(const ParamMap& params) {
    ConeSettings s = coneSettings().read(params);
    s.validate();
    return s;
}

std::string toString(ConeAoMapping m) { return m == ConeAoMapping::Falloff ? "falloff" : "linear"; }

}  // namespace vct
