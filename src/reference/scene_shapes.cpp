#include "reference/scene_shapes.h"

#include "reference/sampling_math.h"

#include <cmath>

namespace vct {

namespace {

uint32_t addVertex(Scene& scene, glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
    scene.positions.push_back(p);
    scene.normals.push_back(n);
    scene.uvs.push_back(uv);
    if (!scene.colors.empty()) scene.colors.push_back(glm::vec4(1.f));  // kept parallel to positions
    scene.bounds.expand(p);
    return uint32_t(scene.positions.size() - 1);
}

void addTriangle(Scene& scene, uint32_t a, uint32_t b, uint32_t c, uint32_t material) {
    scene.triangles.emplace_back(a, b, c);
    scene.triangleMaterial.push_back(material);
    scene.triangleOffscreen.push_back(0);
}

}  // namespace

uint32_t addMaterial(Scene& scene, const Material& material) {
    scene.materials.push_back(material);
    return uint32_t(scene.materials.size() - 1);
}

uint32_t addDiffuseMaterial(Scene& scene, glm::vec3 albedo, glm::vec3 emission) {
    Material m;
    m.baseColorFactor = glm::vec4(albedo, 1.f);
    m.emissiveFactor = emission;
    m.doubleSided = true;
    return addMaterial(scene, m);
}

void addQuad(Scene& scene, glm::vec3 corner, glm::vec3 edgeU, glm::vec3 edgeV, uint32_t material) {
    glm::vec3 n = glm::normalize(glm::cross(edgeU, edgeV));
    uint32_t a = addVertex(scene, corner, n, {0.f, 0.f});
    uint32_t b = addVertex(scene, corner + edgeU, n, {1.f, 0.f});
    uint32_t c = addVertex(scene, corner + edgeU + edgeV, n, {1.f, 1.f});
    uint32_t d = addVertex(scene, corner + edgeV, n, {0.f, 1.f});
    addTriangle(scene, a, b, c, material);
    addTriangle(scene, a, c, d, material);
}

void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool inward) {
    glm::vec3 e = hi - lo;
    glm::vec3 ex(e.x, 0, 0), ey(0, e.y, 0), ez(0, 0, e.z);
    // Each face as (corner, u, v) with cross(u, v) pointing outward.
    struct Face { glm::vec3 corner, u, v; };
    const Face faces[6] = {
        {lo, ez, ey}, {lo + ex, ey, ez},       // -x, +x
        {lo, ex, ez}, {lo + ey, ez, ex},       // -y, +y
        {lo, ey, ex}, {lo + ez, ex, ey},       // -z, +z
    };
    for (const Face& f : faces) {
        if (inward) addQuad(scene, f.corner, f.v, f.u, material);
        else addQuad(scene, f.corner, f.u, f.v, material);
    }
}

void addDisc(Scene& scene, glm::vec3 centre, glm::vec3 normal, float radius, int segments, uint32_t material) {
    Frame frame = Frame::fromZ(glm::normalize(normal));
    uint32_t c = addVertex(scene, centre, frame.z, {0.5f, 0.5f});
    std::vector<uint32_t> ring;
    for (int i = 0; i < segments; ++i) {
        float phi = 2.f * 3.14159265358979f * float(i) / float(segments);
        glm::vec2 d(std::cos(phi), std::sin(phi));
        ring.push_back(addVertex(scene, centre + radius * (d.x * frame.x + d.y * frame.y), frame.z, 0.5f + 0.5f * d));
    }
    for (int i = 0; i < segments; ++i) addTriangle(scene, c, ring[size_t(i)], ring[size_t((i + 1) % segments)], material);
}

void scaleScene(Scene& scene, float s) {
    scene.bounds = Bounds3{};
    for (glm::vec3& p : scene.positions) {
        p *= s;
        scene.bounds.expand(p);
    }
    for (Light& l : scene.lights) l.position *= s;
    for (Camera& c : scene.cameras) {
        c.eye *= s;
        c.target *= s;
        c.znear *= s;
        c.zfar *= s;
    }
}

}  // namespace vct
