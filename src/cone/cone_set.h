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

}  // namespace vct
