// glTF materials and their textures: base colour and emission (with
// KHR_materials_emissive_strength), images converted to 8-bit RGBA once per image and
// wrap mode, and glTF's default material for primitives that name none.
#include "scene/gltf_detail.h"

#include <cmath>
#include <cstring>

namespace vct::gltf_detail {

namespace {

// The decoded image as 8-bit RGBA (grey replicated, missing alpha = 255, 16-bit rounded to 8).
std::vector<uint8_t> rgba8FromImage(const tinygltf::Image& image) {
    const size_t texels = size_t(image.width) * size_t(image.height);
    const int comps = image.component;
    const int bytesPerComp = image.bits == 16 ? 2 : 1;
    std::vector<uint8_t> rgba(texels * 4);
    if (comps == 4 && bytesPerComp == 1) {  // what tinygltf's default stb loader produces
        std::memcpy(rgba.data(), image.image.data(), texels * 4);
        return rgba;
    }
    for (size_t i = 0; i < texels; ++i) {
        uint8_t c[4] = {0, 0, 0, 255};
        for (int k = 0; k < comps; ++k) {
            const unsigned char* p =
                image.image.data() + (i * size_t(comps) + size_t(k)) * size_t(bytesPerComp);
            uint32_t v = p[0];
            if (bytesPerComp == 2) {
                uint16_t v16;
                std::memcpy(&v16, p, 2);
                v = (uint32_t(v16) * 255u + 32767u) / 65535u;
            }
            c[k] = uint8_t(v);
        }
        uint8_t* o = &rgba[4 * i];
        if (comps <= 2) {  // grey (+ alpha)
            o[0] = o[1] = o[2] = c[0];
            o[3] = comps == 2 ? c[1] : 255;
        } else {
            o[0] = c[0];
            o[1] = c[1];
            o[2] = c[2];
            o[3] = comps == 4 ? c[3] : 255;
        }
    }
    return rgba;
}

// A sampler's wrapS or wrapT: GL's enum, the three glTF allows.
TextureWrap textureWrap(const LoadContext& load, int mode, const std::string& where) {
    switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: break;
    }
    load.fail(where + ": " + std::to_string(mode) +
              " is not a wrap mode (10497 REPEAT, 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT)");
}

// The scene texture of glTF texture `gltfTexture`, converting it on first use.
int textureFor(LoadContext& load, int gltfTexture, const std::string& ctx) {
    const tinygltf::Model& model = load.model;
    const int count = int(model.textures.size());
    if (gltfTexture < 0 || gltfTexture >= count) load.fail(ctx + ": " + outOfRange("texture", gltfTexture, count));
    if (load.sceneTextureFromGltf.empty()) load.sceneTextureFromGltf.assign(size_t(count), -1);
    int& mapped = load.sceneTextureFromGltf[size_t(gltfTexture)];
    if (mapped >= 0) return mapped;

    const tinygltf::Texture& tex = model.textures[size_t(gltfTexture)];
    const std::string where = label("texture", gltfTexture, tex.name);
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    if (tex.sampler >= 0) {
        if (tex.sampler >= int(model.samplers.size()))
            load.fail(where + ": " + outOfRange("sampler", tex.sampler, model.samplers.size()));
        const tinygltf::Sampler& s = model.samplers[size_t(tex.sampler)];
        const std::string samplerWhere = label("sampler", tex.sampler, s.name);
        wrapS = textureWrap(load, s.wrapS, samplerWhere + " wrapS");
        wrapT = textureWrap(load, s.wrapT, samplerWhere + " wrapT");
    }
    // Many glTF textures often share one image (Lost Empire: 45 textures, one atlas): convert it once.
    const auto shared = load.sceneTextureFromImage.find({tex.source, int(wrapS), int(wrapT)});
    if (shared != load.sceneTextureFromImage.end()) return mapped = shared->second;
    const int imageCount = int(model.images.size());
    if (tex.source < 0 || tex.source >= imageCount)
        load.fail(where + ": " + outOfRange("image", tex.source, imageCount));
    const tinygltf::Image& image = model.images[size_t(tex.source)];
    const std::string imageWhere = label("image", tex.source, image.name.empty() ? image.uri : image.name);
    const int comps = image.component;
    const int bytesPerComp = image.bits == 16 ? 2 : 1;
    if (image.width <= 0 || image.height <= 0 || comps < 1 || comps > 4 || (image.bits != 8 && image.bits != 16) ||
        image.image.size() < size_t(image.width) * size_t(image.height) * size_t(comps * bytesPerComp))
        load.fail(imageWhere + ": not decoded (missing file or unsupported format)");

    Texture out;
    out.name = image.name.empty() ? (image.uri.empty() ? tex.name : image.uri) : image.name;
    out.width = image.width;
    out.height = image.height;
    out.rgba = rgba8FromImage(image);
    out.wrapS = wrapS;
    out.wrapT = wrapT;
    mapped = int(load.scene.textures.size());
    load.sceneTextureFromImage[{tex.source, int(wrapS), int(wrapT)}] = mapped;
    load.scene.textures.push_back(std::move(out));
    return mapped;
}

// Element k of a KHR_texture_transform member that must be `n` finite numbers.
glm::vec2 transformPair(const LoadContext& load, const tinygltf::Value& ext, const char* key, glm::vec2 fallback,
                        const std::string& where) {
    if (!ext.Has(key)) return fallback;
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        load.fail(where + ": KHR_texture_transform " + key + " must be two numbers");
    const glm::vec2 out(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
    if (!std::isfinite(out.x) || !std::isfinite(out.y))
        load.fail(where + ": KHR_texture_transform " + key + " is not finite");
    return out;
}

// The coordinates texture `info` reads: its texCoord, and KHR_texture_transform's offset,
// rotation (counter-clockwise in UV space), scale and texCoord override. As the extension
// defines them: u' = s_u u cos r + s_v v sin r + o_u, v' = -s_u u sin r + s_v v cos r + o_v.
UvMapping uvMappingOf(const LoadContext& load, const tinygltf::TextureInfo& info, const std::string& where) {
    UvMapping m;
    m.set = info.texCoord;
    const auto found = info.extensions.find("KHR_texture_transform");
    if (found != info.extensions.end() && found->second.IsObject()) {
        const tinygltf::Value& ext = found->second;
        const glm::vec2 offset = transformPair(load, ext, "offset", glm::vec2(0.f), where);
        const glm::vec2 scale = transformPair(load, ext, "scale", glm::vec2(1.f), where);
        float rotation = 0.f;
        if (ext.Has("rotation")) {
            if (!ext.Get("rotation").IsNumber()) load.fail(where + ": KHR_texture_transform rotation must be a number");
            rotation = float(ext.Get("rotation").GetNumberAsDouble());
            if (!std::isfinite(rotation)) load.fail(where + ": KHR_texture_transform rotation is not finite");
        }
        if (ext.Has("texCoord")) {
            if (!ext.Get("texCoord").IsInt()) load.fail(where + ": KHR_texture_transform texCoord must be an integer");
            m.set = ext.Get("texCoord").GetNumberAsInt();
        }
        const float c = std::cos(rotation), s = std::sin(rotation);
        m.transform = glm::mat3(glm::vec3(scale.x * c, -scale.x * s, 0.f), glm::vec3(scale.y * s, scale.y * c, 0.f),
                                glm::vec3(offset, 1.f));
    }
    if (m.set < 0) load.fail(where + ": texCoord " + std::to_string(m.set) + " is negative");
    return m;
}

}  // namespace

void convertMaterials(LoadContext& load) {
    const tinygltf::Model& model = load.model;
    std::vector<std::string> blended;  // materials whose alphaMode is BLEND
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        const std::string where = label("material", int(i), m.name);
        Material out;
        out.name = m.name.empty() ? "material" + std::to_string(i) : m.name;
        const std::vector<double>& bc = m.pbrMetallicRoughness.baseColorFactor;
        if (bc.size() == 4) out.baseColorFactor = glm::vec4(float(bc[0]), float(bc[1]), float(bc[2]), float(bc[3]));
        if (m.emissiveFactor.size() == 3)
            out.emissiveFactor =
                glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]), float(m.emissiveFactor[2]));
        auto strength = m.extensions.find("KHR_materials_emissive_strength");
        if (strength != m.extensions.end() && strength->second.IsObject() && strength->second.Has("emissiveStrength"))
            out.emissiveFactor *= float(strength->second.Get("emissiveStrength").GetNumberAsDouble());
        const glm::vec4 bcf = out.baseColorFactor;
        if (!finite3(glm::vec3(bcf)) || !std::isfinite(bcf.w) || !finite3(out.emissiveFactor))
            load.fail(where + ": base colour or emissive factor is not finite");
        if (glm::any(glm::lessThan(out.emissiveFactor, glm::vec3(0.f))))
            load.fail(where + ": negative emissive factor " + str3(out.emissiveFactor));
        if (m.pbrMetallicRoughness.baseColorTexture.index >= 0)
            out.baseColorTexture =
                textureFor(load, m.pbrMetallicRoughness.baseColorTexture.index, where + " base colour");
        if (m.emissiveTexture.index >= 0)
            out.emissiveTexture = textureFor(load, m.emissiveTexture.index, where + " emissive");
        // One set of UVs per vertex: the base colour's mapping (the alpha test reads it too),
        // else the emissive texture's.
        UvMapping uv;
        if (out.baseColorTexture >= 0) {
            uv = uvMappingOf(load, m.pbrMetallicRoughness.baseColorTexture, where + " base colour");
            if (out.emissiveTexture >= 0 && !(uvMappingOf(load, m.emissiveTexture, where + " emissive") == uv))
                load.scene.warnings.push_back(where +
                                              ": the emissive texture reads other texture coordinates than the base "
                                              "colour's (texCoord or KHR_texture_transform); both read the base colour's");
        } else if (out.emissiveTexture >= 0) {
            uv = uvMappingOf(load, m.emissiveTexture, where + " emissive");
        }
        load.materialUv.push_back(uv);
        out.doubleSided = m.doubleSided;
        out.alphaMask = m.alphaMode == "MASK";
        if (m.alphaMode == "BLEND") blended.push_back(where);
        out.alphaCutoff = float(m.alphaCutoff);
        if (!std::isfinite(out.alphaCutoff)) load.fail(where + ": alphaCutoff is not finite");
        load.scene.materials.push_back(std::move(out));
    }
    if (!blended.empty()) {
        // Said once for all of them: a scene of many glass panes would otherwise fill the log.
        std::string names;
        for (size_t i = 0; i < blended.size() && i < 4; ++i) names += (i ? ", " : "") + blended[i];
        if (blended.size() > 4) names += " and " + std::to_string(blended.size() - 4) + " more";
        load.scene.warnings.push_back(names + ": alphaMode BLEND is drawn opaque (vct renders no partial "
                                              "transparency: such surfaces occlude and reflect as opaque ones)");
    }
}

uint32_t materialFor(LoadContext& load, int gltfMaterial, const std::string& ctx) {
    if (gltfMaterial >= int(load.model.materials.size()))
        load.fail(ctx + ": " + outOfRange("material", gltfMaterial, load.model.materials.size()));
    if (gltfMaterial >= 0) return uint32_t(gltfMaterial);
    if (load.defaultMaterial < 0) {  // glTF's default material: white, single-sided
        load.defaultMaterial = int(load.scene.materials.size());
        Material m;
        m.name = "default";
        load.scene.materials.push_back(m);
    }
    return uint32_t(load.defaultMaterial);
}

}  // namespace vct::gltf_detail
