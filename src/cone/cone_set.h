// The diffuse cone sets: directions in the tangent frame (z = normal) and weights that
// integrate the cosine lobe, (1/pi) * integral over the cone's share of the hemisphere of
// cos(theta) dw, so sum_c w_c = 1 and sum_c w_c * f_c estimates (1/pi) * integral f cos dw.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace vct {

// xyz = unit direction (z >= 0 is up the normal), w = weight; the weights sum to 1.
// 6: Villegas 2016 - one cone along the normal, five at 60 degrees from it. With 60-degree
//    cones the central one covers the cap theta < 30 deg, whose cosine weight is
//    sin^2(30 deg) = 1/4; the five others split the rest, 3/20 each.
// 16, 32, 64: a Vogel spiral on the unit disc lifted to the hemisphere (Malley's method): each
//    point stands for an equal area of the disc, i.e. an equal share of the cosine lobe, 1/N;
//    as N grows with the cones narrowing (cone/cone_shared.h), the set's sum tends to the
//    cosine integral, so refining cones with voxels drives the total error down.
std::vector<glm::vec4> diffuseConeSet(int coneCount);

// The cones a march traces for a set: each cone of the set (aperture `apertureDeg`) split
// into `lanes` narrower cones, its lanes, spread uniformly in solid angle over its cap (a
// Vogel spiral in cos(theta) and azimuth), each with 1 / lanes of its cap's solid angle and
// 1 / lanes of its weight. One lane is the cone itself.
//
// Why: a cone's samples average the voxels over its footprint, which grows with distance in
// world units whatever the grid's resolution, so with a fixed set the march converges to the
// prefiltered estimate of that footprint, not to the cone's exact visibility: two occluders
// in one footprint composite as if independent, a wall beside the cone darkens every sample
// it touches, a thin sheet's trilinear tent lets light through. Lanes whose footprint at R
// stays a fixed number of voxels as the grid refines (lanes ~ resolution^2) make each lane
// resolve what the cone only averaged, so the march approaches the cone's exact visibility.
//
// A lane below the surface's geometric plane is open when its cone's axis is above it: the
// part of a cone below the plane is open (a cone never sees the surface it starts from, and
// the cone model, reference/cone_model.h, counts those directions open), or with
// vct.below-plane=mirror marched reflected above the plane (the cone model reflects them too),
// and a cone whose axis is below the plane is closed, every lane of it. The lanes of cone c are
// cones[c * lanesPerCone, (c + 1) * lanesPerCone), so a march finds a lane's cone by index.
struct ConeLanes {
    std::vector<glm::vec4> cones;  // xyz = direction (tangent frame), w = weight; sum of w = 1
    float apertureDeg = 0.f;       // each lane's full aperture
    int lanesPerCone = 1;
    std::vector<glm::vec4> axes;   // the set's cones, whose axes decide a lane below the plane
};
ConeLanes coneLanes(const std::vector<glm::vec4>& set, float apertureDeg, int lanes);

// vct.lanes = 0 (auto): (maxResolution / baseResolution)^2 lanes, rounded, clamped to
// [1, CONE_MAX_CONES / coneCount]: a lane's footprint at a given distance stays the same
// number of voxels as the grid refines. Otherwise `lanes` itself. `baseResolution`
// (vct.lanes-base, CONE_LANES_BASE_RES by default) is the resolution at which auto marches
// each cone whole.
int resolveConeLanes(int lanes, int coneCount, int maxResolution, int baseResolution);

}  // namespace vct
