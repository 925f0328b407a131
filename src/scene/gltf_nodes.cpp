// The glTF node hierarchy: each node's local transform (matrix or TRS) composed into world
// space, the off-screen marks inherited by descendants, and each node's mesh, light and
// camera converted under its world transform.
#include "scene/gltf_detail.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace vct::gltf_detail {

namespace {

glm::mat4 localFromNode(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m = glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, as glm
        return glm::mat4(m);
    }
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);  // glm quaternions are (w, x, y, z); glTF stores (x, y, z, w)
    if (node.translation.size() == 3) t = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) s = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4)
        r = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
    return glm::mat4(m);
}

bool nodeIsOffscreen(const tinygltf::Node& node) {
    if (node.name.rfind("offscreen", 0) == 0) return true;
    if (node.extras.IsObject() && node.extras.Has("offscreen_occluder")) {
        const tinygltf::Value& v = node.extras.Get("offscreen_occluder");
        if (v.IsBool()) return v.Get<bool>();
        if (v.IsNumber()) return v.GetNumberAsDouble() != 0.0;
    }
    return false;
}

}  // namespace

std::vector<int> rootNodes(const tinygltf::Model& model) {
    if (!model.scenes.empty()) {
        const int s = model.defaultScene >= 0 && model.defaultScene < int(model.scenes.size()) ? model.defaultScene : 0;
        return model.scenes[size_t(s)].nodes;
    }
    std::vector<uint8_t> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& n : model.nodes)
        for (int c : n.children)
            if (c >= 0 && c < int(model.nodes.size())) isChild[size_t(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

void visitNode(LoadContext& load, int nodeIndex, const glm::mat4& worldFromParent, bool parentOffscreen, size_t depth) {
    const tinygltf::Model& model = load.model;
    if (nodeIndex < 0 || nodeIndex >= int(model.nodes.size()))
        load.fail(outOfRange("node", nodeIndex, model.nodes.size()));
    if (depth > model.nodes.size())
        load.fail(label("node", nodeIndex, model.nodes[size_t(nodeIndex)].name) + ": cycle in the node hierarchy");
    const tinygltf::Node& node = model.nodes[size_t(nodeIndex)];
    const std::string where = label("node", nodeIndex, node.name);
    if ((!node.matrix.empty() && node.matrix.size() != 16) || (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3) || (!node.translation.empty() && node.translation.size() != 3))
        load.fail(where + ": malformed matrix/translation/rotation/scale");
    for (const std::vector<double>* v : {&node.matrix, &node.rotation, &node.scale, &node.translation})
        for (double x : *v)
            if (!std::isfinite(x)) load.fail(where + ": transform has a non-finite value");
    const glm::mat4 worldFromLocal = worldFromParent * localFromNode(node);
    // Finite doubles can overflow the float matrix (a translation of 1e39): blame the node,
    // not the first vertex it moves.
    for (int c = 0; c < 4; ++c)
        if (!std::isfinite(worldFromLocal[c].x) || !std::isfinite(worldFromLocal[c].y) ||
            !std::isfinite(worldFromLocal[c].z) || !std::isfinite(worldFromLocal[c].w))
            load.fail(where + ": world transform is not finite in single precision");
    const bool offscreen = parentOffscreen || nodeIsOffscreen(node);

    if (node.mesh >= 0) {
        if (node.mesh >= int(model.meshes.size()))
            load.fail(where + ": " + outOfRange("mesh", node.mesh, model.meshes.size()));
        const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
        const uint32_t first = uint32_t(load.scene.positions.size());
        for (size_t p = 0; p < mesh.primitives.size(); ++p)
            addPrimitive(load, node.mesh, int(p), worldFromLocal, offscreen);
        std::vector<int> chain = load.nodeStack;
        chain.push_back(nodeIndex);
        const uint32_t count = uint32_t(load.scene.positions.size()) - first;
        if (count > 0) load.placedMeshes.push_back({nodeIndex, first, count, worldFromLocal, std::move(chain)});
    }
    load.nodeStack.push_back(nodeIndex);
    const size_t lightsBefore = load.scene.lights.size();
    addLight(load, node, nodeIndex, worldFromLocal);
    if (load.scene.lights.size() > lightsBefore) load.placedLights.push_back({lightsBefore, load.nodeStack});
    if (node.camera >= 0) {
        const size_t before = load.scene.cameras.size();
        addCamera(load, node, nodeIndex, worldFromLocal);
        // Remembered only when it was added (orthographic cameras are skipped).
        if (load.scene.cameras.size() > before) load.placedCameras.push_back({before, load.nodeStack});
    }
    for (int child : node.children) visitNode(load, child, worldFromLocal, offscreen, depth + 1);
    load.nodeStack.pop_back();
}

}  // namespace vct::gltf_detail
