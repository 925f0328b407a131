// Embree 3 over vct::Scene: one RTC_GEOMETRY_TYPE_TRIANGLE whose index buffer is the
// Scene's own triangle array (shared, not copied) and whose vertex buffer is a padded copy
// of Scene::positions (Embree reads vertices with 16-byte loads, so the last vertex needs
// 4 bytes of slack that a std::vector<glm::vec3> does not promise). Robust scene flag, high
// build quality, no backface culling: back faces occlude, as the AO definition (every surface two-sided) asks.
// Alpha-masked materials (glTF alphaMode MASK) are honoured by intersection/occlusion
// filter functions that test baseColorFactor.a x texture alpha against the cutoff.
#pragma once

#include "scene/scene.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace vct {

// A surface hit rebuilt from Embree's (primID, u, v): position from the barycentrics
// (pbrt's choice: its error is bounded by the vertex magnitudes, not by t), normals faced
// toward the incoming direction, texture coordinates and vertex colours interpolated.
struct SurfaceHit {
    glm::vec3 position{0.f};
    glm::vec3 geomNormal{0.f, 0.f, 1.f};     // unit, faces the side the ray came from
    bool frontFacing = true;                 // the ray came from the side of the winding normal
    glm::vec3 shadingNormal{0.f, 0.f, 1.f};  // unit, interpolated, on geomNormal's side
    glm::vec2 uv{0.f};
    glm::vec4 color{1.f};  // the vertex colour (Scene::colors) at the hit
    uint32_t triangle = 0;
    float errorScale = 0.f;  // max |coordinate| of the triangle's vertices and the point
};

class EmbreeScene {
  public:
    // `scene` must outlive this object (its triangle array is shared with Embree).
    // Throws std::runtime_error naming the first non-finite vertex or bad index.
    explicit EmbreeScene(const Scene& scene);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    RTCScene handle() const { return mScene; }
    const Scene& scene() const { return *mSource; }
    bool empty() const { return mSource->triangles.empty(); }
    // Max |coordinate| over the scene bounds (0 for an empty scene).
    float sceneMaxAbs() const { return mSceneMaxAbs; }

    // Closest hit along org + t dir, t in [tnear, tfar]; dir need not be unit.
    bool intersect(const glm::vec3& org, const glm::vec3& dir, float tnear, float tfar, uint32_t* triangle,
                   float* u, float* v, float* t) const;
    bool occluded(const glm::vec3& org, const glm::vec3& dir, float tfar) const;
    // Closest hits of `count` rays that start together and point nearly the same way (the
    // samples of one pixel), traced as one coherent stream: Embree packs them into packets
    // that share their BVH traversal. Each ray's hit is set as rtcIntersect1 would set it.
    void intersectCoherent(RTCRayHit* rays, unsigned count) const;

    SurfaceHit surfaceAt(uint32_t triangle, float u, float v, const glm::vec3& incomingDir) const;

  private:
    RTCDevice mDevice = nullptr;
    RTCScene mScene = nullptr;
    const Scene* mSource = nullptr;
    std::vector<float> mVertices;  // xyz per vertex + 1 float of padding at the end
    float mSceneMaxAbs = 0.f;
};

// A ray to intersect along org + t dir, t in [tnear, tfar], with no hit yet.
inline RTCRayHit rayHit(const glm::vec3& org, const glm::vec3& dir, float tnear, float tfar) {
    RTCRayHit rh;
    rh.ray.org_x = org.x; rh.ray.org_y = org.y; rh.ray.org_z = org.z; rh.ray.tnear = tnear;
    rh.ray.dir_x = dir.x; rh.ray.dir_y = dir.y; rh.ray.dir_z = dir.z; rh.ray.time = 0.f;
    rh.ray.tfar = tfar; rh.ray.mask = 0xFFFFFFFFu; rh.ray.id = 0; rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// Spawn point for a ray leaving a surface on the side of `geomNormal`: the offset grows with
// the magnitude of the coordinates (float rounding of positions and of Embree's intersection
// test is relative to them), so it works unchanged for scenes scaled from 1e-4 to 1e5.
// 2^-19 is ~2.5x pbrt-v4's error bound gamma(7) * sum|b_i p_i| for barycentric positions.
inline glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& geomNormal, float errorScale) {
    constexpr float kRelative = 0x1p-19f;
    constexpr float kAbsoluteFloor = 1e-30f;  // keeps p = 0 off the plane; far below any scene scale
    return p + geomNormal * (errorScale * kRelative + kAbsoluteFloor);
}

// How occlusion rays are handed to Embree, in batches of 256. bench_reference on Sponza
// (256x256, 64 spp, R = 1, 4.15M rays, 2 cores with AVX-512, loaded machine), time relative
// to a bare rtcOccluded1 loop over the same precomputed rays: Single 1.89x, Stream
// (rtcOccluded1M, incoherent) 1.32x, Packet8 1.47x, Packet16 1.25x. Stream is the default:
// within noise of Packet16 and no packing code on the hot path.
enum class RayMode : int { Single = 0, Stream = 1, Packet8 = 2, Packet16 = 3 };

// A buffer of occlusion rays, traced in one go when full or flushed. Each ray carries an
// owner id; `flush` calls visit(owner, visible) in the order the rays were added.
class OcclusionBatch {
  public:
    static constexpr int kCapacity = 256;
    OcclusionBatch(const EmbreeScene& scene, RayMode mode) : mScene(scene), mMode(mode) {}

    template <typename Visit>
    void add(const glm::vec3& org, const glm::vec3& dir, float tfar, uint32_t owner, Visit&& visit) {
        RTCRay& r = mRays[mCount];
        r.org_x = org.x; r.org_y = org.y; r.org_z = org.z; r.tnear = 0.f;
        r.dir_x = dir.x; r.dir_y = dir.y; r.dir_z = dir.z; r.time = 0.f;
        r.tfar = tfar; r.mask = 0xFFFFFFFFu; r.id = 0; r.flags = 0;
        mOwners[mCount++] = owner;
        if (mCount == kCapacity) flush(visit);
    }
    template <typename Visit>
    void flush(Visit&& visit) {
        if (mCount == 0) return;
        trace();
        for (int i = 0; i < mCount; ++i) visit(mOwners[i], mRays[i].tfar >= 0.f);
        mRaysTraced += uint64_t(mCount);
        mCount = 0;
    }
    uint64_t raysTraced() const { return mRaysTraced; }

  private:
    void trace();  // sets tfar = -inf on occluded rays
    const EmbreeScene& mScene;
    RayMode mMode;
    int mCount = 0;
    uint64_t mRaysTraced = 0;
    RTCRay mRays[kCapacity];
    uint32_t mOwners[kCapacity];
};

}  // namespace vct
