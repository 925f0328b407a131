// The CPU cone tracer: the shaders' march itself (cone/cone_march_shared.h) and tangent frame
// (common/tangent_frame.h) over the sparse levels instead of 3D textures, with
// shaders/cone/cone_common.glsl's gather and surface test and cone_march.glsl's sampling of
// the directional levels when the voxels have them.
#include "vdb/sparse_cone.h"

#include "common/tangent_frame.h"
#include "cone/cone_march_shared.h"
#include "cone/cone_set.h"
#include "core/errors.h"
#include "util/progress.h"
#include "voxelize/opacity_depth.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace vct {

namespace {

using OpacityAcc = openvdb::tree::ValueAccessor<const openvdb::FloatTree, false>;  // unregistered: read-only trees
using RadianceAcc = openvdb::tree::ValueAccessor<const openvdb::Vec3STree, false>;
using ConstAcc3 = RadianceAcc;

struct MarchParams {
    gpu::ConeMarch march;
    float offset, maxLod;
    glm::vec3 res;
    std::vector<glm::vec3> levelScale;  // level texel coordinates per voxel unit: size_k / res
    std::vector<glm::vec4> cones;       // the set's lanes (coneMarchLanes)
    std::vector<glm::vec4> axes;        // the set's cones (ConeLanes::axes)
    int lanesPerCone = 1;
    float laneApertureDeg = 0.f;        // each lane's full aperture (ConeLanes::apertureDeg)
    float sharpen = 1.f;                // vct.sharpen when the levels are directional, else 1
    bool aim = false;                   // vct.aim (gpu::cone_aimedDirection)
    bool mirror = false;                // vct.below-plane=mirror (gpu::cone_mirrored)
};

// True where a pixel gather's base samples read the sheets (vct.voxel.edges=sheet over
// directional levels; AO and GI alike). The bounces keep the trilinear base, as the dense
// bounce pass has no sheet variant (cone_gpu.h's readsSheets).
bool readsSheets(const SparseVoxelScene& v) { return v.sheet && !v.directional[0].empty(); }

// Who marches through a LevelSampler: what it reads of the levels.
enum class Gatherer {
    PixelAO,  // a pixel's AO cones: opacity, and the sheets where readsSheets
    PixelGI,  // a pixel's GI cones: opacity, radiance and normals, and the sheets where readsSheets
    Bounce,   // a voxel's bounce gather: as PixelGI over the trilinear base, never the sheets
};

// One thread's view of the levels: the volume of gpu::cone_marchVolume.
struct LevelSampler {
    const MarchParams* mp;
    Gatherer gatherer;
    std::vector<std::unique_ptr<OpacityAcc>> opacity;
    std::vector<std::unique_ptr<RadianceAcc>> radiance;  // empty for AO
    std::vector<std::unique_ptr<RadianceAcc>> normal;    // GI only: normal levels (facing test)
    // The directional levels per direction (+X, -X, +Y, -Y, +Z, -Z); empty when isotropic.
    std::array<std::vector<std::unique_ptr<OpacityAcc>>, 6> dirOpacity;
    std::array<std::vector<std::unique_ptr<RadianceAcc>>, 6> dirRadiance;  // GI only
    // Texture fetches as the GPU's volume counts them (cone/cone_cost.h): one per textureLod
    // the shader would make, whatever levels the CPU blends for it.
    double fetches = 0.0;
    bool depth = false;  // the directional levels hold optical depth (opacity_depth.h)
    // Fetches of one directional sample: the dense AO grid's one texture of the three axes'
    // opacity (VoxelGrid::anisoOpacity), or a lit grid's three of its six RGBA textures.
    double directionalFetches = 3.0;
    // Level 0's sheets (SparseVoxelScene::sheet), read by a pixel gather's base samples (readsSheets).
    std::unique_ptr<RadianceAcc> sheets;
    std::unique_ptr<openvdb::tree::ValueAccessor<const openvdb::UInt32Tree>> sheetExtents;  // its extent bits

