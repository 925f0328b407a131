// glTF mesh primitives to world-space triangles: index lists and strips/fans expanded,
// winding kept front-facing under mirroring transforms, zero-area triangles dropped, flat
// normals where the file has none and area-weighted ones where its normals are unusable.
#include "scene/gltf_detail.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace vct::gltf_detail {

namespace {

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

// Expands the primitive's index list (or 0..n-1) to triangles in file winding.
std::vector<glm::uvec3> primitiveTriangles(const LoadContext& load, const tinygltf::Primitive& prim,
                                           size_t vertexCount, const std::string& ctx) {
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
        size_t count = 0;
        int componentType = 0;
        std::vector<double> raw = readAccessor(load, prim.indices, ctx + ", indices", 1, &count, &componentType);
        const std::string where = accessorLabel(prim.indices, ctx + ", indices");
        if (!isIntegerComponent(componentType)) load.fail(where + ": index components are not integers");
        idx.resize(count);
        for (size_t i = 0; i < count; ++i) {
            if (raw[i] < 0 || raw[i] >= double(vertexCount))
                load.fail(where + ": " + outOfRange("index", int64_t(raw[i]), vertexCount));
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
        for (size_t i = 0; i + 2 < idx.size(); ++i) tris.emplace_back(idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]);
    } else {  // fan: (v_{i+1}, v_{i+2}, v_0)
        for (size_t i = 0; i + 2 < idx.size(); ++i) tris.emplace_back(idx[i + 1], idx[i + 2], idx[0]);
    }
    return tris;
}

bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    // Relative to the edge lengths, so the test is scale-free; a few ulps of the cross
    // product is rounding noise of collinear points, while slivers well above it stay.
    const float area2 = glm::length(glm::cross(e1, e2));
    return !(area2 > 4.f * FLT_EPSILON * glm::length(e1) * glm::length(e2));
}

// The triangles to emit: wound as seen in world space (a mirroring transform reverses the
// file's winding) and without the degenerate ones, which are counted.
std::vector<glm::uvec3> keptTriangles(const std::vector<glm::uvec3>& tris, const std::vector<glm::vec3>& world,
                                      bool mirrored, size_t& degenerateCount) {
    std::vector<glm::uvec3> kept;
    kept.reserve(tris.size());
    for (glm::uvec3 t : tris) {
        if (mirrored) std::swap(t.y, t.z);
        if (degenerate(world[t.x], world[t.y], world[t.z])) {
            ++degenerateCount;
            continue;
        }
        kept.push_back(t);
    }
    return kept;
}

}  // namespace

