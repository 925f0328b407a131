// CPU voxel cone tracing over the sparse voxels (vdb/sparse_voxels.h): the same cone sets
// (cone/cone_set.h), settings and AO mapping as the GPU passes, and their march itself
// (shaders/cone/cone_march_shared.h, compiled as C++), with the GL sampling reproduced on the
// VDB trees: trilinear within a level (tools::BoxSampler at the GL texel centres of that
// level, zero outside the occupied set) and linear between the two levels around the
// fractional level (quadrilinear), the level clamped to [0, levels - 1]. When the voxels were
// built with directional levels (SparseBuildOptions::anisotropic, as the dense grid's
// vct.aniso=1) a sample reads them as cone_march.glsl does, sharpened with vct.sharpen; else the
// isotropic levels. TBB over points; the result does not depend on the thread count.
#pragma once

#include "cone/cone_bounce.h"
#include "cone/cone_cost.h"
#include "cone/cone_settings.h"
#include "vdb/sparse_voxels.h"

#include <glm/glm.hpp>

#include <vector>

namespace vct {

// One surface point per pixel, top row first (as the reference's SurfacePoint, plus albedo).
struct SparsePoint {
    glm::vec3 position{0.f};                // world space
    glm::vec3 normal{0.f, 0.f, 1.f};        // shading normal (normalized here; 0 -> geomNormal)
    glm::vec3 geomNormal{0.f, 0.f, 1.f};    // geometric normal on the viewer's side (cone offset, horizon)
    glm::vec3 albedo{0.f};                  // linear albedo (GI only)
    bool valid = false;                     // false = sky: AO 1, GI 0
};

// AO in [0, 1] per point (coneTraceAO): 1 - sum_c w_c alpha_c, cones limited to `radius`
// (world units, >= 0). Reads the opacity levels.
// `cost`, when given, gets the samples and fetches counted as the GPU pass counts them.
std::vector<float> sparseConeAO(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                float radius, const ConeSettings& settings, ConeCost* cost = nullptr);

// One lane of one point's AO gather, as sparseConeAO marches it.
struct SparseLane {
    int cone = 0;               // the cone of the set it belongs to
    glm::vec3 direction{0.f};   // its ray from the surface point (world space; before vct.aim)
    glm::vec3 tangent{0.f};     // the same in the tangent frame of the shading normal (z = normal)
    float weight = 0.f;         // its share of the cosine-weighted hemisphere (the lanes sum to 1)
    float alpha = 0.f;          // the occlusion it composited: 1 closed by the surface's plane, 0 left open
};

// The lanes of `point`'s AO gather, in the set's order: 1 - sum_l weight_l alpha_l is the point's
// sparseConeAO. No lanes for a point without a usable surface (sky).
struct SparseLanes {
    float apertureDeg = 0.f;  // each lane's full aperture, as the march chose it for these voxels
    std::vector<SparseLane> lanes;
};
SparseLanes sparseConeAOLanes(const SparseVoxelScene& voxels, const SparsePoint& point, float radius,
                              const ConeSettings& settings);

// Indirect diffuse radiance per point (coneTraceGI): albedo * sum_c w_c (L_c + (1 - alpha_c) sky),
// cones run until they leave the grid. Requires injected radiance. Invalid points give 0.
std::vector<glm::vec3> sparseConeGI(const SparseVoxelScene& voxels, const std::vector<SparsePoint>& points,
                                    float sky, const ConeSettings& settings, ConeCost* cost = nullptr);

// `bounce.bounces` further diffuse bounces between the voxels (shaders/cone/cone_bounce.glsl):
// each occupied level-0 voxel with a normal gathers the previous total around its normal with the
// pixel cones' march, so its radiance becomes direct + albedo * sum_c w_c (L_c + (1 - alpha_c)
// sky), the cones starting offset + 0.5 voxels out (the voxel's surface may lie half a voxel
// from its centre); escaping cones see `sky` unless bounce.sky is off. A scene with emitters
// (emission, or a sky the cones see) gathers once more first, from the emission alone
// (bounceGathers, cone_bounce.h). Rebuilds the levels (directional ones when `anisotropic`)
// before each gather from the previous one; the caller builds the final levels. Requires
// injected radiance.
void traceSparseBounces(SparseVoxelScene& voxels, float sky, const ConeSettings& settings,
                        const BounceSettings& bounce, bool anisotropic);

}  // namespace vct
