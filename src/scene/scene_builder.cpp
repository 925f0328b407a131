#include "scene/scene_builder.h"

#include "core/errors.h"
#include "scene/gltf_loader.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace vct {
namespace {

std::vector<double> toDoubles(const float* p, int n) { return std::vector<double>(p, p + n); }

// Appends the parallelogram corner, +u, +u+v, +v (front face along cross(u, v)).
void appendQuad(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                std::vector<uint32_t>& indices, const glm::vec3& corner, const glm::vec3& u,
                const glm::vec3& v) {
    const uint32_t base = uint32_t(positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (const glm::vec3& p : {corner, corner + u, corner + u + v, corner + v}) {
        positions.push_back(p);
        normals.push_back(n);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
}

// The 24-vertex box [-h, h] with outward normals.
void appendBox(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
               std::vector<uint32_t>& indices, const glm::vec3& h) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 u(0.f), v(0.f), n(0.f);
        u[(axis + 1) % 3] = 2.f * h[(axis + 1) % 3];
        v[(axis + 2) % 3] = 2.f * h[(axis + 2) % 3];  // cross(u, v) points along +axis
        for (float s : {1.f, -1.f}) {
            n = glm::vec3(0.f);
            n[axis] = s * h[axis];
            const glm::vec3 corner = n - 0.5f * u - 0.5f * v;
            if (s > 0.f)
                appendQuad(positions, normals, indices, corner, u, v);
            else
                appendQuad(positions, normals, indices, corner, v, u);
        }
    }
}

}  // namespace

glm::quat rotationLookingAlong(const glm::vec3& direction, const glm::vec3& up) {
    const glm::vec3 forward = glm::normalize(direction);
    glm::vec3 upHint = up;
    if (std::abs(glm::dot(glm::normalize(up), forward)) > 0.999f)
        upHint = std::abs(forward.y) < 0.9f ? glm::vec3(0.f, 1.f, 0.f) : glm::vec3(0.f, 0.f, -1.f);
    // Columns of worldFromNode: the node's +X, +Y, +Z axes in world space; -Z is `forward`.
    const glm::vec3 z = -forward;
    const glm::vec3 x = glm::normalize(glm::cross(upHint, z));
    const glm::vec3 y = glm::cross(z, x);
    return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

SceneBuilder::SceneBuilder(std::string name) : sceneName(std::move(name)) {
    model.asset.version = "2.0";
    model.asset.generator = "vct SceneBuilder";
    model.buffers.emplace_back();
}

int SceneBuilder::addBufferView(const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    buffer.resize((buffer.size() + 3) & ~size_t(3), 0);  // 4-byte alignment for every view
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    buffer.resize(buffer.size() + bytes);
    std::memcpy(buffer.data() + view.byteOffset, data, bytes);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size()) - 1;
}

int SceneBuilder::addMaterial(const std::string& name, const glm::vec3& baseColor, const glm::vec3& emissive,
                              bool doubleSided) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {baseColor.r, baseColor.g, baseColor.b, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 1.0;
    m.doubleSided = doubleSided;
    const float peak = std::max(emissive.r, std::max(emissive.g, emissive.b));
    if (peak > 1.f) {  // emissiveFactor is clamped to [0, 1] by the spec: carry the rest as strength
        m.emissiveFactor = {emissive.r / peak, emissive.g / peak, emissive.b / peak};
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(double(peak));
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
        if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                      "KHR_materials_emissive_strength") == model.extensionsUsed.end())
            model.extensionsUsed.push_back("KHR_materials_emissive_strength");
    } else {
        m.emissiveFactor = {emissive.r, emissive.g, emissive.b};
    }
    model.materials.push_back(m);
    return int(model.materials.size()) - 1;
}