void addPrimitive(LoadContext& load, int meshIndex, int primIndex, const glm::mat4& worldFromLocal, bool offscreen) {
    const tinygltf::Mesh& mesh = load.model.meshes[size_t(meshIndex)];
    const tinygltf::Primitive& prim = mesh.primitives[size_t(primIndex)];
    const std::string ctx = (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : "mesh '" + mesh.name + "'") +
                            ", primitive " + std::to_string(primIndex);
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        load.fail(ctx + ": mode " + std::to_string(mode) + " (" + modeName(mode) +
                  ") is not supported; only TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN are");
    auto attr = [&](const char* name) {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    };
    const int posAccessor = attr("POSITION");
    if (posAccessor < 0) load.fail(ctx + ": has no POSITION attribute");
    const std::vector<glm::vec3> positions = readVec3(load, posAccessor, ctx + ", POSITION");
    auto checkCount = [&](const char* name, size_t count) {
        if (count != positions.size())
            load.fail(accessorLabel(attr(name), ctx + ", " + name) + ": count " + std::to_string(count) +
                      " differs from POSITION count " + std::to_string(positions.size()));
    };
    std::vector<glm::vec3> normals;
    if (attr("NORMAL") >= 0) {
        normals = readVec3(load, attr("NORMAL"), ctx + ", NORMAL");
        checkCount("NORMAL", normals.size());
    }
    const uint32_t material = materialFor(load, prim.material, ctx);
    // The texture coordinates the material's textures read, mapped as they read them (a
    // primitive without that attribute reads the mapped (0, 0) everywhere).
    const UvMapping mapping = prim.material >= 0 && size_t(prim.material) < load.materialUv.size()
                                  ? load.materialUv[size_t(prim.material)]
                                  : UvMapping{};
    const std::string uvName = "TEXCOORD_" + std::to_string(mapping.set);
    std::vector<glm::vec2> uvs(positions.size(), glm::vec2(mapping.transform[2]));
    if (attr(uvName.c_str()) >= 0) {
        size_t count = 0;
        std::vector<double> raw = readAccessor(load, attr(uvName.c_str()), ctx + ", " + uvName, 2, &count);
        checkCount(uvName.c_str(), count);
        for (size_t i = 0; i < count; ++i) {
            const glm::vec2 uv(float(raw[2 * i]), float(raw[2 * i + 1]));
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                load.fail(accessorLabel(attr(uvName.c_str()), ctx + ", " + uvName) + ": element " +
                          std::to_string(i) + " is not finite");
            uvs[i] = glm::vec2(mapping.transform * glm::vec3(uv, 1.f));
        }
    }
    // Vertex colours multiply the base colour and its alpha; only set 0 is read.
    std::vector<glm::vec4> colors;
    if (attr("COLOR_0") >= 0) {
        colors = readColors(load, attr("COLOR_0"), ctx + ", COLOR_0");
        checkCount("COLOR_0", colors.size());
    }
    const std::vector<glm::uvec3> tris = primitiveTriangles(load, prim, positions.size(), ctx);

    const glm::mat3 linear(worldFromLocal);
    const glm::mat3 normalFromLocal = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.f;
    std::vector<glm::vec3> world(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        world[i] = glm::vec3(worldFromLocal * glm::vec4(positions[i], 1.f));
        if (!finite3(world[i]))
            load.fail(ctx + ": vertex " + std::to_string(i) + " is not finite in world space " + str3(world[i]));
    }
    Scene& scene = load.scene;
    // Scene::colors stays empty until a primitive brings colours; from then on it holds one
    // per vertex, white for the primitives without.
    const bool keepsColors = !colors.empty() || !scene.colors.empty();
    if (keepsColors) scene.colors.resize(scene.positions.size(), glm::vec4(1.f));
    auto pushColor = [&](size_t vertex) {
        if (keepsColors) scene.colors.push_back(colors.empty() ? glm::vec4(1.f) : colors[vertex]);
    };
    auto emitTriangle = [&](const glm::uvec3& t) {
        scene.triangles.push_back(t);
        scene.triangleMaterial.push_back(material);
        scene.triangleOffscreen.push_back(offscreen ? 1 : 0);
    };
    const std::vector<glm::uvec3> kept = keptTriangles(tris, world, mirrored, load.degenerateCount);

    if (normals.empty()) {
        // Flat normals, as the glTF spec asks for primitives without NORMAL.
        for (const glm::uvec3& t : kept) {
            const glm::vec3 a = world[t.x], b = world[t.y], c = world[t.z];
            const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            const uint32_t base = uint32_t(scene.positions.size());
            for (uint32_t k = 0; k < 3; ++k) {
                scene.positions.push_back(world[t[int(k)]]);
                scene.normals.push_back(n);
                scene.uvs.push_back(uvs[t[int(k)]]);
                pushColor(t[int(k)]);
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
        pushColor(i);
    }
    bool anyRepair = false;
    for (const glm::uvec3& t : kept) {
        emitTriangle(t + glm::uvec3(base));
        if (needsRepair[t.x] | needsRepair[t.y] | needsRepair[t.z]) {
            anyRepair = true;
            const glm::vec3 a = world[t.x], b = world[t.y], c = world[t.z];
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
            ++load.repairedNormalCount;
        }
    }
}

}  // namespace vct::gltf_detail