    LevelSampler(const SparseVoxelScene& v, const MarchParams& params, Gatherer who)
        : mp(&params), gatherer(who), depth(v.depthLevels), directionalFetches(v.injected() ? 3.0 : 1.0) {
        const bool gi = gatherer != Gatherer::PixelAO;
        for (const auto& g : v.opacityLevels) opacity.push_back(std::make_unique<OpacityAcc>(g->tree()));
        if (gi) {
            for (const auto& g : v.radianceLevels) radiance.push_back(std::make_unique<RadianceAcc>(g->tree()));
            for (const auto& g : v.normalLevels) normal.push_back(std::make_unique<RadianceAcc>(g->tree()));
        }
        if (gatherer != Gatherer::Bounce && readsSheets(v)) {
            sheets = std::make_unique<RadianceAcc>(v.sheet->tree());
            sheetExtents = std::make_unique<openvdb::tree::ValueAccessor<const openvdb::UInt32Tree>>(*v.sheetExtent);
        }
        for (size_t d = 0; d < 6; ++d)
            for (const auto& l : v.directional[d]) {
                dirOpacity[d].push_back(std::make_unique<OpacityAcc>(l.opacity->tree()));
                if (gi) dirRadiance[d].push_back(std::make_unique<RadianceAcc>(l.radiance->tree()));
            }
    }

    // Level texel coordinates of voxel-space p: GL texel centres (i + 0.5) / size_k, i.e.
    // index p * size_k / res - 0.5.
    openvdb::Vec3R levelCoord(const glm::vec3& p, int level) const {
        const glm::vec3 x = p * mp->levelScale[size_t(level)] - 0.5f;
        return openvdb::Vec3R(x.x, x.y, x.z);
    }

    // GL_LINEAR_MIPMAP_LINEAR across levels: atLevel(floor(lod)) blended with the next level.
    template <class AtLevel>
    auto acrossLevels(float lod, AtLevel atLevel) const {
        lod = std::clamp(lod, 0.f, mp->maxLod);
        const int l0 = int(std::floor(lod));
        const float f = lod - float(l0);
        const auto s0 = atLevel(l0);
        if (f <= 0.f || l0 + 1 > int(mp->maxLod)) return s0;
        return glm::mix(s0, atLevel(l0 + 1), f);
    }

    // Trilinear at one level.
    glm::vec4 sampleLevel(const glm::vec3& p, int level) { return sampleLevelAt(levelCoord(p, level), level); }

    // Trilinear at one level, at level texel coordinates xyz.
    glm::vec4 sampleLevelAt(const openvdb::Vec3R& xyz, int level) {
        const float a = openvdb::tools::BoxSampler::sample(*opacity[size_t(level)], xyz);
        if (radiance.empty()) return glm::vec4(0.f, 0.f, 0.f, a);
        const openvdb::Vec3s c = openvdb::tools::BoxSampler::sample(*radiance[size_t(level)], xyz);
        return glm::vec4(c[0], c[1], c[2], a);
    }

    // The levels up to the coarsest.
    float lod(float footprintLod, const glm::vec3&) const { return std::min(footprintLod, mp->maxLod); }

    // The levels' box [0, res].
    bool leaving(const glm::vec3& p, const glm::vec3& d, float texel) const {
        return gpu::cone_leaving(p, d, mp->res, 1.5f * texel);
    }

    // Level texel coordinates xyz moved along `axis` by vct.sharpen (gpu::cone_sharpenTexel, on
    // GL texel coordinates: index + 1/2); cone_sharpenAlong.
    openvdb::Vec3R sharpenAlong(openvdb::Vec3R xyz, size_t axis) const {
        xyz[axis] = double(gpu::cone_sharpenTexel(float(xyz[axis]) + 0.5f, mp->sharpen) - 0.5f);
        return xyz;
    }

    // Trilinear at pyramid level `level` (>= 1) of direction d's levels; with vct.sharpen,
    // sharpened along d's axis.
    glm::vec4 sampleDirectional(const glm::vec3& p, size_t d, int level) {
        openvdb::Vec3R xyz = levelCoord(p, level);
        if (mp->sharpen > 1.f) xyz = sharpenAlong(xyz, d / 2);
        const float a = openvdb::tools::BoxSampler::sample(*dirOpacity[d][size_t(level - 1)], xyz);
        if (dirRadiance[d].empty()) return glm::vec4(0.f, 0.f, 0.f, a);
        const openvdb::Vec3s c = openvdb::tools::BoxSampler::sample(*dirRadiance[d][size_t(level - 1)], xyz);
        return glm::vec4(c[0], c[1], c[2], a);
    }

