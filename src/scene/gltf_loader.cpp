// The one translation unit that compiles tinygltf and stb_image(_write).
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "scene/gltf_loader.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <sstream>

namespace vct {
namespace {

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
    for (char& c : s)
        if (c == '\n') c = ';';
    return s;
}

std::string label(const char* kind, int index, const std::string& name) {
    std::string s = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) s += " '" + name + "'";
    return s;
}

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string str3(const glm::vec3& v) {
    std::ostringstream os;
    os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return os.str();
}

const char* modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

// One component as a double; normalized integers map to [0,1] / [-1,1] (glTF 2.0, 3.11).
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            uint8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_INT: {
            int32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: {
            double v;
            std::memcpy(&v, p, 8);
            return v;
        }
        default: return 0.0;
    }
}

bool isIntegerComponent(int componentType) {
    return componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && componentType != TINYGLTF_COMPONENT_TYPE_DOUBLE;
}

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
        r = glm::normalize(
            glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
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

struct Loader {
    const tinygltf::Model& model;
    std::string path;
    Scene scene;
    std::vector<int> sceneTextureFromGltf;                             // -1 = not converted yet
    std::map<std::tuple<int, bool, bool>, int> sceneTextureFromImage;  // (image, repeatS, repeatT) -> texture
    int defaultMaterial = -1;
    size_t degenerateCount = 0;
    size_t repairedNormalCount = 0;
    std::vector<size_t> camerasWithInfiniteFar;

    Loader(const tinygltf::Model& m, const std::string& p) : model(m), path(p) {}

    [[noreturn]] void fail(const std::string& what) const { throw SceneError(path + ": " + what); }

    // Reads accessor `index` as count x `components` doubles (sparse substitution applied).
    std::vector<double> readAccessor(int index, const std::string& ctx, int components, size_t* countOut,
                                     int* componentTypeOut = nullptr) const {
        const int accessorCount = int(model.accessors.size());
        if (index < 0 || index >= accessorCount)
            fail(ctx + ": accessor " + std::to_string(index) + " out of range [0, " +
                 std::to_string(accessorCount) + ")");
        const tinygltf::Accessor& acc = model.accessors[size_t(index)];
        const std::string where = "accessor " + std::to_string(index) + " (" + ctx + ")";
        const int n = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
        if (n != components)
            fail(where + ": has " + std::to_string(n) + " components per element, expected " +
                 std::to_string(components));
        const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
        if (componentSize <= 0) fail(where + ": unknown component type " + std::to_string(acc.componentType));
        if (acc.count > (size_t(1) << 31))
            fail(where + ": count " + std::to_string(acc.count) + " is too large");
        if (componentTypeOut) *componentTypeOut = acc.componentType;
        *countOut = acc.count;

        std::vector<double> out(acc.count * size_t(components), 0.0);
        if (acc.bufferView >= 0) {
            size_t byteLength = 0;
            const unsigned char* data = bufferViewData(acc.bufferView, where, &byteLength);
            const tinygltf::BufferView& bv = model.bufferViews[size_t(acc.bufferView)];
            const int stride = acc.ByteStride(bv);
            if (stride <= 0)
                fail(where + ": invalid byteStride " + std::to_string(bv.byteStride) + " of buffer view " +
                     std::to_string(acc.bufferView));
            const size_t elementSize = size_t(componentSize) * size_t(components);
            if (acc.count > 0) {
                const size_t end = acc.byteOffset + size_t(stride) * (acc.count - 1) + elementSize;
                if (end > byteLength)
                    fail(where + ": needs bytes [" + std::to_string(acc.byteOffset) + ", " +
                         std::to_string(end) + ") of buffer view " + std::to_string(acc.bufferView) +
                         ", which has " + std::to_string(byteLength) + " bytes");
            }
            for (size_t i = 0; i < acc.count; ++i) {
                const unsigned char* e = data + acc.byteOffset + i * size_t(stride);
                for (int c = 0; c < components; ++c)
                    out[i * size_t(components) + size_t(c)] = readComponent(
                        e + size_t(c) * size_t(componentSize), acc.componentType, acc.normalized);
            }
        }
        if (acc.sparse.isSparse) applySparse(acc, where, components, componentSize, out);
        return out;
    }

    void applySparse(const tinygltf::Accessor& acc, const std::string& where, int components,
                     int componentSize, std::vector<double>& out) const {
        const size_t count = size_t(std::max(acc.sparse.count, 0));
        const int indexSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.sparse.indices.componentType));
        if (indexSize <= 0 || !isIntegerComponent(acc.sparse.indices.componentType))
            fail(where + ": sparse indices have an invalid component type");
        size_t indexBytes = 0, valueBytes = 0;
        const unsigned char* indices =
            bufferViewData(acc.sparse.indices.bufferView, where + " sparse indices", &indexBytes);
        const unsigned char* values =
            bufferViewData(acc.sparse.values.bufferView, where + " sparse values", &valueBytes);
        const size_t elementSize = size_t(componentSize) * size_t(components);
        if (size_t(acc.sparse.indices.byteOffset) + count * size_t(indexSize) > indexBytes ||
            size_t(acc.sparse.values.byteOffset) + count * elementSize > valueBytes)
            fail(where + ": sparse data exceed their buffer views");
        for (size_t k = 0; k < count; ++k) {
            const double i =
                readComponent(indices + size_t(acc.sparse.indices.byteOffset) + k * size_t(indexSize),
                              acc.sparse.indices.componentType, false);
            if (i < 0 || i >= double(acc.count))
                fail(where + ": sparse index " + std::to_string(size_t(i)) + " out of range [0, " +
                     std::to_string(acc.count) + ")");
            for (int c = 0; c < components; ++c)
                out[size_t(i) * size_t(components) + size_t(c)] =
                    readComponent(values + size_t(acc.sparse.values.byteOffset) + k * elementSize +
                                      size_t(c) * size_t(componentSize),
                                  acc.componentType, acc.normalized);
        }
    }

    // The bytes of a buffer view, after checking that it lies inside its buffer.
    const unsigned char* bufferViewData(int viewIndex, const std::string& where, size_t* byteLength) const {
        const int viewCount = int(model.bufferViews.size());
        if (viewIndex < 0 || viewIndex >= viewCount)
            fail(where + ": buffer view " + std::to_string(viewIndex) + " out of range [0, " +
                 std::to_string(viewCount) + ")");
        const tinygltf::BufferView& bv = model.bufferViews[size_t(viewIndex)];
        const int bufferCount = int(model.buffers.size());
        if (bv.buffer < 0 || bv.buffer >= bufferCount)
            fail("buffer view " + std::to_string(viewIndex) + ": buffer " + std::to_string(bv.buffer) +
                 " out of range [0, " + std::to_string(bufferCount) + ")");
        const tinygltf::Buffer& buffer = model.buffers[size_t(bv.buffer)];
        if (bv.byteOffset + bv.byteLength > buffer.data.size())
            fail("buffer view " + std::to_string(viewIndex) + ": bytes [" + std::to_string(bv.byteOffset) +
                 ", " + std::to_string(bv.byteOffset + bv.byteLength) + ") exceed buffer " +
                 std::to_string(bv.buffer) + " of " + std::to_string(buffer.data.size()) + " bytes");
        *byteLength = bv.byteLength;
        return buffer.data.data() + bv.byteOffset;
    }

    // Reads a VEC3 attribute and rejects NaN or infinite elements.
    std::vector<glm::vec3> readVec3(int accessor, const std::string& ctx) const {
        size_t count = 0;
        std::vector<double> v = readAccessor(accessor, ctx, 3, &count);
        std::vector<glm::vec3> out(count);
        for (size_t i = 0; i < count; ++i) {
            out[i] = glm::vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
            if (!finite3(out[i]))
                fail("accessor " + std::to_string(accessor) + " (" + ctx + "): element " + std::to_string(i) +
                     " is not finite " + str3(out[i]));
        }
        return out;
    }

    int textureFor(int gltfTexture, const std::string& ctx) {
        const int count = int(model.textures.size());
        if (gltfTexture < 0 || gltfTexture >= count)
            fail(ctx + ": texture " + std::to_string(gltfTexture) + " out of range [0, " +
                 std::to_string(count) + ")");
        if (sceneTextureFromGltf.empty()) sceneTextureFromGltf.assign(size_t(count), -1);
        int& mapped = sceneTextureFromGltf[size_t(gltfTexture)];
        if (mapped >= 0) return mapped;

        const tinygltf::Texture& tex = model.textures[size_t(gltfTexture)];
        const std::string where = label("texture", gltfTexture, tex.name);
        bool repeatS = true, repeatT = true;
        if (tex.sampler >= 0) {
            if (tex.sampler >= int(model.samplers.size()))
                fail(where + ": sampler " + std::to_string(tex.sampler) + " out of range [0, " +
                     std::to_string(model.samplers.size()) + ")");
            const tinygltf::Sampler& s = model.samplers[size_t(tex.sampler)];
            // MIRRORED_REPEAT is read as REPEAT: the Texture struct has no mirror mode.
            repeatS = s.wrapS != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
            repeatT = s.wrapT != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        }
        // Many glTF textures often share one image (Lost Empire: 45 textures, one atlas): convert it once.
        const auto shared = sceneTextureFromImage.find({tex.source, repeatS, repeatT});
        if (shared != sceneTextureFromImage.end()) return mapped = shared->second;
        const int imageCount = int(model.images.size());
        if (tex.source < 0 || tex.source >= imageCount)
            fail(where + ": image " + std::to_string(tex.source) + " out of range [0, " +
                 std::to_string(imageCount) + ")");
        const tinygltf::Image& image = model.images[size_t(tex.source)];
        const std::string imageWhere =
            label("image", tex.source, image.name.empty() ? image.uri : image.name);
        const int comps = image.component;
        const int bytesPerComp = image.bits == 16 ? 2 : 1;
        if (image.width <= 0 || image.height <= 0 || comps < 1 || comps > 4 ||
            (image.bits != 8 && image.bits != 16) ||
            image.image.size() < size_t(image.width) * size_t(image.height) * size_t(comps * bytesPerComp))
            fail(imageWhere + ": not decoded (missing file or unsupported format)");

        Texture out;
        out.name = image.name.empty() ? (image.uri.empty() ? tex.name : image.uri) : image.name;
        out.width = image.width;
        out.height = image.height;
        out.rgba = rgba8FromImage(image);
        out.repeatS = repeatS;
        out.repeatT = repeatT;
        mapped = int(scene.textures.size());
        sceneTextureFromImage[{tex.source, repeatS, repeatT}] = mapped;
        scene.textures.push_back(std::move(out));
        return mapped;
    }

    void convertMaterials() {
        for (size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& m = model.materials[i];
            const std::string where = label("material", int(i), m.name);
            Material out;
            out.name = m.name.empty() ? "material" + std::to_string(i) : m.name;
            const std::vector<double>& bc = m.pbrMetallicRoughness.baseColorFactor;
            if (bc.size() == 4)
                out.baseColorFactor = glm::vec4(float(bc[0]), float(bc[1]), float(bc[2]), float(bc[3]));
            if (m.emissiveFactor.size() == 3)
                out.emissiveFactor = glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]),
                                               float(m.emissiveFactor[2]));
            auto strength = m.extensions.find("KHR_materials_emissive_strength");
            if (strength != m.extensions.end() && strength->second.IsObject() &&
                strength->second.Has("emissiveStrength"))
                out.emissiveFactor *= float(strength->second.Get("emissiveStrength").GetNumberAsDouble());
            const glm::vec4 bcf = out.baseColorFactor;
            if (!finite3(glm::vec3(bcf)) || !std::isfinite(bcf.w) || !finite3(out.emissiveFactor))
                fail(where + ": base colour or emissive factor is not finite");
            if (glm::any(glm::lessThan(out.emissiveFactor, glm::vec3(0.f))))
                fail(where + ": negative emissive factor " + str3(out.emissiveFactor));
            if (m.pbrMetallicRoughness.baseColorTexture.index >= 0)
                out.baseColorTexture =
                    textureFor(m.pbrMetallicRoughness.baseColorTexture.index, where + " base colour");
            if (m.emissiveTexture.index >= 0)
                out.emissiveTexture = textureFor(m.emissiveTexture.index, where + " emissive");
            out.doubleSided = m.doubleSided;
            out.alphaMask = m.alphaMode == "MASK";
            out.alphaCutoff = float(m.alphaCutoff);
            if (!std::isfinite(out.alphaCutoff)) fail(where + ": alphaCutoff is not finite");
            scene.materials.push_back(std::move(out));
        }
    }

    uint32_t materialFor(int gltfMaterial, const std::string& ctx) {
        if (gltfMaterial >= int(model.materials.size()))
            fail(ctx + ": material " + std::to_string(gltfMaterial) + " out of range [0, " +
                 std::to_string(model.materials.size()) + ")");
        if (gltfMaterial >= 0) return uint32_t(gltfMaterial);
        if (defaultMaterial < 0) {  // glTF's default material: white, single-sided
            defaultMaterial = int(scene.materials.size());
            Material m;
            m.name = "default";
            scene.materials.push_back(m);
        }
        return uint32_t(defaultMaterial);
    }

    // Expands the primitive's index list (or 0..n-1) to triangles in file winding.
    std::vector<glm::uvec3> primitiveTriangles(const tinygltf::Primitive& prim, size_t vertexCount,
                                               const std::string& ctx) const {
        std::vector<uint32_t> idx;
        if (prim.indices >= 0) {
            size_t count = 0;
            int componentType = 0;
            std::vector<double> raw =
                readAccessor(prim.indices, ctx + ", indices", 1, &count, &componentType);
            const std::string where = "accessor " + std::to_string(prim.indices) + " (" + ctx + ", indices)";
            if (!isIntegerComponent(componentType)) fail(where + ": index components are not integers");
            idx.resize(count);
            for (size_t i = 0; i < count; ++i) {
                if (raw[i] < 0 || raw[i] >= double(vertexCount))
                    fail(where + ": index " + std::to_string(int64_t(raw[i])) + " out of range [0, " +
                         std::to_string(vertexCount) + ")");
                idx[i] = uint32_t(raw[i]);
            }
        } else {
            idx.resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) idx[i] = uint32_t(i);
        }
        std::vector<glm::uvec3> tris;
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < idx.size(); i += 3) tris.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // glTF 2.0 section 3.7.2.1: triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2}).
            for (size_t i = 0; i + 2 < idx.size(); ++i)
                tris.emplace_back(idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]);
        } else {  // fan: (v_{i+1}, v_{i+2}, v_0)
            for (size_t i = 0; i + 2 < idx.size(); ++i) tris.emplace_back(idx[i + 1], idx[i + 2], idx[0]);
        }
        return tris;
    }

    static bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        const glm::vec3 e1 = b - a, e2 = c - a;
        // Relative to the edge lengths, so the test is scale-free; a few ulps of the cross
        // product is rounding noise of collinear points, while slivers well above it stay.
        const float area2 = glm::length(glm::cross(e1, e2));
        return !(area2 > 4.f * FLT_EPSILON * glm::length(e1) * glm::length(e2));
    }

    void addPrimitive(int meshIndex, int primIndex, const glm::mat4& worldFromLocal, bool offscreen) {
        const tinygltf::Mesh& mesh = model.meshes[size_t(meshIndex)];
        const tinygltf::Primitive& prim = mesh.primitives[size_t(primIndex)];
        const std::string ctx =
            (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : "mesh '" + mesh.name + "'") +
            ", primitive " + std::to_string(primIndex);
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            fail(ctx + ": mode " + std::to_string(mode) + " (" + modeName(mode) +
                 ") is not supported; only TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN are");
        auto attr = [&](const char* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int posAccessor = attr("POSITION");
        if (posAccessor < 0) fail(ctx + ": has no POSITION attribute");
        const std::vector<glm::vec3> positions = readVec3(posAccessor, ctx + ", POSITION");
        std::vector<glm::vec3> normals;
        if (attr("NORMAL") >= 0) {
            normals = readVec3(attr("NORMAL"), ctx + ", NORMAL");
            if (normals.size() != positions.size())
                fail("accessor " + std::to_string(attr("NORMAL")) + " (" + ctx + ", NORMAL): count " +
                     std::to_string(normals.size()) + " differs from POSITION count " +
                     std::to_string(positions.size()));
        }
        std::vector<glm::vec2> uvs(positions.size(), glm::vec2(0.f));
        if (attr("TEXCOORD_0") >= 0) {
            size_t count = 0;
            std::vector<double> raw = readAccessor(attr("TEXCOORD_0"), ctx + ", TEXCOORD_0", 2, &count);
            if (count != positions.size())
                fail("accessor " + std::to_string(attr("TEXCOORD_0")) + " (" + ctx + ", TEXCOORD_0): count " +
                     std::to_string(count) + " differs from POSITION count " +
                     std::to_string(positions.size()));
            for (size_t i = 0; i < count; ++i) {
                uvs[i] = glm::vec2(float(raw[2 * i]), float(raw[2 * i + 1]));
                if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y))
                    fail("accessor " + std::to_string(attr("TEXCOORD_0")) + " (" + ctx +
                         ", TEXCOORD_0): element " + std::to_string(i) + " is not finite");
            }
        }
        const uint32_t material = materialFor(prim.material, ctx);
        const std::vector<glm::uvec3> tris = primitiveTriangles(prim, positions.size(), ctx);

        const glm::mat3 linear(worldFromLocal);
        const glm::mat3 normalFromLocal = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0.f;
        std::vector<glm::vec3> world(positions.size());
        for (size_t i = 0; i < positions.size(); ++i) {
            world[i] = glm::vec3(worldFromLocal * glm::vec4(positions[i], 1.f));
            if (!finite3(world[i]))
                fail(ctx + ": vertex " + std::to_string(i) + " is not finite in world space " +
                     str3(world[i]));
        }
        auto emitTriangle = [&](const glm::uvec3& t) {
            scene.triangles.push_back(t);
            scene.triangleMaterial.push_back(material);
            scene.triangleOffscreen.push_back(offscreen ? 1 : 0);
        };

        if (normals.empty()) {
            // Flat normals, as the glTF spec asks for primitives without NORMAL.
            for (glm::uvec3 t : tris) {
                if (mirrored) std::swap(t.y, t.z);
                const glm::vec3 a = world[t.x], b = world[t.y], c = world[t.z];
                if (degenerate(a, b, c)) {
                    ++degenerateCount;
                    continue;
                }
                const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
                const uint32_t base = uint32_t(scene.positions.size());
                for (uint32_t k = 0; k < 3; ++k) {
                    scene.positions.push_back(world[t[int(k)]]);
                    scene.normals.push_back(n);
                    scene.uvs.push_back(uvs[t[int(k)]]);
                }
                emitTriangle(glm::uvec3(base, base + 1, base + 2));
            }
            return;
        }

        const uint32_t base = uint32_t(scene.positions.size());
        std::vector<uint8_t> needsRepair(positions.size(), 0);
        for (size_t i = 0; i < positions.size(); ++i) {
            glm::vec3 n = normalFromLocal * normals[i];
            const float len = glm::length(n);
            if (len > 0.f && std::isfinite(len)) {
                n /= len;
            } else {
                needsRepair[i] = 1;
                n = glm::vec3(0.f);
            }
            scene.positions.push_back(world[i]);
            scene.normals.push_back(n);
            scene.uvs.push_back(uvs[i]);
        }
        bool anyRepair = false;
        for (glm::uvec3 t : tris) {
            if (mirrored) std::swap(t.y, t.z);
            const glm::vec3 a = world[t.x], b = world[t.y], c = world[t.z];
            if (degenerate(a, b, c)) {
                ++degenerateCount;
                continue;
            }
            emitTriangle(t + glm::uvec3(base));
            if (needsRepair[t.x] | needsRepair[t.y] | needsRepair[t.z]) {
                anyRepair = true;
                const glm::vec3 areaNormal = glm::cross(b - a, c - a);  // length = 2 x area: area weighting
                for (int k = 0; k < 3; ++k)
                    if (needsRepair[t[k]]) scene.normals[base + t[k]] += areaNormal;
            }
        }
        if (anyRepair || std::find(needsRepair.begin(), needsRepair.end(), 1) != needsRepair.end()) {
            for (size_t i = 0; i < positions.size(); ++i) {
                if (!needsRepair[i]) continue;
                glm::vec3& n = scene.normals[base + i];
                const float len = glm::length(n);
                n = len > 0.f ? n / len : glm::vec3(0.f, 1.f, 0.f);  // unreferenced vertex: any unit vector
                ++repairedNormalCount;
            }
        }
    }

    void addLight(const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal) {
        auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return;
        const std::string nodeWhere = label("node", nodeIndex, node.name);
        const int index = ext->second.Get("light").GetNumberAsInt();
        if (index < 0 || index >= int(model.lights.size()))
            fail(nodeWhere + ": light " + std::to_string(index) + " out of range [0, " +
                 std::to_string(model.lights.size()) + ")");
        const tinygltf::Light& l = model.lights[size_t(index)];
        const std::string where = label("light", index, l.name) + " (" + nodeWhere + ")";
        Light out;
        out.name =
            l.name.empty() ? (node.name.empty() ? "light" + std::to_string(index) : node.name) : l.name;
        if (l.type == "directional")
            out.type = LightType::Directional;
        else if (l.type == "point")
            out.type = LightType::Point;
        else if (l.type == "spot")
            out.type = LightType::Spot;
        else
            fail(where + ": unknown type '" + l.type + "'");
        glm::vec3 color(1.f);
        if (l.color.size() == 3) color = glm::vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
        out.color = color * float(l.intensity);
        out.range = float(l.range);
        out.innerConeAngle = float(l.spot.innerConeAngle);
        out.outerConeAngle = float(l.spot.outerConeAngle);
        out.position = glm::vec3(worldFromLocal * glm::vec4(0.f, 0.f, 0.f, 1.f));
        const glm::vec3 dir = glm::mat3(worldFromLocal) * glm::vec3(0.f, 0.f, -1.f);
        if (!finite3(color) || !std::isfinite(l.intensity) || !finite3(out.color) ||
            !std::isfinite(out.range) || !std::isfinite(out.innerConeAngle) ||
            !std::isfinite(out.outerConeAngle) || !finite3(out.position) || !finite3(dir))
            fail(where + ": colour, intensity, range, cone angles or transform not finite");
        if (l.intensity < 0 || glm::any(glm::lessThan(color, glm::vec3(0.f))) || out.range < 0.f)
            fail(where + ": negative colour, intensity or range");
        if (glm::length(dir) <= 0.f) fail(where + ": node transform collapses the light direction");
        out.direction = glm::normalize(dir);
        if (out.type == LightType::Spot &&
            !(out.innerConeAngle >= 0.f && out.innerConeAngle <= out.outerConeAngle &&
              out.outerConeAngle <= 1.5707964f))
            fail(where + ": spot cone angles must satisfy 0 <= inner <= outer <= pi/2");
        scene.lights.push_back(out);
    }

    void addCamera(const tinygltf::Node& node, int nodeIndex, const glm::mat4& worldFromLocal) {
        const std::string nodeWhere = label("node", nodeIndex, node.name);
        if (node.camera >= int(model.cameras.size()))
            fail(nodeWhere + ": camera " + std::to_string(node.camera) + " out of range [0, " +
                 std::to_string(model.cameras.size()) + ")");
        const tinygltf::Camera& c = model.cameras[size_t(node.camera)];
        const std::string where = label("camera", node.camera, c.name) + " (" + nodeWhere + ")";
        if (c.type != "perspective") {
            scene.warnings.push_back(where + ": " + c.type +
                                     " camera skipped (only perspective is supported)");
            return;
        }
        Camera out;
        out.name = !c.name.empty()      ? c.name
                   : !node.name.empty() ? node.name
                                        : "camera" + std::to_string(node.camera);
        const tinygltf::PerspectiveCamera& p = c.perspective;
        if (!std::isfinite(p.yfov) || !(p.yfov > 0.0) || !(p.yfov < M_PI))
            fail(where + ": yfov " + std::to_string(p.yfov) + " not in (0, pi)");
        if (!std::isfinite(p.znear) || !(p.znear > 0.0))
            fail(where + ": znear " + std::to_string(p.znear) + " not > 0");
        if (!std::isfinite(p.zfar) || (p.zfar != 0.0 && !(p.zfar > p.znear)))
            fail(where + ": zfar " + std::to_string(p.zfar) + " must be 0 (infinite) or > znear");
        out.yfov = float(p.yfov);
        out.znear = float(p.znear);
        out.zfar = float(p.zfar);
        const glm::mat3 linear(worldFromLocal);
        out.eye = glm::vec3(worldFromLocal * glm::vec4(0.f, 0.f, 0.f, 1.f));
        glm::vec3 forward = linear * glm::vec3(0.f, 0.f, -1.f);
        glm::vec3 up = linear * glm::vec3(0.f, 1.f, 0.f);
        if (!finite3(out.eye) || !finite3(forward) || !finite3(up))
            fail(where + ": node transform is not finite");
        if (!(glm::length(forward) > 0.f)) fail(where + ": node transform collapses the view direction");
        forward = glm::normalize(forward);
        up -= glm::dot(up, forward) * forward;  // re-orthogonalize under shear or non-uniform scale
        if (!(glm::length(up) > 0.f)) fail(where + ": node transform collapses the up direction");
        out.up = glm::normalize(up);
        out.target = out.eye + forward;
        if (p.zfar == 0.0) camerasWithInfiniteFar.push_back(scene.cameras.size());
        scene.cameras.push_back(out);
    }

    void visitNode(int nodeIndex, const glm::mat4& worldFromParent, bool parentOffscreen, size_t depth) {
        const int nodeCount = int(model.nodes.size());
        if (nodeIndex < 0 || nodeIndex >= nodeCount)
            fail("node " + std::to_string(nodeIndex) + " out of range [0, " + std::to_string(nodeCount) +
                 ")");
        if (depth > model.nodes.size())
            fail(label("node", nodeIndex, model.nodes[size_t(nodeIndex)].name) +
                 ": cycle in the node hierarchy");
        const tinygltf::Node& node = model.nodes[size_t(nodeIndex)];
        const std::string where = label("node", nodeIndex, node.name);
        if ((!node.matrix.empty() && node.matrix.size() != 16) ||
            (!node.rotation.empty() && node.rotation.size() != 4) ||
            (!node.scale.empty() && node.scale.size() != 3) ||
            (!node.translation.empty() && node.translation.size() != 3))
            fail(where + ": malformed matrix/translation/rotation/scale");
        for (const std::vector<double>* v : {&node.matrix, &node.rotation, &node.scale, &node.translation})
            for (double x : *v)
                if (!std::isfinite(x)) fail(where + ": transform has a non-finite value");
        const glm::mat4 worldFromLocal = worldFromParent * localFromNode(node);
        // Finite doubles can overflow the float matrix (a translation of 1e39): blame the node,
        // not the first vertex it moves.
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(worldFromLocal[c].x) || !std::isfinite(worldFromLocal[c].y) ||
                !std::isfinite(worldFromLocal[c].z) || !std::isfinite(worldFromLocal[c].w))
                fail(where + ": world transform is not finite in single precision");
        const bool offscreen = parentOffscreen || nodeIsOffscreen(node);

        if (node.mesh >= 0) {
            if (node.mesh >= int(model.meshes.size()))
                fail(where + ": mesh " + std::to_string(node.mesh) + " out of range [0, " +
                     std::to_string(model.meshes.size()) + ")");
            const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
            for (size_t p = 0; p < mesh.primitives.size(); ++p)
                addPrimitive(node.mesh, int(p), worldFromLocal, offscreen);
        }
        addLight(node, nodeIndex, worldFromLocal);
        if (node.camera >= 0) addCamera(node, nodeIndex, worldFromLocal);
        for (int child : node.children) visitNode(child, worldFromLocal, offscreen, depth + 1);
    }

    std::vector<int> rootNodes() const {
        if (!model.scenes.empty()) {
            const int s = model.defaultScene >= 0 && model.defaultScene < int(model.scenes.size())
                              ? model.defaultScene
                              : 0;
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

    Scene run() {
        scene.path = path;
        convertMaterials();
        for (int root : rootNodes()) visitNode(root, glm::mat4(1.f), false, 0);
        if (degenerateCount > 0)
            scene.warnings.push_back("dropped " + std::to_string(degenerateCount) + " degenerate triangles");
        if (repairedNormalCount > 0)
            scene.warnings.push_back("replaced " + std::to_string(repairedNormalCount) +
                                     " zero-length normals by area-weighted face normals");
        if (scene.triangles.empty())
            fail("no triangles" + (degenerateCount
                                       ? " (all " + std::to_string(degenerateCount) + " were degenerate)"
                                       : std::string()));
        for (const glm::uvec3& t : scene.triangles)
            for (int k = 0; k < 3; ++k) scene.bounds.expand(scene.positions[t[k]]);
        // A glTF zfar of 0 means an infinite far plane: give those cameras one that holds the scene.
        for (size_t i : camerasWithInfiniteFar) {
            Camera& c = scene.cameras[i];
            const float reach =
                glm::length(glm::abs(c.eye - scene.bounds.center()) + 0.5f * scene.bounds.extent());
            c.zfar = std::max(2.f * reach, 1000.f * c.znear);
        }
        return std::move(scene);
    }
};

}  // namespace

Scene sceneFromModel(const tinygltf::Model& model, const std::string& pathForMessages) {
    return Loader(model, pathForMessages).run();
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
    if (!ok)
        throw SceneError(path + ": " + (binary ? "GLB container: " : "glTF JSON: ") +
                         (err.empty() ? std::string("failed to parse") : trimmed(err)));
    Scene scene = sceneFromModel(model, path);
    if (!warn.empty()) scene.warnings.push_back("tinygltf: " + trimmed(warn));
    return scene;
}

}  // namespace vct
