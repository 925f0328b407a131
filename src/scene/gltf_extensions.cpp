// The glTF extensions the loader implements, and what it does with the others: a file that
// requires one it lacks is refused by name (the glTF spec: a loader must not load an asset
// whose extensionsRequired it does not support, since the file renders wrongly without it:
// Draco or meshopt geometry, KTX2 textures, transforms of the texture coordinates); one it
// merely uses is loaded without it, with a warning naming what was left out.
#include "scene/gltf_detail.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

namespace vct::gltf_detail {

namespace {

// What the loader reads (each in the file named): KHR_lights_punctual
// (gltf_lights_cameras.cpp), KHR_materials_emissive_strength and KHR_texture_transform
// (gltf_materials.cpp), KHR_mesh_quantization (integer and normalized attributes,
// gltf_accessors.cpp).
const char* const kImplemented[] = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                    "KHR_mesh_quantization", "KHR_texture_transform"};

bool implemented(const std::string& name) {
    return std::any_of(std::begin(kImplemented), std::end(kImplemented),
                       [&](const char* e) { return name == e; });
}

std::string implementedList() {
    std::string s;
    for (const char* e : kImplemented) s += (s.empty() ? "" : ", ") + std::string(e);
    return s;
}

// The JSON text of a .gltf file, or of a GLB's first chunk; empty when the file is not
// readable as either (the caller then keeps tinygltf's own message).
std::string jsonText(const std::string& path, bool binary) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    if (!binary) return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    unsigned char header[20];
    if (!in.read(reinterpret_cast<char*>(header), sizeof(header))) return {};
    uint32_t chunkLength = 0;
    std::memcpy(&chunkLength, header + 12, 4);
    if (std::memcmp(header + 16, "JSON", 4) != 0 || std::streamoff(chunkLength) > size - 20) return {};
    std::string text(chunkLength, '\0');
    if (!in.read(text.data(), std::streamsize(chunkLength))) return {};
    return text;
}

}  // namespace

std::string unimplementedRequiredExtension(const std::vector<std::string>& required) {
    for (const std::string& e : required)
        if (!implemented(e))
            return "requires the glTF extension " + e + ", which vct does not implement (it implements " +
                   implementedList() + ")";
    return {};
}

std::string unimplementedRequiredExtensionInFile(const std::string& path, bool binary) {
    const nlohmann::json j = nlohmann::json::parse(jsonText(path, binary), nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || !j.contains("extensionsRequired") || !j["extensionsRequired"].is_array()) return {};
    std::vector<std::string> required;
    for (const nlohmann::json& e : j["extensionsRequired"])
        if (e.is_string()) required.push_back(e.get<std::string>());
    return unimplementedRequiredExtension(required);
}

void checkExtensions(LoadContext& load) {
    const std::string refused = unimplementedRequiredExtension(load.model.extensionsRequired);
    if (!refused.empty()) load.fail(refused);
    std::string ignored;
    for (const std::string& e : load.model.extensionsUsed)
        if (!implemented(e)) ignored += (ignored.empty() ? "" : ", ") + e;
    if (!ignored.empty())
        load.scene.warnings.push_back("loaded without the glTF extensions it uses but does not require: " + ignored);
}

}  // namespace vct::gltf_detail
