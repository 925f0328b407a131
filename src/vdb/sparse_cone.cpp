// The CPU cone marcher: shaders/cone/cone_march.glsl line for line (cone_march, cone_gather,
// cone_surface), over the sparse levels instead of 3D textures.
#include "vdb/sparse_cone.h"

#include "cone/cone_set.h"
#include "cone/cone_shared.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace vct {

namespace {

using OpacityAcc = openvdb::tree::ValueAccessor<const openvdb::FloatTree, false>;  // unregistered: read-only trees
using RadianceAcc = openvdb::tree::ValueAccessor<const openvdb::Vec3STree, false>;

struct MarchParams {
    float tanHalf, beta, offset, maxAlpha, planeRatio, maxLod;
    glm::vec3 res;
    std::vector<glm::vec3> levelScale;  // level texel coordinates per voxel unit: size_k / res
};

// One thread's view of the levels.
struct LevelSampler {
    const MarchParams* mp;
    std::vector<std::unique_ptr<OpacityAcc>> opacity;
    std::vector<std::unique_ptr<RadianceAcc>> radiance;  // empty for AO
    std::vector<std::unique_ptr<RadianceAcc>> normal;    // GI only: normal levels (facing test)

    LevelSampler(const SparseVoxelScene& v, const MarchParams& params, bool gi) : mp(&params) {
        for (const auto& g : v.opacityLevels) opacity.push_back(std::make_unique<OpacityAcc>(g->tree()));
        if (gi) {
            for (const auto& g : v.radianceLevels) radiance.push_back(std::make_unique<RadianceAcc>(g->tree()));
            for (const auto& g : v.normalLevels) normal.push_back(std::make_unique<RadianceAcc>(g->tree()));
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
    glm::vec4 sampleLevel(const glm::vec3& p, int level) {
        const openvdb::Vec3R xyz = levelCoord(p, level);
        const float a = openvdb::tools::BoxSampler::sample(*opacity[size_t(level)], xyz);
        if (radiance.empty()) return glm::vec4(0.f, 0.f, 0.f, a);
        const openvdb::Vec3s c = openvdb::tools::BoxSampler::sample(*radiance[size_t(level)], xyz);
        return glm::vec4(c[0], c[1], c[2], a);
    }

    // textureLod: premultiplied radiance (GI) and opacity at footprint 2^lod.
    glm::vec4 sample(const glm::vec3& p, float lod) {
        return acrossLevels(lod, [&](int level) { return sampleLevel(p, level); });
    }

    // cone_facing: vox_facingWeight of the occupied voxels' mean normal at the sample's level,
    // the filtered normal over the filtered coverage (`coverage`: the opacity sample).
    float facing(const glm::vec3& p, const glm::vec3& d, float lod, float coverage) {
        const glm::vec3 n = acrossLevels(lod, [&](int level) {
            const openvdb::Vec3s v = openvdb::tools::BoxSampler::sample(*normal[size_t(level)], levelCoord(p, level));
            return glm::vec3(v[0], v[1], v[2]);
        });
        return gpu::vox_facingWeight(n / std::max(coverage, 1e-4f), d);
    }
};

struct ConeResult {
    glm::vec3 radiance{0.f};
    float alpha = 0.f;
};

// cone_march: origin in voxel units, unit d; h0/rise for the plane limit.
ConeResult march(LevelSampler& sampler, const glm::vec3& origin, const glm::vec3& d, float h0, float rise,
                 float maxDist, float falloff) {
    const MarchParams& mp = *sampler.mp;
    ConeResult r;
    float t = 0.f;
    for (int i = 0; i < gpu::CONE_MAX_STEPS; ++i) {
        if (t >= maxDist || r.alpha >= mp.maxAlpha) break;
        float lod = std::log2(std::max(1.f, 2.f * t * mp.tanHalf));
        if (mp.planeRatio > 0.f) {
            const float h = h0 + t * rise;
            lod = std::min(lod, std::floor(std::log2(std::max(1.f, h / mp.planeRatio))));
        }
        lod = std::min(lod, mp.maxLod);
        const float texel = std::exp2(lod);
        const float dt = std::min(mp.beta * texel, maxDist - t);
        const glm::vec3 p = origin + d * (t + 0.5f * dt);

        const float reach = 1.5f * texel;
        bool leaving = false;
        for (int a = 0; a < 3; ++a)
            leaving = leaving || (p[a] < -reach && d[a] <= 0.f) || (p[a] > mp.res[a] + reach && d[a] >= 0.f);
        if (leaving) break;

        glm::vec4 s = sampler.sample(p, lod);
        if (!sampler.radiance.empty()) s = glm::vec4(glm::vec3(s) * sampler.facing(p, d, lod, s.a), s.a);
        const float a = std::clamp(s.a, 0.f, 1.f);
        const float k = dt / texel;
        const float aStep = 1.f - std::exp2(k * std::log2(std::max(1.f - a, 1e-7f)));
        const glm::vec3 c = a > 1e-6f ? glm::vec3(s) * (aStep / a) : glm::vec3(s) * k;
        const float w = falloff > 0.f ? 1.f / (1.f + falloff * (t + 0.5f * dt)) : 1.f;
        r.radiance += (1.f - r.alpha) * c;
        r.alpha += (1.f - r.alpha) * aStep * w;
        t += dt;
    }
    if (r.alpha >= mp.maxAlpha) {
        r.radiance /= r.alpha;
        r.alpha = 1.f;
    }
    return r;
}

// cone_frame (Duff et al. 2017): columns t, b, n.
void coneFrame(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float s = n.z >= 0.f ? 1.f : -1.f;
    const float a = -1.f / (s + n.z);
    const float bb = n.x * n.y * a;
    t = glm::vec3(1.f + s * n.x * n.x * a, s * bb, -s * n.x);
    b = glm::vec3(bb, s + n.y * n.y * a, -n.y);
}

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

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
};

Gather gather(LevelSampler& sampler, const SparseVoxelScene& v, const std::vector<glm::vec4>& cones,
              const glm::vec3& pWorld, const glm::vec3& n, const glm::vec3& ng, float maxDist, float falloff,
              float sky) {
    const glm::vec3 p = glm::vec3(v.voxelFromWorld * glm::vec4(pWorld, 1.f));
    glm::vec3 t, b;
    coneFrame(n, t, b);
    const float offset = sampler.mp->offset;
    const glm::vec3 origin = p + ng * offset;
    Gather g;
    for (const glm::vec4& cone : cones) {
        const glm::vec3 d = glm::normalize(t * cone.x + b * cone.y + n * cone.z);
        const float rise = glm::dot(d, ng);
        if (rise <= 0.f) {
            g.occlusion += cone.w;
            continue;
        }
        const ConeResult r = march(sampler, origin, d, offset, rise, maxDist, falloff);
        g.radiance += cone.w * (r.radiance + (1.f - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
    }
    return g;
}

MarchParams marchParams(const SparseVoxelScene& v, const ConeSettings& s) {
    MarchParams mp;
    mp.tanHalf = std::tan(0.5f * s.apertureDeg * float(M_PI) / 180.f);
    mp.beta = s.stepFactor;
    mp.offset = s.offsetVoxels;
    mp.maxAlpha = s.maxAlpha;
    mp.planeRatio = s.planeLimit ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f;
    mp.maxLod = float(int(v.opacityLevels.size()) - 1);
    mp.res = glm::vec3(v.resolution);
    for (int k = 0; k < int(v.opacityLevels.size()); ++k)
        mp.levelScale.push_back(glm::vec3(v.levelSize(k)) / mp.res);
    return mp;
}

void checkVoxels(const SparseVoxelScene& v, const char* what) {
    if (v.opacityLevels.empty() || !v.opacityLevels[0])
        throw std::invalid_argument(std::string(what) + ": the sparse voxels have no opacity");
    if (int(v.opacityLevels.size()) != v.levels)
        throw std::invalid_argument(std::string(what) + ": the sparse voxels have no levels (buildSparseLevels)");
}

}  // namespace

std::vector<float> sparseConeAO(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                float radius, const ConeSettings& settings) {
    checkVoxels(voxels, "sparseConeAO");
    settings.validate();
    if (!(radius >= 0.f) || !std::isfinite(radius))
        throw std::invalid_argument("sparseConeAO: radius " + std::to_string(radius) + " must be finite and >= 0");
    const MarchParams mp = marchParams(voxels, settings);
    const float maxDist = radius / voxels.voxelSize;
    const float falloff = (settings.aoMapping == ConeAoMapping::Falloff && maxDist > 0.f)
                              ? gpu::CONE_FALLOFF_LAMBDA_R / maxDist
                              : 0.f;
    const std::vector<glm::vec4> cones = diffuseConeSet(settings.coneCount);
    std::vector<float> ao(points.size(), 1.f);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        LevelSampler sampler(voxels, mp, false);
        for (size_t i = r.begin(); i != r.end(); ++i) {
            glm::vec3 n, ng;
            if (!surface(points[i], n, ng)) continue;
            const Gather g = gather(sampler, voxels, cones, points[i].position, n, ng, maxDist, falloff, 0.f);
            ao[i] = std::clamp(1.f - g.occlusion, 0.f, 1.f);
        }
    });
    return ao;
}

std::vector<glm::vec3> sparseConeGI(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                    float sky, const ConeSettings& settings) {
    checkVoxels(voxels, "sparseConeGI");
    settings.validate();
    if (!voxels.injected() || voxels.radianceLevels.size() != voxels.opacityLevels.size() ||
        voxels.normalLevels.size() != voxels.opacityLevels.size())
        throw std::invalid_argument("sparseConeGI: the sparse voxels have no radiance (inject first)");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw std::invalid_argument("sparseConeGI: sky radiance " + std::to_string(sky) + " must be finite and >= 0");
    const MarchParams mp = marchParams(voxels, settings);
    // GI cones run until they leave the grid: twice the box diagonal bounds every path.
    const float maxDist = 2.f * glm::length(glm::vec3(voxels.resolution));
    const std::vector<glm::vec4> cones = diffuseConeSet(settings.coneCount);
    std::vector<glm::vec3> gi(points.size(), glm::vec3(0.f));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        LevelSampler sampler(voxels, mp, true);
        for (size_t i = r.begin(); i != r.end(); ++i) {
            glm::vec3 n, ng;
            if (!surface(points[i], n, ng)) continue;
            const Gather g = gather(sampler, voxels, cones, points[i].position, n, ng, maxDist, 0.f, sky);
            gi[i] = glm::max(points[i].albedo, glm::vec3(0.f)) * g.radiance;
        }
    });
    return gi;
}

}  // namespace vct
