// Settings of voxel cone tracing, read from `--param vct.*`. Defaults and
// their reasons live in shaders/cone/cone_shared.h (CONE_DEFAULT_*).
//
// Keys, defaults, ranges and docs: coneSettings() (vct.cones, vct.aperture, vct.step,
// vct.offset, vct.max-alpha, vct.aniso, vct.ao-mapping, vct.plane-limit, vct.lanes, vct.jitter,
// vct.opacity, vct.trace-scale, vct.dispatch-cones, vct.below-plane and the march's others).
//
// AO mappings: `linear` A = 1 - sum_c w_c alpha_c, where alpha_c is cone c's opacity
// accumulated within R; with cosine-lobe weights w_c this estimates A_R, the cosine-weighted
// fraction of the hemisphere unoccluded within R (binary visibility, no falloff), so it is
// the one to score against the reference.
// `falloff` weights each sample's opacity by 1 / (1 + lambda t), lambda = 4 / R (Crassin
// 2011's smooth AO); it is brighter than A_R by design and not an estimator of it.
#pragma once

#include "cone/cone_shared.h"

#include "core/settings.h"

#include <cstdint>
#include <string>

namespace vct {

enum class ConeAoMapping { Linear, Falloff };
// What the directional levels hold and interpolate: opacity (Crassin 2011), or optical depth
// (shaders/voxelize/opacity_depth.h), whose trilinear filter along a ray passes exactly a
// texel's own transmittance (a one-texel wall crossed under opacity filtering passes ~13%).
enum class ConeOpacity { Alpha, Depth };
// What the part of a cone's cap below the geometric plane stands for (vct.below-plane): open, as
// the sky (a cone never sees the surface it starts from), or the same directions reflected
// above the plane (cone_mirrored), so that the set's weight stays on the hemisphere.
enum class ConeBelowPlane { Open, Mirror };

struct ConeSettings {
    int coneCount = gpu::CONE_DEFAULT_COUNT;
    float apertureDeg = gpu::CONE_DEFAULT_APERTURE_6;  // full apex angle, degrees
    float stepFactor = gpu::CONE_DEFAULT_STEP;         // beta: step / footprint diameter
    float offsetVoxels = gpu::CONE_DEFAULT_OFFSET;     // start offset along the geometric normal, voxels
    float maxAlpha = gpu::CONE_DEFAULT_MAX_ALPHA;      // early exit
    bool anisotropic = true;        // use grid.anisoRadiance when present
    ConeAoMapping aoMapping = ConeAoMapping::Linear;
    bool planeLimit = true;         // limit the footprint by the height above the tangent plane
    int lanes = 1;                  // lanes per cone (cone/cone_set.h); 0 = auto, (res / lanesBase)^2
    int lanesBase = gpu::CONE_LANES_BASE_RES;  // vct.lanes-base: auto's resolution of one lane per cone
    bool jitter = false;            // turn the set about the normal per pixel (cone_jitterAngle)
    ConeOpacity opacity = ConeOpacity::Alpha;  // vct.opacity: the directional levels' encoding
    int traceScale = 1;             // vct.trace-scale: cones traced for one pixel per s x s block, resolved
    int dispatchCones = 0;          // vct.dispatch-cones: at most this many cones per dispatch; 0 = the loop budget's
    float sharpen = gpu::CONE_DEFAULT_SHARPEN;  // vct.sharpen: directional levels' filter along their axis (cone_sharpenTexel)
    bool aim = false;               // vct.aim: march each cone towards its ray's point at the max distance
    bool endTaper = false;          // vct.end-taper: finer levels near the max distance (ConeMarch::endRatio)
    float levelBias = gpu::CONE_DEFAULT_LEVEL_BIAS;  // vct.level-bias: level log2(footprint) + b
    ConeBelowPlane belowPlane = ConeBelowPlane::Open;  // vct.below-plane: a cap's part below the plane
    uint32_t seed = 0;              // the render's seed, for the jitter: set by the caller, not a --param

    // Throws InternalError naming the field if a value is outside its range.
    void validate() const;
};

// The set's own aperture: 60 degrees for 6 cones, 50 for 16.
float defaultConeAperture(int coneCount);

const SettingsTable<ConeSettings>& coneSettings();

// The cones a march over a grid of `maxResolution` voxels (its longest axis) traces: the set
// of vct.cones split into vct.lanes lanes (cone/cone_set.h).
struct ConeLanes coneMarchLanes(const ConeSettings& s, int maxResolution);
ConeSettings readConeSettings(const ParamMap& params);  // coneSettings().read(params)
// ConeSettings::seed from a render's 64-bit seed (both halves folded in).
inline uint32_t coneJitterSeed(uint64_t seed) { return uint32_t(seed) ^ uint32_t(seed >> 32); }

// tan(aperture / 2) of a cone of full aperture `apertureDeg`, degrees: its footprint's radius at
// distance 1.
float coneTanHalfAperture(float apertureDeg);
// ConeMarch::tanHalfAperture of a march whose cones (or lanes) have the full aperture
// `apertureDeg` (ConeLanes::apertureDeg): coneTanHalfAperture 2^(vct.level-bias), so the
// footprint's level carries the bias (times exactly 1 at the default 0).
float coneFootprintTangent(const ConeSettings& s, float apertureDeg);
// ConeMarch::capTan of a march over sheets whose cones are split into `lanesPerCone` lanes of
// full aperture `apertureDeg` (ConeLanes): the lanes' tan(aperture / 2), or 0 for whole cones. The cap is a first-order correction for narrow lanes
// near R, where the march would read them as rays; a whole cone (60 degrees for 6) is no ray
// there, and its zone about R (cone_capZone) read at the base level would be most of its march.
float laneCapTangent(int lanesPerCone, float apertureDeg);

// True when the directional levels are to hold optical depth: vct.opacity=depth, which only
// the directional levels carry (vct.aniso=1). The one rule the mip builders of both backends,
// the voxel caches' keys and --explain read.
inline bool wantsDepthLevels(const ConeSettings& s) { return s.anisotropic && s.opacity == ConeOpacity::Depth; }
// True when the directional levels are to be read with vct.sharpen's filter (s > 1; the
// settings refuse s > 1 without them). The one rule both backends' samplers and --explain read.
inline bool sharpensLevels(const ConeSettings& s) { return s.anisotropic && s.sharpen > 1.f; }

std::string toString(ConeAoMapping m);

}  // namespace vct