    // cone_sampleBase: the base level at a sample of direction d. With vct.sharpen, one fetch per
    // axis sharpened along that axis, blended as the directional levels' axes are
    // (cone_sampleBaseSharpened); else one trilinear fetch.
    glm::vec4 sampleBase(const glm::vec3& p, const glm::vec3& d, float lod, float dt, const glm::vec2& cap) {
        if (sheets) return gpu::cone_sampleSheets(*this, p, d, lod, dt, cap);  // vct.voxel.edges=sheet
        if (!(mp->sharpen > 1.f)) return sampleLevel(p, 0);
        const openvdb::Vec3R xyz = levelCoord(p, 0);
        const glm::vec4 x = sampleLevelAt(sharpenAlong(xyz, 0), 0), y = sampleLevelAt(sharpenAlong(xyz, 1), 0),
                        z = sampleLevelAt(sharpenAlong(xyz, 2), 0);
        return gpu::cone_blendDirectional(gpu::cone_anisoWeights(d), x, y, z);
    }

    // gpu::cone_sampleSheets' texel of voxel v: (opacity, lo, hi, axis), axis -1 where v holds
    // no sheet (zero outside the grid, as the dense grid's CONE_SHEETS variant reads it).
    glm::vec4 sheet(const glm::ivec3& v) {
        const openvdb::Coord ijk(v.x, v.y, v.z);
        float opacity0 = 0.f;
        opacity[0]->probeValue(ijk, opacity0);
        openvdb::Vec3s span;
        if (!sheets->probeValue(ijk, span)) return glm::vec4(opacity0, 0.f, 0.f, -1.f);
        return glm::vec4(opacity0, span[0], span[1], span[2]);
    }
    // Its extent bits (vox_extentBits), none (the whole voxel) where unoccupied.
    uint32_t sheetExtent(const glm::ivec3& v) { return sheetExtents->getValue(openvdb::Coord(v.x, v.y, v.z)); }
    // The light leaving voxel v (GI): its base-level radiance over its opacity; none for AO. One
    // fetch (cone_volumeSheetLight), inside the grid.
    glm::vec3 sheetLight(const glm::ivec3& v) {
        if (radiance.empty()) return glm::vec3(0.f);
        if (glm::any(glm::lessThan(v, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(v, glm::ivec3(mp->res)))) return glm::vec3(0.f);
        fetches += 1.0;
        const openvdb::Coord ijk(v.x, v.y, v.z);
        const openvdb::Vec3s c = radiance[0]->getValue(ijk);
        return glm::vec3(c[0], c[1], c[2]) / std::max(opacity[0]->getValue(ijk), 1.0e-4f);
    }

    // The fetches of one directional sample at footprint 2^lod: the textures' own (one or
    // three, trilinear across levels), or, sharpened, one per axis at each of the levels it
    // blends (the CONE_SHARPEN variant fetches each axis at its own coordinate).
    double directionalSampleFetches(float lod) const {
        if (!(mp->sharpen > 1.f)) return directionalFetches;
        const float l = std::clamp(std::max(lod, 1.f), 0.f, mp->maxLod);
        const bool blends = l - std::floor(l) > 0.f && std::floor(l) + 1.f <= mp->maxLod;
        return blends ? 6.0 : 3.0;
    }

    // cone_sampleAniso: the directional levels at footprint 2^lod (lod >= 1) as seen by a cone
    // travelling along d, each axis's level chosen by the sign of d and blended as optical depth.
    glm::vec4 sampleAniso(const glm::vec3& p, const glm::vec3& d, float lod) {
        const size_t dx = d.x >= 0.f ? 0 : 1, dy = d.y >= 0.f ? 2 : 3, dz = d.z >= 0.f ? 4 : 5;
        auto along = [&](size_t dir) {
            // Optical-depth levels filter (across levels too) as depth and composite as opacity.
            const glm::vec4 s =
                acrossLevels(std::max(lod, 1.f), [&](int level) { return sampleDirectional(p, dir, level); });
            return depth ? gpu::vox_alphaFromDepth(s) : s;
        };
        return gpu::cone_blendDirectional(gpu::cone_anisoWeights(d), along(dx), along(dy), along(dz));
    }

    // textureLod: premultiplied radiance (GI) and opacity at footprint 2^lod. With directional
    // levels, cone_sampleGrid: below lod 1 the base level blended into the first directional
    // one, as trilinear filtering blends two mip levels.
    glm::vec4 sample(const glm::vec3& p, const glm::vec3& d, float lod, float dt, const glm::vec2& cap) {
        if (dirOpacity[0].empty()) {
            fetches += 1.0;
            return acrossLevels(lod, [&](int level) { return sampleLevel(p, level); });
        }
        const double baseFetches = sheets ? 16.0 : mp->sharpen > 1.f ? 3.0 : 1.0;  // GI's sheetLight counts its own
        fetches += directionalSampleFetches(lod) + (lod < 1.f ? baseFetches : 0.0);
        glm::vec4 directional = sampleAniso(p, d, lod);
        if (lod < 1.f) {
            if (depth)
                directional = gpu::vox_alphaFromDepth(glm::mix(gpu::vox_depthFromCoverage(sampleBase(p, d, lod, dt, cap)),
                                                              gpu::vox_depthFromAlpha(directional), std::max(lod, 0.f)));
            else
                directional = glm::mix(sampleBase(p, d, lod, dt, cap), directional, std::max(lod, 0.f));
        }
        return directional;
    }

    // GI: cone_facing, vox_facingWeight of the occupied voxels' mean normal at the sample's
    // level: the filtered normal over the filtered coverage (the isotropic opacity level, as
    // the GPU's normal mips carry it; with directional levels the sample's alpha is not the
    // coverage). AO: 1.
    float facing(const glm::vec3& p, const glm::vec3& d, float lod, const glm::vec4&) {
        if (radiance.empty()) return 1.f;
        fetches += 1.0;
        const glm::vec4 n = acrossLevels(lod, [&](int level) {
            const openvdb::Vec3R xyz = levelCoord(p, level);
            const openvdb::Vec3s v = openvdb::tools::BoxSampler::sample(*normal[size_t(level)], xyz);
            const float coverage = openvdb::tools::BoxSampler::sample(*opacity[size_t(level)], xyz);
            return glm::vec4(v[0], v[1], v[2], coverage);
        });
        return gpu::vox_facingWeight(glm::vec3(n) / std::max(n.w, 1e-4f), d);
    }
};


// cone_surface: false for sky or unusable normals.
bool surface(const SparsePoint& pt, glm::vec3& n, glm::vec3& ng) {
    if (!pt.valid || !finite3(pt.position)) return false;
    const float ln = glm::dot(pt.normal, pt.normal), lg = glm::dot(pt.geomNormal, pt.geomNormal);
    if (!(lg > 1e-12f) || !std::isfinite(lg)) return false;
    ng = pt.geomNormal / std::sqrt(lg);
    n = (ln > 1e-12f && std::isfinite(ln)) ? pt.normal / std::sqrt(ln) : ng;
    return true;
}

struct Gather {
    glm::vec3 radiance{0.f};
    float occlusion = 0.f;
    float samples = 0.f;  // volume samples of all its cones
};

// cone_gatherVoxel from voxel-space p over the march's lanes: the cones start `offset` voxels along ng, `h0` is that
// start's height above the tangent plane for the plane limit.
// `lanes`, when given, gets each lane's direction, weight and occlusion.
Gather gatherVoxel(LevelSampler& sampler, const glm::vec3& p,
                   const glm::vec3& n, const glm::vec3& ng, float offset, float h0, float maxDist, float falloff,
                   float sky, std::vector<SparseLane>* lanes = nullptr) {
    const glm::mat3 frame = gpu::frame_fromZ(n);
    const glm::vec3 origin = p + ng * offset;
    Gather g;
    const MarchParams& mp = *sampler.mp;
    for (size_t c = 0; c < mp.cones.size(); ++c) {
        const glm::vec4& cone = mp.cones[c];
        glm::vec3 d = glm::normalize(frame * glm::vec3(cone));
        const float rise = glm::dot(d, ng);
        const float axisRise =
            mp.lanesPerCone > 1
                ? glm::dot(frame * glm::vec3(mp.axes[size_t(gpu::cone_laneCone(int(c), mp.lanesPerCone))]), ng)
                : rise;
        const int state = gpu::cone_laneState(rise, axisRise);
        auto record = [&](float alpha) {
            if (lanes)
                lanes->push_back({gpu::cone_laneCone(int(c), mp.lanesPerCone), d, glm::vec3(cone), cone.w, alpha});
        };
        if (state == gpu::CONE_LANE_CLOSED) {
            g.occlusion += cone.w;
            record(1.f);
            continue;
        }
        if (state == gpu::CONE_LANE_OPEN) {
            if (!mp.mirror) {
                g.radiance += cone.w * sky;
                record(0.f);
                continue;
            }
            d = gpu::cone_mirrored(d, ng);  // vct.below-plane=mirror
        }
        // vct.aim: towards the point the lane's ray from p reaches at maxDist, and as far as it.
        const glm::vec3 marched = mp.aim ? gpu::cone_aimedDirection(d, ng, offset, maxDist) : d;
        const float reach = mp.aim ? gpu::cone_aimedReach(d, ng, offset, maxDist) : maxDist;
        const gpu::ConeResult r =
            gpu::cone_marchVolume(sampler, sampler.mp->march, origin, marched, h0, glm::dot(marched, ng), reach, falloff);
        g.radiance += cone.w * (r.radiance + (1.f - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
        g.samples += r.samples;
        record(r.alpha);
    }
    return g;
}

// The pixel cones' gather (cone_gather): from the surface point, offset and plane height alike
// (GI over sheets: the start's, cone_sheetStartOffset).
Gather gather(LevelSampler& sampler, const SparseVoxelScene& v,
              const glm::vec3& pWorld, const glm::vec3& n, const glm::vec3& ng, float maxDist, float falloff,
              float sky, std::vector<SparseLane>* lanes = nullptr) {
    const glm::vec3 p = glm::vec3(v.voxelFromWorld * glm::vec4(pWorld, 1.f));
    float offset = sampler.mp->offset;
    if (sampler.gatherer == Gatherer::PixelGI && sampler.sheets) {  // GI over sheets: gpu::cone_sheetStartOffset
        sampler.fetches += gpu::CONE_SHEET_START_FETCHES;
        offset = gpu::cone_sheetStartOffset(sampler, p, ng, offset);
    }
    return gatherVoxel(sampler, p, n, ng, offset, offset, maxDist, falloff, sky, lanes);
}

MarchParams marchParams(const SparseVoxelScene& v, const ConeSettings& s) {
    MarchParams mp;
    const ConeLanes lanes = coneMarchLanes(s, std::max(v.resolution.x, std::max(v.resolution.y, v.resolution.z)));
    mp.cones = lanes.cones;
    mp.axes = lanes.axes;
    mp.lanesPerCone = lanes.lanesPerCone;
    mp.laneApertureDeg = lanes.apertureDeg;
    mp.march.tanHalfAperture = coneFootprintTangent(s, lanes.apertureDeg);
    mp.march.stepFactor = s.stepFactor;
    mp.march.maxAlpha = s.maxAlpha;
    mp.march.planeRatio = s.planeLimit ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f;
    mp.march.levelBase = glm::vec3(v.resolution);
    mp.march.endRatio = s.endTaper ? gpu::cone_endRatio(s.stepFactor) : 0.f;
    mp.march.capTan = 0.f;  // AO over sheets sets it (aoMarch)
    mp.offset = s.offsetVoxels;
    mp.sharpen = sharpensLevels(s) ? s.sharpen : 1.f;
    mp.aim = s.aim;
    mp.mirror = s.belowPlane == ConeBelowPlane::Mirror;
    mp.maxLod = float(int(v.opacityLevels.size()) - 1);
    mp.res = glm::vec3(v.resolution);
    for (int k = 0; k < int(v.opacityLevels.size()); ++k)
        mp.levelScale.push_back(glm::vec3(v.levelSize(k)) / mp.res);
    return mp;
}

void checkVoxels(const SparseVoxelScene& v, const char* what) {
    if (v.opacityLevels.empty() || !v.opacityLevels[0])
        throw InternalError(what, "the sparse voxels have no opacity");
    if (int(v.opacityLevels.size()) != v.levels)
        throw InternalError(what, "the sparse voxels have no levels (buildSparseLevels)");
}

// An AO gather's march over checked voxels: its parameters, the distance R in voxels and the
// falloff (sparseConeAO and its lane by lane twin share it).
struct AoMarch {
    MarchParams mp;
    float maxDist = 0.f, falloff = 0.f;
};

AoMarch aoMarch(const SparseVoxelScene& voxels, float radius, const ConeSettings& settings, const char* what) {
    checkVoxels(voxels, what);
    settings.validate();
    if (!(radius >= 0.f) || !std::isfinite(radius))
        throw InternalError(what, "radius " + std::to_string(radius) + " must be finite and >= 0");
    AoMarch m;
    m.mp = marchParams(voxels, settings);
    // Lane caps where the march reads sheets (cone_sampleSheets, laneCapTangent).
    if (readsSheets(voxels)) m.mp.march.capTan = laneCapTangent(m.mp.lanesPerCone, m.mp.laneApertureDeg);
    m.maxDist = radius / voxels.voxelSize;
    m.falloff = (settings.aoMapping == ConeAoMapping::Falloff && m.maxDist > 0.f)
                    ? gpu::CONE_FALLOFF_LAMBDA_R / m.maxDist
                    : 0.f;
    return m;
}

}  // namespace

// Sums the per-point counts into `cost` (serially: the sum does not depend on the threads).
void sumCost(ConeCost* cost, const std::vector<double>& samples, const std::vector<double>& fetches) {
    if (!cost) return;
    *cost = ConeCost{};
    for (size_t i = 0; i < samples.size(); ++i) cost->addPixel(samples[i], fetches[i], samples[i] > 0.0);
}

std::vector<float> sparseConeAO(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                float radius, const ConeSettings& settings, ConeCost* cost) {
    const AoMarch m = aoMarch(voxels, radius, settings, "sparseConeAO");
    std::vector<float> ao(points.size(), 1.f);
    std::vector<double> samples(points.size(), 0.0), fetches(points.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        LevelSampler sampler(voxels, m.mp, Gatherer::PixelAO);
        for (size_t i = r.begin(); i != r.end(); ++i) {
            glm::vec3 n, ng;
            if (!surface(points[i], n, ng)) continue;
            const double before = sampler.fetches;
            const Gather g = gather(sampler, voxels, points[i].position, n, ng, m.maxDist, m.falloff, 0.f);
            ao[i] = std::clamp(1.f - g.occlusion, 0.f, 1.f);
            samples[i] = g.samples;
            fetches[i] = sampler.fetches - before;
        }
    });
    sumCost(cost, samples, fetches);
    return ao;
}

SparseLanes sparseConeAOLanes(const SparseVoxelScene& voxels, const SparsePoint& point, float radius,
                              const ConeSettings& settings) {
    const AoMarch m = aoMarch(voxels, radius, settings, "sparseConeAOLanes");
    SparseLanes out;
    out.apertureDeg = m.mp.laneApertureDeg;
    glm::vec3 n, ng;
    if (!surface(point, n, ng)) return out;
    LevelSampler sampler(voxels, m.mp, Gatherer::PixelAO);
    gather(sampler, voxels, point.position, n, ng, m.maxDist, m.falloff, 0.f, &out.lanes);
    return out;
}

std::vector<glm::vec3> sparseConeGI(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                    float sky, const ConeSettings& settings, ConeCost* cost) {
    checkVoxels(voxels, "sparseConeGI");
    settings.validate();
    if (!voxels.injected() || voxels.radianceLevels.size() != voxels.opacityLevels.size() ||
        voxels.normalLevels.size() != voxels.opacityLevels.size())
        throw InternalError("sparseConeGI", "the sparse voxels have no radiance (inject first)");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw InternalError("sparseConeGI", "sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    const MarchParams mp = marchParams(voxels, settings);
    // GI cones run until they leave the grid: twice the box diagonal bounds every path.
    const float maxDist = 2.f * glm::length(glm::vec3(voxels.resolution));
    std::vector<glm::vec3> gi(points.size(), glm::vec3(0.f));
    std::vector<double> samples(points.size(), 0.0), fetches(points.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        LevelSampler sampler(voxels, mp, Gatherer::PixelGI);
        for (size_t i = r.begin(); i != r.end(); ++i) {
            glm::vec3 n, ng;
            if (!surface(points[i], n, ng)) continue;
            const double before = sampler.fetches;
            const Gather g = gather(sampler, voxels, points[i].position, n, ng, maxDist, 0.f, sky);
            gi[i] = glm::max(points[i].albedo, glm::vec3(0.f)) * g.radiance;
            samples[i] = g.samples;
            fetches[i] = sampler.fetches - before;
        }
    });
    sumCost(cost, samples, fetches);
    return gi;
}

void traceSparseBounces(SparseVoxelScene& voxels, float sky, const ConeSettings& settings,
                        const BounceSettings& bounce, bool anisotropic) {
    if (!voxels.injected() || !voxels.albedo || !voxels.normal || !voxels.emission)
        throw InternalError("traceSparseBounces", "the sparse voxels have no radiance (inject first)");
    // Emitters by their voxels (the dense grid goes by its materials: a material that emits
    // nowhere in the grid adds a gather of zero emission there, which changes nothing).
    bool emissive = false;
    for (auto it = voxels.emission->cbeginValueOn(); it && !emissive; ++it) emissive = it->lengthSqr() > 0.f;
    const int bounces = std::max(bounce.bounces, 0), gathers = bounceGathers(bounce, emissive, sky);
    if (!bounce.sky) sky = 0.f;
    if (gathers == 0) return;
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw InternalError("traceSparseBounces", "sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    settings.validate();
    // The direct term stays fixed; each bounce re-gathers from the previous total.
    const openvdb::Vec3SGrid::Ptr direct = voxels.radiance;
    const openvdb::FloatTree& opacity = voxels.opacity->tree();
    const float maxDist = 2.f * glm::length(glm::vec3(voxels.resolution));
    // Minutes at 1024^3 on a few cores: a bar on a terminal, in leaf nodes of 8^3 voxels.
    ProgressBar progress("vdb bounces", uint64_t(gathers) * uint64_t(direct->tree().leafCount()), true);
    if (gathers > bounces) {
        // Emitters: the first gather reads the emission alone, premultiplied (cone_bounce.h).
        openvdb::Vec3SGrid::Ptr emitted = direct->deepCopy();
        openvdb::tree::LeafManager<openvdb::Vec3STree> leaves(emitted->tree());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
            ConstAcc3 emissionAcc(voxels.emission->tree());
            OpacityAcc opacityAcc(opacity);
            for (size_t li = r.begin(); li != r.end(); ++li)
                for (auto it = leaves.leaf(li).beginValueOn(); it; ++it)
                    it.setValue(emissionAcc.getValue(it.getCoord()) * opacityAcc.getValue(it.getCoord()));
        });
        voxels.radiance = emitted;
        voxels.radianceLevels = {emitted};
    }
    for (int bounce = 0; bounce < gathers; ++bounce) {
        buildSparseLevels(voxels, anisotropic, anisotropic && wantsDepthLevels(settings));
        const MarchParams mp = marchParams(voxels, settings);
        openvdb::Vec3SGrid::Ptr next = direct->deepCopy();
        openvdb::tree::LeafManager<openvdb::Vec3STree> leaves(next->tree());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
            LevelSampler sampler(voxels, mp, Gatherer::Bounce);
            ConstAcc3 normalAcc(voxels.facing()->tree()), albedoAcc(voxels.albedo->tree());
            OpacityAcc opacityAcc(opacity);
            for (size_t li = r.begin(); li != r.end(); ++li)
                for (auto it = leaves.leaf(li).beginValueOn(); it; ++it) {
                    const openvdb::Coord ijk = it.getCoord();
                    const float a = opacityAcc.getValue(ijk);
                    const openvdb::Vec3s nv = normalAcc.getValue(ijk);
                    const glm::vec3 n(nv[0], nv[1], nv[2]);
                    // bounce_gathers: radiance and a normal (faces that cancel keep their direct light).
                    if (!(a > 0.f) || !(glm::dot(n, n) > 0.f)) continue;
                    const glm::vec3 nn = glm::normalize(n);
                    const glm::vec3 centre = glm::vec3(ijk.x(), ijk.y(), ijk.z()) + 0.5f;
                    const Gather g =
                        gatherVoxel(sampler, centre, nn, nn, mp.offset + 0.5f, mp.offset, maxDist, 0.f, sky);
                    const openvdb::Vec3s albedo = albedoAcc.getValue(ijk), L = it.getValue();
                    glm::vec3 out;
                    for (int c = 0; c < 3; ++c) out[c] = (L[c] / a + albedo[c] * g.radiance[c]) * a;
                    it.setValue(openvdb::Vec3s(out.x, out.y, out.z));
                }
            progress.advance(r.size());
        });
        next->setName(direct->getName());
        voxels.radiance = next;
        voxels.radianceLevels = {next};
    }
}

}  // namespace vct
