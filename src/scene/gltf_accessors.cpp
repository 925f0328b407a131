// glTF accessors: typed, strided, possibly sparse views of buffer bytes, read as doubles
// after checking that every byte they name lies inside its buffer view and buffer.
#include "scene/gltf_detail.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

namespace vct::gltf_detail {

namespace {

template <typename T>
T loadAs(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// 8- and 16-bit components may be normalized: unsigned c maps to c / max, signed c to
// max(c / max, -1) (glTF 2.0, 3.11).
template <typename T>
double normalizable(const unsigned char* p, bool normalized) {
    const T v = loadAs<T>(p);
    if (!normalized) return v;
    const double scale = std::numeric_limits<T>::max();
    return std::is_signed_v<T> ? std::max(v / scale, -1.0) : v / scale;
}

// One component as a double.
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return normalizable<int8_t>(p, normalized);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalizable<uint8_t>(p, normalized);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return normalizable<int16_t>(p, normalized);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalizable<uint16_t>(p, normalized);
        case TINYGLTF_COMPONENT_TYPE_INT: return loadAs<int32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return loadAs<uint32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return loadAs<float>(p);
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return loadAs<double>(p);
        default: return 0.0;
    }
}

// The bytes of a buffer view, after checking that it lies inside its buffer.
const unsigned char* bufferViewData(const LoadContext& load, int viewIndex, const std::string& where,
                                    size_t* byteLength) {
    const tinygltf::Model& model = load.model;
    if (viewIndex < 0 || viewIndex >= int(model.bufferViews.size()))
        load.fail(where + ": " + outOfRange("buffer view", viewIndex, model.bufferViews.size()));
    const tinygltf::BufferView& bv = model.bufferViews[size_t(viewIndex)];
    if (bv.buffer < 0 || bv.buffer >= int(model.buffers.size()))
        load.fail("buffer view " + std::to_string(viewIndex) + ": " +
                  outOfRange("buffer", bv.buffer, model.buffers.size()));
    const tinygltf::Buffer& buffer = model.buffers[size_t(bv.buffer)];
    if (bv.byteOffset + bv.byteLength > buffer.data.size())
        load.fail("buffer view " + std::to_string(viewIndex) + ": bytes [" + std::to_string(bv.byteOffset) + ", " +
                  std::to_string(bv.byteOffset + bv.byteLength) + ") exceed buffer " + std::to_string(bv.buffer) +
                  " of " + std::to_string(buffer.data.size()) + " bytes");
    *byteLength = bv.byteLength;
    return buffer.data.data() + bv.byteOffset;
}

void applySparse(const LoadContext& load, const tinygltf::Accessor& acc, const std::string& where, int components,
                 int componentSize, std::vector<double>& out) {
    const size_t count = size_t(std::max(acc.sparse.count, 0));
    const int indexSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.sparse.indices.componentType));
    if (indexSize <= 0 || !isIntegerComponent(acc.sparse.indices.componentType))
        load.fail(where + ": sparse indices have an invalid component type");
    size_t indexBytes = 0, valueBytes = 0;
    const unsigned char* indices =
        bufferViewData(load, acc.sparse.indices.bufferView, where + " sparse indices", &indexBytes);
    const unsigned char* values =
        bufferViewData(load, acc.sparse.values.bufferView, where + " sparse values", &valueBytes);
    const size_t elementSize = size_t(componentSize) * size_t(components);
    if (size_t(acc.sparse.indices.byteOffset) + count * size_t(indexSize) > indexBytes ||
        size_t(acc.sparse.values.byteOffset) + count * elementSize > valueBytes)
        load.fail(where + ": sparse data exceed their buffer views");
    for (size_t k = 0; k < count; ++k) {
        const double i = readComponent(indices + size_t(acc.sparse.indices.byteOffset) + k * size_t(indexSize),
                                       acc.sparse.indices.componentType, false);
        if (i < 0 || i >= double(acc.count)) load.fail(where + ": " + outOfRange("sparse index", size_t(i), acc.count));
        for (int c = 0; c < components; ++c)
            out[size_t(i) * size_t(components) + size_t(c)] =
                readComponent(values + size_t(acc.sparse.values.byteOffset) + k * elementSize +
                                  size_t(c) * size_t(componentSize),
                              acc.componentType, acc.normalized);
    }
}

}  // namespace

std::string accessorLabel(int index, const std::string& ctx) {
    return "accessor " + std::to_string(index) + " (" + ctx + ")";
}

