#include "support/test_scenes.h"

#include "scene/camera.h"

namespace vcttest {

uint32_t addMaterial(vct::Scene& s, glm::vec3 albedo, glm::vec3 emission) {
    vct::Material m;
    m.baseColorFactor = glm::vec4(albedo, 1.f);
    m.emissiveFactor = emission;
    m.doubleSided = true;
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
}

void addQuad(vct::Scene& s, glm::vec3 c, glm::vec3 u, glm::vec3 v, uint32_t material) {
    uint32_t base = uint32_t(s.positions.size());
    glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (glm::vec3 p : {c, c + u, c + u + v, c + v}) {
        s.positions.push_back(p);
        s.normals.push_back(n);
        s.uvs.push_back(glm::vec2(0.f));
    }
    s.triangles.push_back({base, base + 1, base + 2});
    s.triangles.push_back({base, base + 2, base + 3});
    for (int i = 0; i < 2; ++i) {
        s.triangleMaterial.push_back(material);
        s.triangleOffscreen.push_back(0);
    }
}

void addBox(vct::Scene& s, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    glm::vec3 d = hi - lo;
    glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
    addQuad(s, lo, y, x, material);           // -z
    addQuad(s, lo + z, x, y, material);       // +z
    addQuad(s, lo, z, y, material);           // -x
    addQuad(s, lo + x, y, z, material);       // +x
    addQuad(s, lo, x, z, material);           // -y
    addQuad(s, lo + y, z, x, material);       // +y
}

vct::Camera lookAt(const vct::Scene& s, glm::vec3 eye, glm::vec3 target, float fovDeg) {
    vct::CameraRequest cam;
    cam.hasEye = true;
    cam.eye = eye;
    cam.target = target;
    cam.fovDeg = fovDeg;
    return vct::resolveCamera(s, cam, 1.f);
}

void finish(vct::Scene& s) {
    s.bounds = vct::Bounds3{};
    for (const auto& p : s.positions) s.bounds.expand(p);
}

}  // namespace vcttest
