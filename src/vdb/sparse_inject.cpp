// Direct light into the sparse voxels: the CPU twin of shaders/voxelize/inject.glsl.
// L = emission + albedo / pi * sum_lights E, E the irradiance of each KHR_lights_punctual light
// on the voxel's average normal with visibility from a walk through the level-0 opacity.
// Radiance is per area, so nothing scales with the voxel size. The walk is hierarchical: a
// DDA over 8^3 leaf blocks (OpenVDB's math::DDA) skips empty blocks, and a voxel DDA runs only
// inside blocks that hold a leaf; it crosses the same voxels as the GPU's Amanatides-Woo walk.
// Two-sided voxels (voxelize_shared.h) are lit on each face and get a facing normal
// (SparseVoxelScene::facingNormal), as inject.glsl rewrites the GPU's normal texture.
#include "core/errors.h"
#include "vdb/sparse_detail.h"
#include "voxelize/voxelize_shared.h"

#include <openvdb/math/DDA.h>
#include <openvdb/math/Ray.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace vct {

namespace {

using namespace vdbdetail;
using RayT = openvdb::math::Ray<double>;
constexpr float kPi = 3.14159265358979f;
constexpr float kFloatMax = std::numeric_limits<float>::max();

// Transmittance from `o` (voxel units) along unit `d` up to tMax (inject_visibility).
float visibility(const ConstAcc<openvdb::FloatTree>& acc, const glm::vec3& res, const glm::vec3& o,
                 const glm::vec3& d, float tMax) {
    // Clip to the grid box: outside it there is nothing to block.
    glm::vec3 invD;
    for (int a = 0; a < 3; ++a) invD[a] = d[a] != 0.f ? 1.f / d[a] : 1.0e30f;
    const glm::vec3 t0 = (glm::vec3(0.f) - o) * invD, t1 = (res - o) * invD;
    const glm::vec3 tNear = glm::min(t0, t1), tFar = glm::max(t0, t1);
    const float tEnter = std::max(0.f, std::max(tNear.x, std::max(tNear.y, tNear.z)));
    const float tExit = std::min(tMax, std::min(tFar.x, std::min(tFar.y, tFar.z)));
    if (!(tEnter < tExit)) return 1.f;

    const RayT ray(openvdb::Vec3d(o.x, o.y, o.z), openvdb::Vec3d(d.x, d.y, d.z), tEnter, tExit);
    float transmittance = 1.f;
    openvdb::math::DDA<RayT, 3> blocks(ray, tEnter, tExit);
    do {
        const openvdb::Coord block = blocks.voxel();
        if (!acc.probeConstLeaf(block) && !acc.isValueOn(block)) continue;
        openvdb::math::DDA<RayT, 0> voxels(ray, blocks.time(), std::max(blocks.time(), blocks.next()));
        do {
            float opacity = 0.f;
            if (acc.probeValue(voxels.voxel(), opacity)) {
                transmittance *= 1.f - opacity;
                if (transmittance < 0.01f) return 0.f;
            }
        } while (voxels.step());
    } while (blocks.step());
    return transmittance;
}

struct InjectContext {
    const Scene* scene;
    glm::vec3 res;
    glm::vec3 origin;
    float voxelSize;
    float offset;
};

// inject_lightIrradiance: a zero normal (faces both ways) is lit as if facing the light at
// half weight, since half its area faces away.
glm::vec3 lightIrradiance(const InjectContext& ctx, const Light& light, const glm::vec3& pWorld,
                          const glm::vec3& pVoxel, const glm::vec3& n, const ConstAcc<openvdb::FloatTree>& acc) {
    glm::vec3 toLight;
    float distance;
    glm::vec3 intensity = light.color;
    if (light.type == LightType::Directional) {
        toLight = -glm::normalize(light.direction);
        distance = 3.4e38f;
    } else {
        const glm::vec3 dl = light.position - pWorld;
        distance = glm::length(dl);
        if (distance <= 0.f) return glm::vec3(0.f);
        toLight = dl / distance;
        intensity /= std::max(distance * distance, 0.25f * ctx.voxelSize * ctx.voxelSize);
        if (light.type == LightType::Spot) {
            // glTF KHR_lights_punctual smooth falloff between the outer and inner cones.
            const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
            const float cd = glm::dot(glm::normalize(light.direction), -toLight);
            const float scale = 1.f / std::max(0.001f, cosInner - cosOuter);
            const float att = std::clamp((cd - cosOuter) * scale, 0.f, 1.f);
            intensity *= att * att;
        }
    }
    const bool twoSided = glm::dot(n, n) < 0.5f;
    const float cosine = twoSided ? 0.5f : glm::dot(n, toLight);
    if (cosine <= 0.f || intensity == glm::vec3(0.f)) return glm::vec3(0.f);
    const glm::vec3 start = pVoxel + (twoSided ? toLight : n) * ctx.offset;
    const float tMax = distance / ctx.voxelSize - glm::length(start - pVoxel);
    if (tMax <= 0.f) return intensity * cosine;
    return intensity * cosine * visibility(acc, ctx.res, start, toLight, tMax);
}

}  // namespace