bool isIntegerComponent(int componentType) {
    return componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && componentType != TINYGLTF_COMPONENT_TYPE_DOUBLE;
}

std::vector<double> readAccessor(const LoadContext& load, int index, const std::string& ctx, int components,
                                 size_t* countOut, int* componentTypeOut) {
    const tinygltf::Model& model = load.model;
    if (index < 0 || index >= int(model.accessors.size()))
        load.fail(ctx + ": " + outOfRange("accessor", index, model.accessors.size()));
    const tinygltf::Accessor& acc = model.accessors[size_t(index)];
    const std::string where = accessorLabel(index, ctx);
    const int n = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
    if (n != components)
        load.fail(where + ": has " + std::to_string(n) + " components per element, expected " +
                  std::to_string(components));
    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
    if (componentSize <= 0) load.fail(where + ": unknown component type " + std::to_string(acc.componentType));
    if (acc.count > (size_t(1) << 31)) load.fail(where + ": count " + std::to_string(acc.count) + " is too large");
    if (componentTypeOut) *componentTypeOut = acc.componentType;
    *countOut = acc.count;

    std::vector<double> out(acc.count * size_t(components), 0.0);
    if (acc.bufferView >= 0) {
        size_t byteLength = 0;
        const unsigned char* data = bufferViewData(load, acc.bufferView, where, &byteLength);
        const tinygltf::BufferView& bv = model.bufferViews[size_t(acc.bufferView)];
        const int stride = acc.ByteStride(bv);
        if (stride <= 0)
            load.fail(where + ": invalid byteStride " + std::to_string(bv.byteStride) + " of buffer view " +
                      std::to_string(acc.bufferView));
        const size_t elementSize = size_t(componentSize) * size_t(components);
        if (acc.count > 0) {
            const size_t end = acc.byteOffset + size_t(stride) * (acc.count - 1) + elementSize;
            if (end > byteLength)
                load.fail(where + ": needs bytes [" + std::to_string(acc.byteOffset) + ", " + std::to_string(end) +
                          ") of buffer view " + std::to_string(acc.bufferView) + ", which has " +
                          std::to_string(byteLength) + " bytes");
        }
        for (size_t i = 0; i < acc.count; ++i) {
            const unsigned char* e = data + acc.byteOffset + i * size_t(stride);
            for (int c = 0; c < components; ++c)
                out[i * size_t(components) + size_t(c)] =
                    readComponent(e + size_t(c) * size_t(componentSize), acc.componentType, acc.normalized);
        }
    }
    if (acc.sparse.isSparse) applySparse(load, acc, where, components, componentSize, out);
    return out;
}

std::vector<glm::vec3> readVec3(const LoadContext& load, int accessor, const std::string& ctx) {
    size_t count = 0;
    std::vector<double> v = readAccessor(load, accessor, ctx, 3, &count);
    std::vector<glm::vec3> out(count);
    for (size_t i = 0; i < count; ++i) {
        out[i] = glm::vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
        if (!finite3(out[i]))
            load.fail(accessorLabel(accessor, ctx) + ": element " + std::to_string(i) + " is not finite " +
                      str3(out[i]));
    }
    return out;
}

std::vector<glm::vec4> readColors(const LoadContext& load, int accessor, const std::string& ctx) {
    const tinygltf::Model& model = load.model;
    if (accessor < 0 || accessor >= int(model.accessors.size()))
        load.fail(ctx + ": " + outOfRange("accessor", accessor, model.accessors.size()));
    const tinygltf::Accessor& acc = model.accessors[size_t(accessor)];
    const std::string where = accessorLabel(accessor, ctx);
    const int components = acc.type == TINYGLTF_TYPE_VEC3 ? 3 : acc.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
    if (components == 0) load.fail(where + ": a vertex colour must be VEC3 or VEC4");
    const bool normalizedInteger = acc.normalized && (acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                      acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger)
        load.fail(where + ": a vertex colour must be float, or normalized unsigned byte or short (component type " +
                  std::to_string(acc.componentType) + (acc.normalized ? ", normalized" : "") + ")");
    size_t count = 0;
    const std::vector<double> v = readAccessor(load, accessor, ctx, components, &count);
    std::vector<glm::vec4> out(count, glm::vec4(1.f));
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < components; ++c) out[i][c] = float(v[i * size_t(components) + size_t(c)]);
        if (!finite3(glm::vec3(out[i])) || !std::isfinite(out[i].a))
            load.fail(where + ": element " + std::to_string(i) + " is not finite");
    }
    return out;
}

}  // namespace vct::gltf_detail
