// KHR_lights_punctual lights and perspective cameras, placed by their node's world
// transform; both look down -Z of the node with +Y up.
#include "scene/gltf_detail.h"

#include <algorithm>
#include <cmath>

namespace vct::gltf_detail {

void addLight(LoadContext& load, const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal) {
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return;
    const std::string nodeWhere = label("node", nodeIndex, node.name);
    const int index = ext->second.Get("light").GetNumberAsInt();
    if (index < 0 || index >= int(load.model.lights.size()))
        load.fail(nodeWhere + ": " + outOfRange("light", index, load.model.lights.size()));
    const tinygltf::Light& l = load.model.lights[size_t(index)];
    const std::string where = label("light", index, l.name) + " (" + nodeWhere + ")";
    Light out;
    out.name = l.name.empty() ? (node.name.empty() ? "light" + std::to_string(index) : node.name) : l.name;
    if (l.type == "directional")
        out.type = LightType::Directional;
    else if (l.type == "point")
        out.type = LightType::Point;
    else if (l.type == "spot")
        out.type = LightType::Spot;
    else
        load.fail(where + ": unknown type '" + l.type + "'");
    glm::vec3 color(1.f);
    if (l.color.size() == 3) color = glm::vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
    out.color = color * float(l.intensity);
    out.range = float(l.range);
    out.innerConeAngle = float(l.spot.innerConeAngle);
    out.outerConeAngle = float(l.spot.outerConeAngle);
    out.position = glm::vec3(worldFromLocal * glm::vec4(0.f, 0.f, 0.f, 1.f));
    const glm::vec3 dir = glm::mat3(worldFromLocal) * glm::vec3(0.f, 0.f, -1.f);
    if (!finite3(color) || !std::isfinite(l.intensity) || !finite3(out.color) || !std::isfinite(out.range) ||
        !std::isfinite(out.innerConeAngle) || !std::isfinite(out.outerConeAngle) || !finite3(out.position) ||
        !finite3(dir))
        load.fail(where + ": colour, intensity, range, cone angles or transform not finite");
    if (l.intensity < 0 || glm::any(glm::lessThan(color, glm::vec3(0.f))) || out.range < 0.f)
        load.fail(where + ": negative colour, intensity or range");
    if (glm::length(dir) <= 0.f) load.fail(where + ": node transform collapses the light direction");
    out.direction = glm::normalize(dir);
    if (out.type == LightType::Spot &&
        !(out.innerConeAngle >= 0.f && out.innerConeAngle <= out.outerConeAngle && out.outerConeAngle <= 1.5707964f))
        load.fail(where + ": spot cone angles must satisfy 0 <= inner <= outer <= pi/2");
    load.scene.lights.push_back(out);
}

void addCamera(LoadContext& load, const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal) {
    const std::string nodeWhere = label("node", nodeIndex, node.name);
    if (node.camera >= int(load.model.cameras.size()))
        load.fail(nodeWhere + ": " + outOfRange("camera", node.camera, load.model.cameras.size()));
    const tinygltf::Camera& c = load.model.cameras[size_t(node.camera)];
    const std::string where = label("camera", node.camera, c.name) + " (" + nodeWhere + ")";
    if (c.type != "perspective") {
        load.scene.warnings.push_back(where + ": " + c.type + " camera skipped (only perspective is supported)");
        return;
    }
    Camera out;
    out.name = !c.name.empty()      ? c.name
               : !node.name.empty() ? node.name
                                    : "camera" + std::to_string(node.camera);
    const tinygltf::PerspectiveCamera& p = c.perspective;
    if (!std::isfinite(p.yfov) || !(p.yfov > 0.0) || !(p.yfov < M_PI))
        load.fail(where + ": yfov " + std::to_string(p.yfov) + " not in (0, pi)");
    if (!std::isfinite(p.znear) || !(p.znear > 0.0))
        load.fail(where + ": znear " + std::to_string(p.znear) + " not > 0");
    if (!std::isfinite(p.zfar) || (p.zfar != 0.0 && !(p.zfar > p.znear)))
        load.fail(where + ": zfar " + std::to_string(p.zfar) + " must be 0 (infinite) or > znear");
    out.yfov = float(p.yfov);
    out.znear = float(p.znear);
    out.zfar = float(p.zfar);
    const glm::mat3 linear(worldFromLocal);
    out.eye = glm::vec3(worldFromLocal * glm::vec4(0.f, 0.f, 0.f, 1.f));
    glm::vec3 forward = linear * glm::vec3(0.f, 0.f, -1.f);
    glm::vec3 up = linear * glm::vec3(0.f, 1.f, 0.f);
    if (!finite3(out.eye) || !finite3(forward) || !finite3(up)) load.fail(where + ": node transform is not finite");
    if (!(glm::length(forward) > 0.f)) load.fail(where + ": node transform collapses the view direction");
    forward = glm::normalize(forward);
    up -= glm::dot(up, forward) * forward;  // re-orthogonalize under shear or non-uniform scale
    if (!(glm::length(up) > 0.f)) load.fail(where + ": node transform collapses the up direction");
    out.up = glm::normalize(up);
    out.target = out.eye + forward;
    if (p.zfar == 0.0) load.camerasWithInfiniteFar.push_back(load.scene.cameras.size());
    load.scene.cameras.push_back(out);
}

void boundInfiniteFarPlanes(LoadContext& load) {
    // A glTF zfar of 0 means an infinite far plane: give those cameras one that holds the scene.
    const Bounds3& bounds = load.scene.bounds;
    for (size_t i : load.camerasWithInfiniteFar) {
        Camera& c = load.scene.cameras[i];
        const float reach = glm::length(glm::abs(c.eye - bounds.center()) + 0.5f * bounds.extent());
        c.zfar = std::max(2.f * reach, 1000.f * c.znear);
    }
}

}  // namespace vct::gltf_detail
