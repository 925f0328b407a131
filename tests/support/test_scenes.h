// Tiny scenes built directly in code for closed-form tests.
#pragma once

#include "scene/scene.h"

namespace vcttest {

// Adds a material and returns its index.
uint32_t addMaterial(vct::Scene& s, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.f));
// Adds the quad with corners c, c+u, c+u+v, c+v (normal along cross(u, v)).
void addQuad(vct::Scene& s, glm::vec3 c, glm::vec3 u, glm::vec3 v, uint32_t material);
// Adds an axis-aligned box (12 triangles, outward normals).
void addBox(vct::Scene& s, glm::vec3 lo, glm::vec3 hi, uint32_t material);
// Recomputes bounds (call after adding geometry).
void finish(vct::Scene& s);
// A square image's camera at `eye` looking at `target` with a vertical field of view in degrees.
vct::Camera lookAt(const vct::Scene& s, glm::vec3 eye, glm::vec3 target, float fovDeg);

}  // namespace vcttest
