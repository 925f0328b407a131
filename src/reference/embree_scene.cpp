#include "reference/embree_scene.h"

#include "reference/sampling_math.h"
#include "scene/texture_sampler.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vct {

namespace {

void throwOnDeviceError(RTCDevice device, const char* what) {
    RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree error ") + std::to_string(int(e)) + " in " + what);
}

uint32_t materialOf(const Scene& s, uint32_t tri) {
    return tri < s.triangleMaterial.size() ? s.triangleMaterial[tri] : uint32_t(-1);
}

glm::vec2 uvAt(const Scene& s, uint32_t tri, float u, float v) {
    if (s.uvs.size() != s.positions.size()) return glm::vec2(0.f);
    const glm::uvec3& t = s.triangles[tri];
    return (1.f - u - v) * s.uvs[t.x] + u * s.uvs[t.y] + v * s.uvs[t.z];
}

// Rejects hits on texels whose glTF coverage alpha is below the material's cutoff.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
    const Scene& scene = *static_cast<const Scene*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        uint32_t tri = RTCHitN_primID(args->hit, args->N, i);
        uint32_t mat = materialOf(scene, tri);
        if (mat >= scene.materials.size() || !scene.materials[mat].alphaMask) continue;
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const glm::vec4 color = vertexColorAt(scene, tri, glm::vec3(1.f - u - v, u, v));
        if (materialAlpha(scene, mat, uvAt(scene, tri, u, v), color) < scene.materials[mat].alphaCutoff)
            args->valid[i] = 0;
    }
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene) : mSource(&scene) {
    const size_t vertexCount = scene.positions.size();
    for (size_t i = 0; i < vertexCount; ++i) {
        const glm::vec3& p = scene.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::runtime_error("EmbreeScene: vertex " + std::to_string(i) + " of scene '" + scene.path +
                                     "' has a non-finite position");
        mSceneMaxAbs = std::max(mSceneMaxAbs, maxAbsComponent(p));
    }
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        const glm::uvec3& t = scene.triangles[i];
        if (t.x >= vertexCount || t.y >= vertexCount || t.z >= vertexCount)
            throw std::runtime_error("EmbreeScene: triangle " + std::to_string(i) + " of scene '" + scene.path +
                                     "' indexes a vertex out of range");
    }

    mDevice = rtcNewDevice(nullptr);
    if (!mDevice) throw std::runtime_error("EmbreeScene: rtcNewDevice failed");
    mScene = rtcNewScene(mDevice);
    rtcSetSceneFlags(mScene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(mScene, RTC_BUILD_QUALITY_HIGH);

    if (!scene.triangles.empty()) {
        mVertices.resize(vertexCount * 3 + 1, 0.f);
        for (size_t i = 0; i < vertexCount; ++i) {
            mVertices[3 * i + 0] = scene.positions[i].x;
            mVertices[3 * i + 1] = scene.positions[i].y;
            mVertices[3 * i + 2] = scene.positions[i].z;
        }
        RTCGeometry geom = rtcNewGeometry(mDevice, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mVertices.data(), 0,
                                   3 * sizeof(float), vertexCount);
        static_assert(sizeof(glm::uvec3) == 3 * sizeof(uint32_t), "tightly packed index triples");
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, scene.triangles.data(), 0,
                                   sizeof(glm::uvec3), scene.triangles.size());
        rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
        bool anyMask = false;
        for (const Material& m : scene.materials) anyMask = anyMask || m.alphaMask;
        if (anyMask) {
            rtcSetGeometryUserData(geom, const_cast<Scene*>(&scene));
            rtcSetGeometryIntersectFilterFunction(geom, alphaMaskFilter);
            rtcSetGeometryOccludedFilterFunction(geom, alphaMaskFilter);
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(mScene, geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(mScene);
    throwOnDeviceError(mDevice, "EmbreeScene construction");
}

EmbreeScene::~EmbreeScene() {
    if (mScene) rtcReleaseScene(mScene);
    if (mDevice) rtcReleaseDevice(mDevice);
}

bool EmbreeScene::intersect(const glm::vec3& org, const glm::vec3& dir, float tnear, float tfar,
                            uint32_t* triangle, float* u, float* v, float* t) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = rayHit(org, dir, tnear, tfar);
    rtcIntersect1(mScene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    *triangle = rh.hit.primID;
    *u = rh.hit.u;
    *v = rh.hit.v;
    *t = rh.ray.tfar;
    return true;
}

void EmbreeScene::intersectCoherent(RTCRayHit* rays, unsigned count) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(mScene, &context, rays, count, sizeof(RTCRayHit));
}

bool EmbreeScene::occluded(const glm::vec3& org, const glm::vec3& dir, float tfar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = org.x; r.org_y = org.y; r.org_z = org.z; r.tnear = 0.f;
    r.dir_x = dir.x; r.dir_y = dir.y; r.dir_z = dir.z; r.time = 0.f;
    r.tfar = tfar; r.mask = 0xFFFFFFFFu; r.id = 0; r.flags = 0;
    rtcOccluded1(mScene, &context, &r);
    return r.tfar < 0.f;
}

SurfaceHit EmbreeScene::surfaceAt(uint32_t triangle, float u, float v, const glm::vec3& incomingDir) const {
    const Scene& s = *mSource;
    const glm::uvec3& t = s.triangles[triangle];
    const glm::vec3 &p0 = s.positions[t.x], &p1 = s.positions[t.y], &p2 = s.positions[t.z];
    float w = 1.f - u - v;
    SurfaceHit h;
    h.triangle = triangle;
    h.position = w * p0 + u * p1 + v * p2;
    h.errorScale = std::max(std::max(maxAbsComponent(p0), maxAbsComponent(p1)),
                            std::max(maxAbsComponent(p2), maxAbsComponent(h.position)));
    glm::vec3 ng = glm::cross(p1 - p0, p2 - p0);
    float len = glm::length(ng);
    // Embree never reports hits on zero-area triangles, but a sliver's cross product can
    // still underflow in float: fall back to facing the ray.
    ng = len > 0.f && std::isfinite(len) ? ng / len : -glm::normalize(incomingDir);
    h.frontFacing = !(glm::dot(ng, incomingDir) > 0.f);
    if (!h.frontFacing) ng = -ng;
    h.geomNormal = ng;
    glm::vec3 ns = ng;
    if (s.normals.size() == s.positions.size()) {
        glm::vec3 n = w * s.normals[t.x] + u * s.normals[t.y] + v * s.normals[t.z];
        float nl = glm::length(n);
        if (nl > 1e-12f && std::isfinite(nl)) {
            n /= nl;
            ns = glm::dot(n, ng) < 0.f ? -n : n;
        }
    }
    h.shadingNormal = ns;
    h.uv = uvAt(s, triangle, u, v);
    h.color = vertexColorAt(s, triangle, glm::vec3(w, u, v));
    return h;
}

void OcclusionBatch::trace() {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCScene scene = mScene.handle();
    switch (mMode) {
        case RayMode::Single:
            for (int i = 0; i < mCount; ++i) rtcOccluded1(scene, &context, &mRays[i]);
            break;
        case RayMode::Stream:
            context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
            rtcOccluded1M(scene, &context, mRays, unsigned(mCount), sizeof(RTCRay));
            break;
        case RayMode::Packet8:
        case RayMode::Packet16: {
            const int width = mMode == RayMode::Packet8 ? 8 : 16;
            alignas(64) RTCRay16 packet;
            for (int base = 0; base < mCount; base += width) {
                alignas(64) int valid[16];
                if (width == 8) {
                    alignas(32) RTCRay8 p8;
                    for (int k = 0; k < 8; ++k) {
                        int i = base + k;
                        valid[k] = i < mCount ? -1 : 0;
                        const RTCRay& r = mRays[i < mCount ? i : base];
                        p8.org_x[k] = r.org_x; p8.org_y[k] = r.org_y; p8.org_z[k] = r.org_z; p8.tnear[k] = r.tnear;
                        p8.dir_x[k] = r.dir_x; p8.dir_y[k] = r.dir_y; p8.dir_z[k] = r.dir_z; p8.time[k] = 0.f;
                        p8.tfar[k] = r.tfar; p8.mask[k] = r.mask; p8.id[k] = 0; p8.flags[k] = 0;
                    }
                    rtcOccluded8(valid, scene, &context, &p8);
                    for (int k = 0; k < 8 && base + k < mCount; ++k) mRays[base + k].tfar = p8.tfar[k];
                } else {
                    for (int k = 0; k < 16; ++k) {
                        int i = base + k;
                        valid[k] = i < mCount ? -1 : 0;
                        const RTCRay& r = mRays[i < mCount ? i : base];
                        packet.org_x[k] = r.org_x; packet.org_y[k] = r.org_y; packet.org_z[k] = r.org_z;
                        packet.tnear[k] = r.tnear; packet.dir_x[k] = r.dir_x; packet.dir_y[k] = r.dir_y;
                        packet.dir_z[k] = r.dir_z; packet.time[k] = 0.f; packet.tfar[k] = r.tfar;
                        packet.mask[k] = r.mask; packet.id[k] = 0; packet.flags[k] = 0;
                    }
                    rtcOccluded16(valid, scene, &context, &packet);
                    for (int k = 0; k < 16 && base + k < mCount; ++k) mRays[base + k].tfar = packet.tfar[k];
                }
            }
            break;
        }
    }
}

}  // namespace vct
