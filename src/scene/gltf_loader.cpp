// The loader's entry points: reading the file with tinygltf, then converting the model
// (materials, the node hierarchy with its meshes, lights and cameras, the animations that
// move a camera) and checking the result. Also the one translation unit that compiles
// tinygltf and stb_image(_write).
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "scene/gltf_loader.h"

#include "scene/gltf_detail.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace vct {

namespace gltf_detail {

std::string label(const char* kind, int index, const std::string& name) {
    std::string s = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) s += " '" + name + "'";
    return s;
}


std::string str3(const glm::vec3& v) {
    std::ostringstream os;
    os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return os.str();
}

}  // namespace gltf_detail

namespace {

// tinygltf's messages on one line, for "<path>: <message>".
std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
    for (char& c : s)
        if (c == '\n') c = ';';
    return s;
}

}  // namespace

Scene sceneFromModel(const tinygltf::Model& model, const std::string& pathForMessages) {
    using namespace gltf_detail;
    LoadContext load(model, pathForMessages);
    Scene& scene = load.scene;
    scene.path = load.path;
    checkExtensions(load);
    convertMaterials(load);
    for (int root : rootNodes(model)) visitNode(load, root, glm::mat4(1.f), false, 0);
    if (load.degenerateCount > 0)
        scene.warnings.push_back("dropped " + std::to_string(load.degenerateCount) + " degenerate triangles");
    if (load.repairedNormalCount > 0)
        scene.warnings.push_back("replaced " + std::to_string(load.repairedNormalCount) +
                                 " zero-length normals by area-weighted face normals");
    if (scene.triangles.empty())
        load.fail("no triangles" + (load.degenerateCount
                                        ? " (all " + std::to_string(load.degenerateCount) + " were degenerate)"
                                        : std::string()));
    for (const glm::uvec3& t : scene.triangles)
        for (int k = 0; k < 3; ++k) scene.bounds.expand(scene.positions[t[k]]);
    boundInfiniteFarPlanes(load);
    addCameraAnimations(load);
    addLightAnimations(load);
    addMeshAnimations(load);
    findGeometryAnimations(load);
    return std::move(scene);
}

Scene loadScene(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw SceneError(path + ": file does not exist or is not a file");
    char magic[4] = {0, 0, 0, 0};
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw SceneError(path + ": cannot open file");
        in.read(magic, 4);
        if (in.gcount() == 0) throw SceneError(path + ": file is empty");
    }
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;
    tinygltf::TinyGLTF gltf;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                           : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!ok) {
        // A file whose geometry or images live in an extension vct lacks fails tinygltf's
        // checks of what is left; the extension is the cause to name.
        const std::string refused = gltf_detail::unimplementedRequiredExtensionInFile(path, binary);
        if (!refused.empty()) throw SceneError(path + ": " + refused);
        throw SceneError(path + ": " + (binary ? "GLB container: " : "glTF JSON: ") +
                         (err.empty() ? std::string("failed to parse") : trimmed(err)));
    }
    Scene scene = sceneFromModel(model, path);
    if (!warn.empty()) scene.warnings.push_back("tinygltf: " + trimmed(warn));
    return scene;
}

}  // namespace vct