void injectSparseRadiance(SparseVoxelScene& voxels, const Scene& scene, float shadowOffsetVoxels) {
    if (!voxels.opacity || !voxels.albedo || !voxels.normal || !voxels.emission)
        throw InternalError("injectSparseRadiance", "the scene is not voxelized");
    if (!std::isfinite(shadowOffsetVoxels) || shadowOffsetVoxels < 0.f)
        throw InternalError("injectSparseRadiance", "shadow offset must be finite and >= 0");
    for (const Light& l : scene.lights)
        if (!std::isfinite(l.color.x + l.color.y + l.color.z) ||
            !std::isfinite(l.position.x + l.position.y + l.position.z) ||
            !std::isfinite(l.direction.x + l.direction.y + l.direction.z))
            throw std::runtime_error("injectSparseRadiance: light '" + l.name + "' has a non-finite value");
    const auto t0 = std::chrono::steady_clock::now();
    const InjectContext ctx{&scene, glm::vec3(voxels.resolution), voxels.origin, voxels.voxelSize,
                            shadowOffsetVoxels};

    const openvdb::FloatTree& opacity = voxels.opacity->tree();
    auto radiance = std::make_shared<openvdb::Vec3STree>(opacity, openvdb::Vec3s(0.f), openvdb::Vec3s(0.f),
                                                         openvdb::TopologyCopy());
    openvdb::tree::LeafManager<const openvdb::FloatTree> opacityLeaves(opacity);
    openvdb::tree::LeafManager<openvdb::Vec3STree> radianceLeaves(*radiance);
    // Written only at two-sided voxels; every other voxel keeps its normal.
    openvdb::Vec3SGrid::Ptr facing = voxels.twoSided ? voxels.normal->deepCopy() : nullptr;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, opacityLeaves.leafCount()), [&](const tbb::blocked_range<size_t>& r) {
        ConstAcc<openvdb::FloatTree> opAcc(opacity);
        ConstAcc<openvdb::Vec3STree> alAcc(voxels.albedo->tree()), nrAcc(voxels.normal->tree()),
            emAcc(voxels.emission->tree());
        std::unique_ptr<ConstAcc<openvdb::FloatTree>> twoSidedAcc;
        std::unique_ptr<openvdb::Vec3SGrid::Accessor> facingAcc;
        if (facing) {
            twoSidedAcc = std::make_unique<ConstAcc<openvdb::FloatTree>>(voxels.twoSided->tree());
            facingAcc = std::make_unique<openvdb::Vec3SGrid::Accessor>(facing->getAccessor());
        }
        for (size_t li = r.begin(); li != r.end(); ++li) {
            const auto& opLeaf = opacityLeaves.leaf(li);
            auto& outLeaf = radianceLeaves.leaf(li);
            for (auto it = opLeaf.cbeginValueOn(); it; ++it) {
                const float alpha = *it;
                if (alpha <= 0.f) continue;
                const openvdb::Coord ijk = it.getCoord();
                const openvdb::Vec3s a = alAcc.getValue(ijk), nv = nrAcc.getValue(ijk), e = emAcc.getValue(ijk);
                const glm::vec3 albedo(a[0], a[1], a[2]), n(nv[0], nv[1], nv[2]);
                const glm::vec3 pVoxel = glm::vec3(ijk.x(), ijk.y(), ijk.z()) + 0.5f;
                const glm::vec3 pWorld = voxels.origin + pVoxel * voxels.voxelSize;
                const glm::vec3 emitted(e[0], e[1], e[2]);
                if (twoSidedAcc && twoSidedAcc->getValue(ijk) >= gpu::VOX_TWO_SIDED_SHARE && glm::dot(n, n) > 0.25f) {
                    // inject.glsl's two-sided branch: each face lit with its own cosine and shadow ray.
                    const glm::vec3 front = glm::normalize(n);
                    glm::vec3 Ef(0.f), Eb(0.f);
                    for (const Light& light : scene.lights) {
                        Ef += lightIrradiance(ctx, light, pWorld, pVoxel, front, opAcc);
                        Eb += lightIrradiance(ctx, light, pWorld, pVoxel, -front, opAcc);
                    }
                    const glm::vec3 Lf = glm::min(emitted + albedo / kPi * Ef, glm::vec3(kFloatMax));
                    const glm::vec3 Lb = glm::min(emitted + albedo / kPi * Eb, glm::vec3(kFloatMax));
                    const float k = gpu::vox_twoSidedNormalScale(Lf, Lb);
                    const glm::vec3 f = front * k, L = (k >= 0.f ? Lf : Lb) * alpha;
                    facingAcc->setValueOnly(ijk, openvdb::Vec3s(f.x, f.y, f.z));
                    outLeaf.setValueOnly(it.pos(), openvdb::Vec3s(L.x, L.y, L.z));
                    continue;
                }
                glm::vec3 E(0.f);
                for (const Light& light : scene.lights) E += lightIrradiance(ctx, light, pWorld, pVoxel, n, opAcc);
                glm::vec3 L = emitted + albedo / kPi * E;
                L = glm::min(L, glm::vec3(kFloatMax)) * alpha;
                outLeaf.setValueOnly(it.pos(), openvdb::Vec3s(L.x, L.y, L.z));
            }
        }
    });
    voxels.radiance = openvdb::Vec3SGrid::create(radiance);
    voxels.radiance->setName("radiance");
    voxels.radiance->setTransform(levelTransform(voxels, 0));
    voxels.radianceLevels = {voxels.radiance};
    if (facing) facing->setName("facing_normal");
    voxels.facingNormal = facing;
    voxels.stats.injectSeconds = secondsSince(t0);
    updateSparseMemoryStats(voxels);
}

}  // namespace vct
