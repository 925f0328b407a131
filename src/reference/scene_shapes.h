// Tiny builders of analytic test scenes straight into a vct::Scene (no file round trip):
// the closed-form checks of the reference renderers, and anyone else's, use them.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace vct {

// Appends a material and returns its index.
uint32_t addMaterial(Scene& scene, const Material& material);
uint32_t addDiffuseMaterial(Scene& scene, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.f));

// Parallelogram corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV; its normal is
// normalize(cross(edgeU, edgeV)); uv (0,0) at the corner, (1,1) opposite.
void addQuad(Scene& scene, glm::vec3 corner, glm::vec3 edgeU, glm::vec3 edgeV, uint32_t material);
// Axis-aligned box, normals facing inward (`inward`) or outward.
void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool inward);
// Regular `segments`-gon inscribed in the circle (centre, radius) of the plane with `normal`.
void addDisc(Scene& scene, glm::vec3 centre, glm::vec3 normal, float radius, int segments, uint32_t material);
// Multiplies every position (and light position) by `s`.
void scaleScene(Scene& scene, float s);

}  // namespace vct