int SceneBuilder::addMesh(const std::string& name, const std::vector<glm::vec3>& positions,
                          const std::vector<glm::vec3>& normals, const std::vector<uint32_t>& indices,
                          int material, int mode) {
    if (positions.empty()) throw InternalError("SceneBuilder::addMesh", "'" + name + "': no positions");
    if (!normals.empty() && normals.size() != positions.size())
        throw InternalError("SceneBuilder::addMesh", "'" + name + "': normal and position counts differ");
    tinygltf::Primitive prim;
    prim.material = material;
    prim.mode = mode;

    tinygltf::Accessor pos;
    pos.bufferView =
        addBufferView(positions.data(), positions.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    pos.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    pos.type = TINYGLTF_TYPE_VEC3;
    pos.count = positions.size();
    glm::vec3 lo(positions[0]), hi(positions[0]);  // min/max are required for POSITION
    for (const glm::vec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    pos.minValues = toDoubles(&lo.x, 3);
    pos.maxValues = toDoubles(&hi.x, 3);
    model.accessors.push_back(pos);
    prim.attributes["POSITION"] = int(model.accessors.size()) - 1;

    if (!normals.empty()) {
        tinygltf::Accessor nrm;
        nrm.bufferView =
            addBufferView(normals.data(), normals.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        nrm.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        nrm.type = TINYGLTF_TYPE_VEC3;
        nrm.count = normals.size();
        model.accessors.push_back(nrm);
        prim.attributes["NORMAL"] = int(model.accessors.size()) - 1;
    }
    if (!indices.empty()) {
        tinygltf::Accessor idx;
        const bool small = *std::max_element(indices.begin(), indices.end()) < 65536u;
        if (small) {
            std::vector<uint16_t> shortIndices(indices.begin(), indices.end());
            idx.bufferView = addBufferView(shortIndices.data(), shortIndices.size() * 2,
                                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            idx.bufferView =
                addBufferView(indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        }
        idx.type = TINYGLTF_TYPE_SCALAR;
        idx.count = indices.size();
        model.accessors.push_back(idx);
        prim.indices = int(model.accessors.size()) - 1;
    }
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    return int(model.meshes.size()) - 1;
}

void SceneBuilder::attach(int node, int parent) {
    if (parent < 0) {
        roots.push_back(node);
        return;
    }
    if (parent >= int(model.nodes.size()))
        throw InternalError("SceneBuilder", "parent node " + std::to_string(parent) + " does not exist");
    model.nodes[size_t(parent)].children.push_back(node);
}

int SceneBuilder::addNode(const std::string& name, int mesh, const NodeTransform& t, int parent) {
    tinygltf::Node node;
    node.name = name;
    node.mesh = mesh;
    if (t.translation != glm::vec3(0.f)) node.translation = toDoubles(&t.translation.x, 3);
    if (t.rotation != glm::quat(1.f, 0.f, 0.f, 0.f))
        node.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
    if (t.scale != glm::vec3(1.f)) node.scale = toDoubles(&t.scale.x, 3);
    model.nodes.push_back(node);
    const int index = int(model.nodes.size()) - 1;
    attach(index, parent);
    return index;
}

int SceneBuilder::addNodeMatrix(const std::string& name, const glm::mat4& parentFromNode, int mesh,
                                int parent) {
    tinygltf::Node node;
    node.name = name;
    node.mesh = mesh;
    node.matrix = toDoubles(&parentFromNode[0][0], 16);  // column-major, as glTF
    model.nodes.push_back(node);
    const int index = int(model.nodes.size()) - 1;
    attach(index, parent);
    return index;
}

int SceneBuilder::addBox(const std::string& name, const glm::vec3& min, const glm::vec3& max, int material,
                         int parent) {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
    appendBox(positions, normals, indices, 0.5f * (max - min));
    NodeTransform t;
    t.translation = 0.5f * (min + max);
    return addNode(name, addMesh(name, positions, normals, indices, material), t, parent);
}

int SceneBuilder::addTransformedBox(const std::string& name, const NodeTransform& parentFromUnitBox,
                                    int material, int parent) {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
    appendBox(positions, normals, indices, glm::vec3(0.5f));
    return addNode(name, addMesh(name, positions, normals, indices, material), parentFromUnitBox, parent);
}

int SceneBuilder::addQuad(const std::string& name, const glm::vec3& corner, const glm::vec3& edgeU,
                          const glm::vec3& edgeV, int material, int parent) {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
    appendQuad(positions, normals, indices, corner, edgeU, edgeV);
    return addNode(name, addMesh(name, positions, normals, indices, material), NodeTransform{}, parent);
}

int SceneBuilder::addPlane(const std::string& name, const glm::vec3& center, const glm::vec2& size,
                           int material, int parent) {
    // cross(+Z, +X) = +Y: the front face looks up.
    const glm::vec3 u(0.f, 0.f, size.y), v(size.x, 0.f, 0.f);
    return addQuad(name, center - 0.5f * u - 0.5f * v, u, v, material, parent);
}

void SceneBuilder::setExtra(int node, const std::string& key, const tinygltf::Value& value) {
    tinygltf::Value& extras = model.nodes.at(size_t(node)).extras;
    tinygltf::Value::Object object;
    if (extras.IsObject())
        for (const std::string& k : extras.Keys()) object[k] = extras.Get(k);
    object[key] = value;
    extras = tinygltf::Value(object);
}

void SceneBuilder::markOffscreen(int node) { setExtra(node, "offscreen_occluder", tinygltf::Value(true)); }

int SceneBuilder::addLightNode(const std::string& name, const tinygltf::Light& light,
                               const glm::vec3& position, const glm::vec3& direction, int parent) {
    model.lights.push_back(light);
    NodeTransform t;
    t.translation = position;
    if (glm::length(direction) > 0.f) t.rotation = rotationLookingAlong(direction);
    const int node = addNode(name, -1, t, parent);
    tinygltf::Value::Object ext;
    ext["light"] = tinygltf::Value(int(model.lights.size()) - 1);
    model.nodes[size_t(node)].extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_lights_punctual") ==
        model.extensionsUsed.end())
        model.extensionsUsed.push_back("KHR_lights_punctual");
    return node;
}

int SceneBuilder::addPointLight(const std::string& name, const glm::vec3& position, const glm::vec3& color,
                                float intensity, int parent) {
    tinygltf::Light l;
    l.name = name;
    l.type = "point";
    l.color = {color.r, color.g, color.b};
    l.intensity = intensity;
    return addLightNode(name, l, position, glm::vec3(0.f), parent);
}

int SceneBuilder::addSpotLight(const std::string& name, const glm::vec3& position, const glm::vec3& direction,
                               const glm::vec3& color, float intensity, float innerConeAngle,
                               float outerConeAngle, int parent) {
    tinygltf::Light l;
    l.name = name;
    l.type = "spot";
    l.color = {color.r, color.g, color.b};
    l.intensity = intensity;
    l.spot.innerConeAngle = innerConeAngle;
    l.spot.outerConeAngle = outerConeAngle;
    return addLightNode(name, l, position, direction, parent);
}

int SceneBuilder::addDirectionalLight(const std::string& name, const glm::vec3& direction,
                                      const glm::vec3& color, float intensity, int parent) {
    tinygltf::Light l;
    l.name = name;
    l.type = "directional";
    l.color = {color.r, color.g, color.b};
    l.intensity = intensity;
    return addLightNode(name, l, glm::vec3(0.f), direction, parent);
}

int SceneBuilder::addCamera(const std::string& name, const glm::vec3& eye, const glm::vec3& target,
                            float yfovRadians, float znear, float zfar, const glm::vec3& up) {
    tinygltf::Camera c;
    c.name = name;
    c.type = "perspective";
    c.perspective.yfov = yfovRadians;
    c.perspective.znear = znear;
    c.perspective.zfar = zfar;
    model.cameras.push_back(c);
    NodeTransform t;
    t.translation = eye;
    t.rotation = rotationLookingAlong(target - eye, up);
    const int node = addNode(name, -1, t, -1);
    model.nodes[size_t(node)].camera = int(model.cameras.size()) - 1;
    return node;
}

void SceneBuilder::addTranslationAnimation(const std::string& name, int node, const std::vector<float>& times,
                                           const std::vector<glm::vec3>& positions) {
    if (times.empty() || times.size() != positions.size())
        throw std::invalid_argument("SceneBuilder::addTranslationAnimation: one position per time");
    auto floatAccessor = [&](const void* data, size_t count, int type) {
        tinygltf::Accessor a;
        a.bufferView = addBufferView(data, count * sizeof(float) * size_t(tinygltf::GetNumComponentsInType(uint32_t(type))), 0);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.type = type;
        a.count = count;
        model.accessors.push_back(a);
        return int(model.accessors.size()) - 1;
    };
    const int input = floatAccessor(times.data(), times.size(), TINYGLTF_TYPE_SCALAR);
    model.accessors[size_t(input)].minValues = {times.front()};
    model.accessors[size_t(input)].maxValues = {times.back()};
    const int output = floatAccessor(positions.data(), positions.size(), TINYGLTF_TYPE_VEC3);
    auto it = std::find_if(model.animations.begin(), model.animations.end(),
                           [&](const tinygltf::Animation& a) { return a.name == name; });
    if (it == model.animations.end()) {
        model.animations.emplace_back();
        model.animations.back().name = name;
        it = model.animations.end() - 1;
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = output;
    sampler.interpolation = "LINEAR";
    it->samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = int(it->samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = "translation";
    it->channels.push_back(channel);
}

tinygltf::Model SceneBuilder::build() const {
    tinygltf::Model out = model;
    tinygltf::Scene scene;
    scene.name = sceneName;
    scene.nodes = roots;
    out.scenes = {scene};
    out.defaultScene = 0;
    if (out.buffers[0].data.empty()) out.buffers.clear();
    return out;
}

Scene SceneBuilder::toScene() const { return sceneFromModel(build(), sceneName); }

void SceneBuilder::write(const std::string& path) const {
    const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    const std::string temporary = path + ".tmp";
    tinygltf::Model m = build();
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&m, temporary, /*embedImages=*/true, /*embedBuffers=*/true,
                                     /*prettyPrint=*/true, binary))
        throw std::runtime_error("SceneBuilder: cannot write " + temporary);
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec)
        throw std::runtime_error("SceneBuilder: cannot rename " + temporary + " to " + path + ": " +
                                 ec.message());
}

}  // namespace vct
