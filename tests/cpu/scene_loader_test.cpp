// glTF loader: error paths on malformed files written here, and geometry checked against hand
// computation (node transforms, normals, winding, lights and cameras under rotated nodes).
#include "scene/gltf_loader.h"
#include "scene/scene_builder.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using vct::Scene;
using vct::SceneError;

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const uint32_t v = (uint32_t(bytes[i]) << 16) | (uint32_t(bytes[i + 1]) << 8) | bytes[i + 2];
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i + 1 == bytes.size()) {
        const uint32_t v = uint32_t(bytes[i]) << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == bytes.size()) {
        const uint32_t v = (uint32_t(bytes[i]) << 16) | (uint32_t(bytes[i + 1]) << 8);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

template <typename T>
void append(std::vector<unsigned char>& buffer, const std::vector<T>& values) {
    const size_t at = buffer.size();
    buffer.resize(at + values.size() * sizeof(T));
    if (!values.empty()) std::memcpy(buffer.data() + at, values.data(), values.size() * sizeof(T));
    buffer.resize((buffer.size() + 3) & ~size_t(3), 0);
}

// A one-mesh glTF written by hand: mesh 'tri' with POSITION (accessor 0), optional NORMAL
// (accessor 1) and optional uint16 indices (the last accessor); nodes and extra top-level
// members are spliced in as JSON text.
struct HandGltf {
    std::vector<float> positions;   // xyz per vertex
    std::vector<float> normals;     // empty = no NORMAL
    std::vector<uint16_t> indices;  // empty = non-indexed
    std::vector<std::vector<float>> texcoords;  // TEXCOORD_0, TEXCOORD_1, ...: uv per vertex
    // COLOR_0 when not empty: its raw bytes and its accessor's members besides bufferView and
    // count (e.g. "componentType": 5121, "normalized": true, "type": "VEC4"); count: colorCount,
    // or the vertex count when negative.
    std::vector<unsigned char> colorBytes;
    std::string colorAccessor;
    int colorCount = -1;
    int mode = 4;
    int positionCountOverride = -1;
    std::string nodes = R"([{"mesh": 0, "name": "n"}])";
    std::string rootNodes = "[0]";
    std::string extraTop;       // e.g. ", \"cameras\": [...]"
    std::string materialField;  // e.g. ", \"material\": 0"

    std::string json() const {
        std::vector<unsigned char> buffer;
        std::ostringstream views, accessors, attributes;
        auto addView = [&](size_t offset, size_t length, bool first) {
            views << (first ? "" : ",") << R"({"buffer": 0, "byteOffset": )" << offset
                  << R"(, "byteLength": )" << length << "}";
        };
        int view = 0;
        size_t at = buffer.size();
        append(buffer, positions);
        addView(at, positions.size() * 4, true);
        const int vertexCount =
            positionCountOverride >= 0 ? positionCountOverride : int(positions.size() / 3);
        accessors << R"({"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )" << vertexCount
                  << "}";
        attributes << R"("POSITION": 0)";
        ++view;
        int accessor = 1;
        if (!normals.empty()) {
            at = buffer.size();
            append(buffer, normals);
            addView(at, normals.size() * 4, false);
            accessors << R"(,{"bufferView": )" << view
                      << R"(, "componentType": 5126, "type": "VEC3", "count": )" << normals.size() / 3 << "}";
            attributes << R"(, "NORMAL": )" << accessor;
            ++view;
            ++accessor;
        }
        for (size_t set = 0; set < texcoords.size(); ++set) {
            at = buffer.size();
            append(buffer, texcoords[set]);
            addView(at, texcoords[set].size() * 4, false);
            accessors << R"(,{"bufferView": )" << view
                      << R"(, "componentType": 5126, "type": "VEC2", "count": )" << texcoords[set].size() / 2 << "}";
            attributes << R"(, "TEXCOORD_)" << set << R"(": )" << accessor;
            ++view;
            ++accessor;
        }
        if (!colorBytes.empty()) {
            at = buffer.size();
            append(buffer, colorBytes);
            addView(at, colorBytes.size(), false);
            accessors << R"(,{"bufferView": )" << view << ", " << colorAccessor
                      << R"(, "count": )" << (colorCount >= 0 ? colorCount : vertexCount) << "}";
            attributes << R"(, "COLOR_0": )" << accessor;
            ++view;
            ++accessor;
        }
        std::string indicesField;
        if (!indices.empty()) {
            at = buffer.size();
            append(buffer, indices);
            addView(at, indices.size() * 2, false);
            accessors << R"(,{"bufferView": )" << view
                      << R"(, "componentType": 5123, "type": "SCALAR", "count": )" << indices.size() << "}";
            indicesField = ", \"indices\": " + std::to_string(accessor);
        }
        std::ostringstream os;
        os << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" << rootNodes << "}],\n"
           << R"("nodes": )" << nodes << ",\n"
           << R"("meshes": [{"name": "tri", "primitives": [{"attributes": {)" << attributes.str() << "}"
           << indicesField << ", \"mode\": " << mode << materialField << "}]}],\n"
           << R"("accessors": [)" << accessors.str() << "],\n"
           << R"("bufferViews": [)" << views.str() << "],\n"
           << R"("buffers": [{"byteLength": )" << buffer.size()
           << R"(, "uri": "data:application/octet-stream;base64,)" << base64(buffer) << "\"}]" << extraTop
           << "}\n";
        return os.str();
    }
};

class SceneLoader : public ::testing::Test {
  protected:
    void SetUp() override {
        static int counter = 0;
        dir = fs::temp_directory_path() /
              ("vct_scene_loader_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const std::string path = (dir / name).string();
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    // Runs loadScene and returns the SceneError message ("" when it did not throw).
    static std::string loadError(const std::string& path) {
        try {
            vct::loadScene(path);
        } catch (const SceneError& e) { return e.what(); }
        return "";
    }
    fs::path dir;
};

// A triangle in the z = 0 plane, counter-clockwise seen from +Z.
const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

#define EXPECT_CONTAINS(haystack, needle) \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << "message: " << (haystack)

}  // namespace

TEST_F(SceneLoader, NonexistentFileNamesTheFile) {
    const std::string msg = loadError((dir / "does_not_exist.gltf").string());
    EXPECT_CONTAINS(msg, "does_not_exist.gltf");
    EXPECT_CONTAINS(msg, "does not exist");
}

TEST_F(SceneLoader, TruncatedGlbIsRejected) {
    vct::SceneBuilder b("t");
    b.addBox("box", glm::vec3(0.f), glm::vec3(1.f), b.addMaterial("m", glm::vec3(0.5f)));
    const std::string full = (dir / "full.glb").string();
    b.write(full);
    ASSERT_EQ(vct::loadScene(full).triangleCount(), 12u);  // the intact file loads
    std::ifstream in(full, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string msg = loadError(write("cut.glb", bytes.substr(0, bytes.size() / 2)));
    EXPECT_CONTAINS(msg, "cut.glb");
    EXPECT_CONTAINS(msg, "GLB");
}

TEST_F(SceneLoader, InvalidJsonIsRejected) {
    const std::string msg = loadError(write("broken.gltf", R"({"asset": {"version": "2.0"}, "nodes": [)"));
    EXPECT_CONTAINS(msg, "broken.gltf");
    EXPECT_CONTAINS(msg, "JSON");
}

TEST_F(SceneLoader, MissingBufferFileIsNamed) {
    HandGltf g;
    g.positions = kTriangle;
    std::string text = g.json();
    const size_t uri = text.find("data:application");
    text.replace(uri, text.find('"', uri) - uri, "missing_geometry.bin");
    const std::string msg = loadError(write("nobuf.gltf", text));
    EXPECT_CONTAINS(msg, "nobuf.gltf");
    EXPECT_CONTAINS(msg, "missing_geometry.bin");
}

TEST_F(SceneLoader, IndexOutOfRangeNamesAccessorMeshAndPrimitive) {
    HandGltf g;
    g.positions = kTriangle;
    g.indices = {0, 1, 77};
    const std::string msg = loadError(write("badindex.gltf", g.json()));
    EXPECT_CONTAINS(
        msg, "badindex.gltf: accessor 1 (mesh 'tri', primitive 0, indices): index 77 out of range [0, 3)");
}

TEST_F(SceneLoader, AccessorBeyondItsBufferViewIsRejected) {
    HandGltf g;
    g.positions = kTriangle;
    g.positionCountOverride = 10;  // 120 bytes from a 36-byte view
    const std::string msg = loadError(write("overrun.gltf", g.json()));
    EXPECT_CONTAINS(msg, "overrun.gltf");
    EXPECT_CONTAINS(msg, "accessor 0 (mesh 'tri', primitive 0, POSITION)");
    EXPECT_CONTAINS(msg, "buffer view 0");
}

TEST_F(SceneLoader, NaNPositionIsRejected) {
    HandGltf g;
    g.positions = kTriangle;
    g.positions[4] = std::numeric_limits<float>::quiet_NaN();
    const std::string msg = loadError(write("nan.gltf", g.json()));
    EXPECT_CONTAINS(msg, "nan.gltf");
    EXPECT_CONTAINS(msg, "POSITION");
    EXPECT_CONTAINS(msg, "element 1 is not finite");
}

TEST_F(SceneLoader, InfiniteNormalIsRejected) {
    HandGltf g;
    g.positions = kTriangle;
    g.normals = {0, 0, 1, 0, 0, 1, 0, 0, std::numeric_limits<float>::infinity()};
    const std::string msg = loadError(write("infnormal.gltf", g.json()));
    EXPECT_CONTAINS(msg, "infnormal.gltf");
    EXPECT_CONTAINS(msg, "NORMAL): element 2 is not finite");
}

TEST_F(SceneLoader, LinesPrimitiveIsRejectedByName) {
    HandGltf g;
    g.positions = kTriangle;
    g.mode = 1;
    const std::string msg = loadError(write("lines.gltf", g.json()));
    EXPECT_CONTAINS(msg, "lines.gltf: mesh 'tri', primitive 0: mode 1 (LINES)");
}

TEST_F(SceneLoader, SceneWithoutTrianglesIsAnError) {
    HandGltf g;
    g.positions = kTriangle;
    g.rootNodes = "[]";  // the mesh exists but no node of the scene instances it
    const std::string msg = loadError(write("empty.gltf", g.json()));
    EXPECT_CONTAINS(msg, "empty.gltf: no triangles");
}

TEST_F(SceneLoader, NonFiniteLightAndCameraValuesAreRejected) {
    HandGltf g;
    g.positions = kTriangle;
    g.nodes = R"([{"mesh": 0}, {"name": "lamp", "extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    g.rootNodes = "[0, 1]";
    g.extraTop =
        R"(, "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 1e39}]}})";
    std::string msg = loadError(write("badlight.gltf", g.json()));
    EXPECT_CONTAINS(msg, "badlight.gltf: light 0 (node 1 'lamp')");

    g.nodes = R"([{"mesh": 0}, {"name": "cam", "camera": 0}])";
    g.extraTop = R"(, "cameras": [{"type": "perspective", "perspective": {"yfov": -1, "znear": 0.1}}])";
    msg = loadError(write("badcam.gltf", g.json()));
    EXPECT_CONTAINS(msg, "badcam.gltf: camera 0 (node 1 'cam'): yfov");
}

TEST_F(SceneLoader, DegenerateTrianglesAreDroppedAndCounted) {
    HandGltf g;
    // Vertices 0-3 span a unit square; 4 lies on the line through 0 and 1.
    g.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0};
    g.indices = {0, 1, 2, 0, 2, 3,  // two good triangles
                 0, 0, 1, 1, 2, 2,  // repeated indices
                 0, 1, 4};          // collinear
    const Scene s = vct::loadScene(write("degenerate.gltf", g.json()));
    EXPECT_EQ(s.triangleCount(), 2u);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], "dropped 3 degenerate triangles");
}

TEST_F(SceneLoader, MissingNormalsAreFlatFaceNormals) {
    HandGltf g;
    g.positions = {0.2f, 0.1f, 0.3f, 1.5f, -0.4f, 0.9f, -0.3f, 1.2f, 0.6f};
    const Scene s = vct::loadScene(write("nonormals.gltf", g.json()));
    ASSERT_EQ(s.triangleCount(), 1u);
    const glm::vec3 a(0.2f, 0.1f, 0.3f), b(1.5f, -0.4f, 0.9f), c(-0.3f, 1.2f, 0.6f);
    const glm::vec3 expected = glm::normalize(glm::cross(b - a, c - a));
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 n = s.normals[s.triangles[0][k]];
        EXPECT_NEAR(n.x, expected.x, 1e-6f);
        EXPECT_NEAR(n.y, expected.y, 1e-6f);
        EXPECT_NEAR(n.z, expected.z, 1e-6f);
    }
}

TEST_F(SceneLoader, NodeHierarchyTransformsPositions) {
    HandGltf g;
    g.positions = kTriangle;
    g.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    // parent: column-major matrix translating by (1, 0, 0); child: T (1,2,3), R 90 deg about +Y, S 2.
    const float s = std::sqrt(0.5f);
    std::ostringstream nodes;
    nodes << R"([{"name": "parent", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1], "children": [1]},)"
          << R"({"name": "child", "mesh": 0, "translation": [1, 2, 3], "rotation": [0, )" << s << ", 0, " << s
          << R"(], "scale": [2, 2, 2]}])";
    g.nodes = nodes.str();
    const Scene scene = vct::loadScene(write("hierarchy.gltf", g.json()));
    ASSERT_EQ(scene.triangleCount(), 1u);
    // By hand: scale 2, then 90 deg about Y maps (x, y, z) to (z, y, -x), then + (1,2,3) + (1,0,0).
    const glm::vec3 expected[3] = {{2, 2, 3}, {2, 2, 1}, {2, 4, 3}};
    const glm::vec3 expectedNormal(1, 0, 0);  // +Z rotated 90 deg about Y
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = scene.positions[scene.triangles[0][k]];
        const glm::vec3 n = scene.normals[scene.triangles[0][k]];
        EXPECT_NEAR(glm::length(p - expected[k]), 0.f, 1e-5f) << "vertex " << k;
        EXPECT_NEAR(glm::length(n - expectedNormal), 0.f, 1e-5f) << "normal " << k;
    }
    EXPECT_NEAR(glm::length(scene.bounds.min - glm::vec3(2, 2, 1)), 0.f, 1e-5f);
    EXPECT_NEAR(glm::length(scene.bounds.max - glm::vec3(2, 4, 3)), 0.f, 1e-5f);
}

TEST_F(SceneLoader, NonUniformScaleKeepsNormalsPerpendicular) {
    HandGltf g;
    // A triangle in the plane x + y = 1 with its true normal; scale (3, 1, 1) tilts that plane.
    g.positions = {1, 0, 0, 0, 1, 0, 1, 0, 1};
    const float r = std::sqrt(0.5f);
    g.normals = {r, r, 0, r, r, 0, r, r, 0};
    g.nodes = R"([{"mesh": 0, "scale": [3, 1, 1]}])";
    const Scene s = vct::loadScene(write("scaled.gltf", g.json()));
    ASSERT_EQ(s.triangleCount(), 1u);
    const glm::uvec3 t = s.triangles[0];
    const glm::vec3 e1 = s.positions[t.y] - s.positions[t.x], e2 = s.positions[t.z] - s.positions[t.x];
    const glm::vec3 n = s.normals[t.x];
    EXPECT_NEAR(glm::dot(n, e1), 0.f, 1e-5f);  // perpendicular to the transformed surface
    EXPECT_NEAR(glm::dot(n, e2), 0.f, 1e-5f);
    EXPECT_NEAR(glm::length(n), 1.f, 1e-5f);
    EXPECT_GT(n.x, 0.f);
    EXPECT_NEAR(n.x / n.y, 1.f / 3.f, 1e-5f);  // plane x/3 + y = 1 has normal (1/3, 1, 0)
}

TEST_F(SceneLoader, MirroringNodeFlipsWinding) {
    HandGltf g;
    g.positions = kTriangle;
    g.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    g.nodes = R"([{"mesh": 0, "scale": [1, 1, -1]}])";  // mirror z: the front face now looks down -Z
    const Scene s = vct::loadScene(write("mirror.gltf", g.json()));
    ASSERT_EQ(s.triangleCount(), 1u);
    const glm::vec3 geometric = s.geometricNormal(0);
    EXPECT_NEAR(geometric.z, -1.f, 1e-6f);
    EXPECT_NEAR(s.normals[s.triangles[0].x].z, -1.f, 1e-6f);  // shading and geometric normal agree
}

TEST_F(SceneLoader, StripAndFanBecomeConsistentlyWoundTriangles) {
    for (int mode : {5, 6}) {
        HandGltf g;
        // Strip order 0,1,2,3 and fan order 0,1,2,3 both cover the unit square facing +Z.
        g.positions = mode == 5 ? std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}
                                : std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        g.mode = mode;
        const Scene s = vct::loadScene(write("strip" + std::to_string(mode) + ".gltf", g.json()));
        ASSERT_EQ(s.triangleCount(), 2u) << "mode " << mode;
        float area = 0.f;
        for (size_t i = 0; i < 2; ++i) {
            EXPECT_NEAR(s.geometricNormal(i).z, 1.f, 1e-6f) << "mode " << mode << " triangle " << i;
            const glm::uvec3 t = s.triangles[i];
            area += 0.5f * glm::length(glm::cross(s.positions[t.y] - s.positions[t.x],
                                                  s.positions[t.z] - s.positions[t.x]));
        }
        EXPECT_NEAR(area, 1.f, 1e-6f) << "mode " << mode;
    }
}

TEST_F(SceneLoader, InterleavedStridedAndNormalizedAccessors) {
    // One view holding position+normal interleaved (stride 24), uvs as normalized UNSIGNED_BYTE
    // (padded to 4 bytes per element), indices as UNSIGNED_BYTE.
    std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1, 0, 2, 0, 0, 0, 1};
    std::vector<uint8_t> uvs = {0, 255, 0, 0, 128, 0, 0, 0, 255, 51, 0, 0};
    std::vector<uint8_t> indices = {0, 1, 2, 0};
    std::vector<unsigned char> buffer;
    append(buffer, interleaved);
    append(buffer, uvs);
    append(buffer, indices);
    std::ostringstream os;
    os << R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
        "accessors": [
          {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "type": "VEC3", "count": 3},
          {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "type": "VEC3", "count": 3},
          {"bufferView": 1, "componentType": 5121, "normalized": true, "type": "VEC2", "count": 3},
          {"bufferView": 2, "componentType": 5121, "type": "SCALAR", "count": 3}],
        "bufferViews": [
          {"buffer": 0, "byteOffset": 0, "byteLength": 72, "byteStride": 24},
          {"buffer": 0, "byteOffset": 72, "byteLength": 12, "byteStride": 4},
          {"buffer": 0, "byteOffset": 84, "byteLength": 3}],
        "buffers": [{"byteLength": )"
       << buffer.size() << R"(, "uri": "data:application/octet-stream;base64,)" << base64(buffer) << "\"}]}";
    const Scene s = vct::loadScene(write("strided.gltf", os.str()));
    ASSERT_EQ(s.triangleCount(), 1u);
    const glm::uvec3 t = s.triangles[0];
    EXPECT_EQ(s.positions[t.y], glm::vec3(2, 0, 0));
    EXPECT_EQ(s.positions[t.z], glm::vec3(0, 2, 0));
    EXPECT_EQ(s.normals[t.x], glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(s.uvs[t.x].y, 1.f);  // 255 / 255
    EXPECT_FLOAT_EQ(s.uvs[t.y].x, 128.f / 255.f);
    EXPECT_FLOAT_EQ(s.uvs[t.z].y, 51.f / 255.f);
}

TEST_F(SceneLoader, LightUnderRotatedNodePointsTheRightWay) {
    HandGltf g;
    g.positions = kTriangle;
    const float s = std::sqrt(0.5f);
    std::ostringstream nodes;
    // Parent at (1,0,0); child at (0,3,0) rotated -90 deg about X: its -Z axis maps to -Y (down).
    nodes << R"([{"mesh": 0}, {"translation": [1, 0, 0], "children": [2]},)"
          << R"({"name": "spot_node", "translation": [0, 3, 0], "rotation": [)" << -s << ", 0, 0, " << s
          << R"(], "extensions": {"KHR_lights_punctual": {"light": 0}}}])";
    g.nodes = nodes.str();
    g.rootNodes = "[0, 1]";
    g.extraTop = R"(, "extensions": {"KHR_lights_punctual": {"lights": [{"name": "spot", "type": "spot",
        "color": [1, 0.5, 0.25], "intensity": 8, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}}]}})";
    const Scene scene = vct::loadScene(write("light.gltf", g.json()));
    ASSERT_EQ(scene.lights.size(), 1u);
    const vct::Light& l = scene.lights[0];
    EXPECT_EQ(l.name, "spot");
    EXPECT_EQ(l.type, vct::LightType::Spot);
    EXPECT_NEAR(glm::length(l.position - glm::vec3(1, 3, 0)), 0.f, 1e-6f);
    EXPECT_NEAR(glm::length(l.direction - glm::vec3(0, -1, 0)), 0.f, 1e-6f);
    EXPECT_NEAR(glm::length(l.color - glm::vec3(8, 4, 2)), 0.f, 1e-6f);
    EXPECT_FLOAT_EQ(l.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(l.outerConeAngle, 0.5f);
}

TEST_F(SceneLoader, CameraFromNodeTransform) {
    HandGltf g;
    g.positions = kTriangle;
    // Rotated 180 deg about Y: the camera's -Z looks along +Z.
    g.nodes =
        R"([{"mesh": 0}, {"name": "cam_node", "camera": 0, "translation": [0, 1, -4], "rotation": [0, 1, 0, 0]}])";
    g.rootNodes = "[0, 1]";
    g.extraTop = R"(, "cameras": [{"name": "back", "type": "perspective",
        "perspective": {"yfov": 0.6, "znear": 0.2, "zfar": 40}}])";
    const Scene s = vct::loadScene(write("camera.gltf", g.json()));
    ASSERT_EQ(s.cameras.size(), 1u);
    const vct::Camera& c = s.cameras[0];
    EXPECT_EQ(c.name, "back");
    EXPECT_NEAR(glm::length(c.eye - glm::vec3(0, 1, -4)), 0.f, 1e-6f);
    EXPECT_NEAR(glm::length(c.target - glm::vec3(0, 1, -3)), 0.f, 1e-6f);
    EXPECT_NEAR(glm::length(c.up - glm::vec3(0, 1, 0)), 0.f, 1e-6f);
    EXPECT_FLOAT_EQ(c.yfov, 0.6f);
    EXPECT_FLOAT_EQ(c.znear, 0.2f);
    EXPECT_FLOAT_EQ(c.zfar, 40.f);
}

TEST_F(SceneLoader, OffscreenMarksByNameExtrasAndAncestry) {
    HandGltf g;
    g.positions = kTriangle;
    g.nodes = R"([{"mesh": 0, "name": "visible"}, {"mesh": 0, "name": "offscreen_roof"},
        {"mesh": 0, "name": "flagged", "extras": {"offscreen_occluder": true}},
        {"name": "offscreen_group", "children": [4]}, {"mesh": 0, "name": "grandchild"}])";
    g.rootNodes = "[0, 1, 2, 3]";
    const Scene s = vct::loadScene(write("offscreen.gltf", g.json()));
    ASSERT_EQ(s.triangleCount(), 4u);
    EXPECT_EQ(s.triangleOffscreen, (std::vector<uint8_t>{0, 1, 1, 1}));
}

TEST_F(SceneLoader, MaterialFactorsEmissiveStrengthAndTexture) {
    // A 2x2 RGB PNG referenced by uri, with a clamp-to-edge S wrap.
    const unsigned char texels[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
    ASSERT_NE(stbi_write_png((dir / "tex.png").string().c_str(), 2, 2, 3, texels, 6), 0);
    HandGltf g;
    g.positions = kTriangle;
    g.materialField = ", \"material\": 0";
    g.extraTop =
        R"(, "materials": [{"name": "glowing", "doubleSided": true, "alphaMode": "MASK", "alphaCutoff": 0.3,
        "emissiveFactor": [1, 0.5, 0], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}},
        "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1], "baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0, "sampler": 0}], "images": [{"uri": "tex.png"}],
        "samplers": [{"wrapS": 33071, "wrapT": 10497}])";
    const Scene s = vct::loadScene(write("material.gltf", g.json()));
    ASSERT_EQ(s.materials.size(), 1u);
    const vct::Material& m = s.materials[0];
    EXPECT_EQ(m.name, "glowing");
    EXPECT_TRUE(m.doubleSided);
    EXPECT_TRUE(m.alphaMask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(4, 2, 0));
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.f, 1.f));
    ASSERT_EQ(m.baseColorTexture, 0);
    ASSERT_EQ(s.textures.size(), 1u);
    const vct::Texture& t = s.textures[0];
    EXPECT_EQ(t.width, 2);
    EXPECT_EQ(t.height, 2);
    EXPECT_EQ(t.wrapS, vct::TextureWrap::ClampToEdge);
    EXPECT_EQ(t.wrapT, vct::TextureWrap::Repeat);
    ASSERT_EQ(t.rgba.size(), 16u);
    EXPECT_EQ(std::vector<uint8_t>(t.rgba.begin(), t.rgba.begin() + 4),
              (std::vector<uint8_t>{255, 0, 0, 255}));
    EXPECT_EQ(std::vector<uint8_t>(t.rgba.begin() + 12, t.rgba.end()),
              (std::vector<uint8_t>{10, 20, 30, 255}));
}

// extensionsRequired names what a file cannot be read without (Draco or meshopt geometry, KTX2
// images, transformed texture coordinates): a loader that lacks one must refuse the file.
TEST_F(SceneLoader, RequiredExtensionTheLoaderLacksIsRefusedByName) {
    HandGltf g;
    g.positions = kTriangle;
    g.extraTop = R"(, "extensionsUsed": ["EXT_meshopt_compression"], "extensionsRequired": ["EXT_meshopt_compression"])";
    const std::string path = write("meshopt.gltf", g.json());
    const std::string msg = loadError(path);
    EXPECT_CONTAINS(msg, path);
    EXPECT_CONTAINS(msg, "requires the glTF extension EXT_meshopt_compression");

    // Draco leaves the index accessor without a buffer view, which tinygltf rejects before the
    // loader sees the model: the message still names the extension, the cause.
    g.indices = {0, 1, 2};
    g.extraTop.clear();
    std::string text = g.json();
    const std::string indexView = R"({"bufferView": 1, "componentType": 5123)";
    ASSERT_NE(text.find(indexView), std::string::npos);
    text.replace(text.find(indexView), indexView.size(), R"({"componentType": 5123)");
    const std::string plain = loadError(write("plain_broken.gltf", text));
    EXPECT_CONTAINS(plain, "glTF JSON");  // tinygltf's own message: no extension involved
    g.extraTop = R"(, "extensionsUsed": ["KHR_draco_mesh_compression"],
        "extensionsRequired": ["KHR_draco_mesh_compression"])";
    text = g.json();
    text.replace(text.find(indexView), indexView.size(), R"({"componentType": 5123)");
    const std::string draco = loadError(write("draco.gltf", text));
    EXPECT_CONTAINS(draco, "requires the glTF extension KHR_draco_mesh_compression");
    // The same from a GLB container (the JSON chunk read on its own).
    vct::SceneBuilder b("glb");
    b.addMaterial("m", glm::vec3(0.5f));
    b.addTransformedBox("box", vct::NodeTransform{}, 0);
    tinygltf::Model model = b.build();
    model.extensionsRequired.push_back("KHR_texture_basisu");
    model.extensionsUsed.push_back("KHR_texture_basisu");
    const std::string glb = (dir / "basisu.glb").string();
    tinygltf::TinyGLTF().WriteGltfSceneToFile(&model, glb, true, true, false, true);
    EXPECT_CONTAINS(loadError(glb), "requires the glTF extension KHR_texture_basisu");
}

TEST_F(SceneLoader, RequiredExtensionsTheLoaderImplementsLoad) {
    HandGltf g;
    g.positions = kTriangle;
    g.extraTop = R"(, "extensionsRequired": ["KHR_lights_punctual", "KHR_materials_emissive_strength",
        "KHR_mesh_quantization", "KHR_texture_transform"],
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength",
        "KHR_mesh_quantization", "KHR_texture_transform"])";
    const Scene s = vct::loadScene(write("implemented.gltf", g.json()));
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST_F(SceneLoader, ExtensionsUsedButNotImplementedAreAWarning) {
    HandGltf g;
    g.positions = kTriangle;
    g.extraTop = R"(, "extensionsUsed": ["KHR_materials_transmission", "KHR_lights_punctual", "KHR_materials_ior"])";
    const Scene s = vct::loadScene(write("used.gltf", g.json()));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_CONTAINS(s.warnings[0], "KHR_materials_transmission, KHR_materials_ior");
    EXPECT_EQ(s.warnings[0].find("KHR_lights_punctual"), std::string::npos);
}

// KHR_texture_transform's own example (offset (0, 1), rotation 90 degrees, scale 0.5): "only
// the lower left quadrant of the source image, rotated clockwise 90 degrees". The unit
// triangle's corners (0, 0), (1, 0), (0, 1) land on (0, 1), (0, 0.5), (0.5, 1).
TEST_F(SceneLoader, TextureTransformMapsTheTextureCoordinates) {
    const unsigned char texel[3] = {200, 100, 50};
    ASSERT_NE(stbi_write_png((dir / "t.png").string().c_str(), 1, 1, 3, texel, 3), 0);
    HandGltf g;
    g.positions = kTriangle;
    g.texcoords = {{0, 0, 1, 0, 0, 1}};
    g.materialField = ", \"material\": 0";
    const std::string images = R"(, "textures": [{"source": 0}], "images": [{"uri": "t.png"}])";
    g.extraTop = R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
        {"KHR_texture_transform": {"offset": [0, 1], "rotation": 1.5707963267948966, "scale": [0.5, 0.5]}}}}}])" +
                 images;
    const Scene s = vct::loadScene(write("transform.gltf", g.json()));
    ASSERT_EQ(s.uvs.size(), 3u);
    const glm::vec2 expected[3] = {{0.f, 1.f}, {0.f, 0.5f}, {0.5f, 1.f}};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(s.uvs[size_t(i)].x, expected[i].x, 1e-6f) << "vertex " << i;
        EXPECT_NEAR(s.uvs[size_t(i)].y, expected[i].y, 1e-6f) << "vertex " << i;
    }

    // Scale acts before the rotation: (u, v) -> (2 v, -u / 2) + (0.25, 0.5) for a scale of
    // (0.5, 2) turned 90 degrees.
    g.extraTop = R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
        {"KHR_texture_transform": {"offset": [0.25, 0.5], "rotation": 1.5707963267948966, "scale": [0.5, 2]}}}}}])" +
                 images;
    const Scene t = vct::loadScene(write("transform2.gltf", g.json()));
    const glm::vec2 expected2[3] = {{0.25f, 0.5f}, {0.25f, 0.f}, {2.25f, 0.5f}};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(t.uvs[size_t(i)].x, expected2[i].x, 1e-6f) << "vertex " << i;
        EXPECT_NEAR(t.uvs[size_t(i)].y, expected2[i].y, 1e-6f) << "vertex " << i;
    }

    g.extraTop = R"(, "materials": [{"name": "bad", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
        "extensions": {"KHR_texture_transform": {"scale": [1, 2, 3]}}}}}])" + images;
    const std::string msg = loadError(write("bad_transform.gltf", g.json()));
    EXPECT_CONTAINS(msg, "material 0 'bad' base colour: KHR_texture_transform scale must be two numbers");
}

// A texture's texCoord picks the attribute set; KHR_texture_transform's texCoord overrides it.
TEST_F(SceneLoader, TexCoordPicksTheAttributeSet) {
    const unsigned char texel[3] = {200, 100, 50};
    ASSERT_NE(stbi_write_png((dir / "t.png").string().c_str(), 1, 1, 3, texel, 3), 0);
    HandGltf g;
    g.positions = kTriangle;
    g.texcoords = {{0, 0, 0, 0, 0, 0}, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}};
    g.materialField = ", \"material\": 0";
    const std::string images = R"(, "textures": [{"source": 0}], "images": [{"uri": "t.png"}])";
    g.extraTop = R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1}}}])" +
                 images;
    const Scene s = vct::loadScene(write("set1.gltf", g.json()));
    ASSERT_EQ(s.uvs.size(), 3u);
    EXPECT_EQ(s.uvs[2], glm::vec2(0.5f, 0.6f));
    g.extraTop = R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1,
        "extensions": {"KHR_texture_transform": {"texCoord": 0}}}}}])" + images;
    EXPECT_EQ(vct::loadScene(write("override.gltf", g.json())).uvs[2], glm::vec2(0.f));

    // An emissive texture that reads other coordinates than the base colour's is read with
    // the base colour's, and the loader says so.
    g.extraTop = R"(, "materials": [{"name": "two", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
        "texCoord": 1}}, "emissiveTexture": {"index": 0}}])" + images;
    const Scene two = vct::loadScene(write("two_sets.gltf", g.json()));
    EXPECT_EQ(two.uvs[2], glm::vec2(0.5f, 0.6f));
    ASSERT_EQ(two.warnings.size(), 1u);
    EXPECT_CONTAINS(two.warnings[0], "material 0 'two': the emissive texture reads other texture coordinates");
}

TEST_F(SceneLoader, SamplerWrapModesAreReadAndUnknownOnesRefused) {
    const unsigned char texel[3] = {200, 100, 50};
    ASSERT_NE(stbi_write_png((dir / "t.png").string().c_str(), 1, 1, 3, texel, 3), 0);
    HandGltf g;
    g.positions = kTriangle;
    g.materialField = ", \"material\": 0";
    auto withSampler = [&](const std::string& sampler) {
        g.extraTop = R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
            "textures": [{"source": 0, "sampler": 0}], "images": [{"uri": "t.png"}], "samplers": [)" +
                     sampler + "]";
        return g.json();
    };
    const Scene s = vct::loadScene(write("mirror.gltf", withSampler(R"({"wrapS": 33648, "wrapT": 33071})")));
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].wrapS, vct::TextureWrap::MirroredRepeat);
    EXPECT_EQ(s.textures[0].wrapT, vct::TextureWrap::ClampToEdge);
    EXPECT_EQ(vct::loadScene(write("default.gltf", withSampler("{}"))).textures[0].wrapS, vct::TextureWrap::Repeat);
    EXPECT_CONTAINS(loadError(write("bad.gltf", withSampler(R"({"name": "odd", "wrapT": 9729})"))),
                    "sampler 0 'odd' wrapT: 9729 is not a wrap mode");
}

TEST_F(SceneLoader, BlendedMaterialsAreDrawnOpaqueAndTheLoaderSaysSo) {
    HandGltf g;
    g.positions = kTriangle;
    g.materialField = ", \"material\": 1";
    g.extraTop = R"(, "materials": [{"name": "a", "alphaMode": "BLEND"}, {"name": "glass", "alphaMode": "BLEND",
        "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.2]}}, {"alphaMode": "OPAQUE"}])";
    const Scene s = vct::loadScene(write("blend.gltf", g.json()));
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_FALSE(s.materials[1].alphaMask);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_CONTAINS(s.warnings[0], "material 0 'a', material 1 'glass': alphaMode BLEND is drawn opaque");
}

// Raw bytes of `values` (floats or unsigned integers) for HandGltf::colorBytes.
template <typename T>
std::vector<unsigned char> bytesOf(const std::vector<T>& values) {
    std::vector<unsigned char> out(values.size() * sizeof(T));
    std::memcpy(out.data(), values.data(), out.size());
    return out;
}

TEST_F(SceneLoader, VertexColoursAreReadInEveryTypeGltfAllows) {
    HandGltf g;
    g.positions = kTriangle;
    // VEC4 of normalized unsigned bytes: value / 255.
    g.colorBytes = {255, 0, 51, 255, 0, 255, 0, 128, 102, 102, 102, 0};
    g.colorAccessor = R"("componentType": 5121, "normalized": true, "type": "VEC4")";
    Scene s = vct::loadScene(write("ubyte.gltf", g.json()));
    ASSERT_EQ(s.colors.size(), 3u);
    const glm::uvec3 t = s.triangles[0];
    EXPECT_EQ(s.colors[t.x], glm::vec4(1.f, 0.f, 51.f / 255.f, 1.f));
    EXPECT_EQ(s.colors[t.y], glm::vec4(0.f, 1.f, 0.f, 128.f / 255.f));
    EXPECT_EQ(s.colors[t.z], glm::vec4(102.f / 255.f, 102.f / 255.f, 102.f / 255.f, 0.f));
    // VEC3 of normalized unsigned shorts: value / 65535, alpha 1.
    g.colorBytes = bytesOf(std::vector<uint16_t>{65535, 0, 13107, 0, 65535, 0, 32768, 32768, 32768});
    g.colorAccessor = R"("componentType": 5123, "normalized": true, "type": "VEC3")";
    s = vct::loadScene(write("ushort.gltf", g.json()));
    ASSERT_EQ(s.colors.size(), 3u);
    EXPECT_EQ(s.colors[s.triangles[0].x], glm::vec4(1.f, 0.f, 0.2f, 1.f));
    EXPECT_FLOAT_EQ(s.colors[s.triangles[0].z].r, 32768.f / 65535.f);
    // VEC3 of floats.
    g.colorBytes = bytesOf(std::vector<float>{0.25f, 0.5f, 0.75f, 1, 1, 1, 0, 0, 0});
    g.colorAccessor = R"("componentType": 5126, "type": "VEC3")";
    s = vct::loadScene(write("float.gltf", g.json()));
    EXPECT_EQ(s.colors[s.triangles[0].x], glm::vec4(0.25f, 0.5f, 0.75f, 1.f));
    // Without COLOR_0 the scene has no colours (every vertex white).
    g.colorBytes.clear();
    EXPECT_TRUE(vct::loadScene(write("none.gltf", g.json())).colors.empty());
}

TEST_F(SceneLoader, APrimitiveWithoutColoursIsWhiteBesideOneWithThem) {
    HandGltf g;
    g.positions = kTriangle;
    g.colorBytes = bytesOf(std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
    g.colorAccessor = R"("componentType": 5126, "type": "VEC3")";
    // Two meshes share nothing but their attributes' accessors: mesh 1 reads POSITION alone.
    std::string json = g.json();
    const std::string meshes = R"("meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "mode": 4}]})";
    ASSERT_NE(json.find(meshes), std::string::npos);
    json.replace(json.find(meshes), meshes.size(),
                 meshes + R"(, {"name": "plain", "primitives": [{"attributes": {"POSITION": 0}}]})");
    const std::string nodes = R"([{"mesh": 0, "name": "n"}])";
    json.replace(json.find(nodes), nodes.size(), R"([{"mesh": 1, "name": "plain"}, {"mesh": 0, "name": "n"}])");
    json.replace(json.find(R"("nodes": [0])"), 12, R"("nodes": [0, 1])");
    const Scene s = vct::loadScene(write("mixed.gltf", json));
    ASSERT_EQ(s.triangles.size(), 2u);
    ASSERT_EQ(s.colors.size(), s.positions.size());
    EXPECT_EQ(s.colors[s.triangles[0].x], glm::vec4(1.f));  // the plain mesh came first
    EXPECT_EQ(s.colors[s.triangles[1].x], glm::vec4(0.5f, 0.5f, 0.5f, 1.f));
}

TEST_F(SceneLoader, VertexColoursOfATypeGltfDoesNotAllowAreRefusedByName) {
    HandGltf g;
    g.positions = kTriangle;
    g.colorBytes = bytesOf(std::vector<float>{1, 1, 1, 1, 1, 1});
    g.colorAccessor = R"("componentType": 5126, "type": "VEC2")";
    EXPECT_CONTAINS(loadError(write("vec2.gltf", g.json())), "COLOR_0): a vertex colour must be VEC3 or VEC4");
    g.colorBytes = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    g.colorAccessor = R"("componentType": 5121, "type": "VEC4")";
    EXPECT_CONTAINS(loadError(write("unnormalized.gltf", g.json())),
                    "a vertex colour must be float, or normalized unsigned byte or short (component type 5121)");
    g.colorAccessor = R"("componentType": 5121, "normalized": true, "type": "VEC4")";
    g.colorCount = 2;
    EXPECT_CONTAINS(loadError(write("short.gltf", g.json())), "count 2 differs from POSITION count 3");
    g.colorCount = -1;
    g.colorBytes = bytesOf(std::vector<float>{1, 1, 1, std::nanf(""), 1, 1, 1, 1, 1});
    g.colorAccessor = R"("componentType": 5126, "type": "VEC3")";
    EXPECT_CONTAINS(loadError(write("nan.gltf", g.json())), "COLOR_0): element 1 is not finite");
}

TEST_F(SceneLoader, GlbAndGltfFromTheBuilderLoadTheSame) {
    vct::SceneBuilder b("roundtrip");
    const int m = b.addMaterial("m", glm::vec3(0.5f));
    b.addTransformedBox(
        "box",
        vct::NodeTransform{glm::vec3(1, 2, 3), glm::angleAxis(0.3f, glm::vec3(0, 1, 0)), glm::vec3(1, 2, 3)},
        m);
    b.addPointLight("p", glm::vec3(0, 5, 0), glm::vec3(1), 2.f);
    const std::string glb = (dir / "r.glb").string(), gltf = (dir / "r.gltf").string();
    b.write(glb);
    b.write(gltf);
    EXPECT_FALSE(fs::exists(glb + ".tmp"));
    const Scene a = vct::loadScene(glb), c = vct::loadScene(gltf), direct = b.toScene();
    ASSERT_EQ(a.triangleCount(), 12u);
    EXPECT_EQ(a.positions, c.positions);
    EXPECT_EQ(a.positions, direct.positions);
    EXPECT_EQ(a.lights.size(), 1u);
    // Box volume from the divergence theorem: sum over faces of (centroid . n) area / 3 = 1*2*3.
    double volume = 0.0;
    for (size_t i = 0; i < a.triangleCount(); ++i) {
        const glm::uvec3 t = a.triangles[i];
        const glm::dvec3 p0 = a.positions[t.x], p1 = a.positions[t.y], p2 = a.positions[t.z];
        volume += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
    }
    EXPECT_NEAR(volume, 6.0, 1e-4);  // positive: outward winding
}

// The third-party scenes beside the project (../shared/scenes); triangle counts from its README.
TEST(SharedScenes, FloorCubeAndCornellBoxTriangleCounts) {
    const char* env = std::getenv("VCT_SHARED_SCENES");
    const fs::path root = env ? fs::path(env) : fs::path(VCT_SOURCE_DIR) / ".." / "shared" / "scenes";
    if (!fs::exists(root / "floor_cube.glb") || !fs::exists(root / "mcguire_CornellBox-Original.glb"))
        GTEST_SKIP() << "shared scenes not found in " << root << " (set VCT_SHARED_SCENES)";
    const Scene cube = vct::loadScene((root / "floor_cube.glb").string());
    EXPECT_EQ(cube.triangleCount(), 14u);
    EXPECT_FALSE(cube.cameras.empty());
    // The README lists (-5,-1,-5)..(5,1,5): the mesh-local bounds. The "Cube" node is translated by
    // (0, 1, 0), so in world space the cube sits on the floor: (-5,0,-5)..(5,2,5).
    EXPECT_NEAR(cube.bounds.min.x, -5.f, 0.01f);
    EXPECT_NEAR(cube.bounds.min.y, 0.f, 0.01f);
    EXPECT_NEAR(cube.bounds.max.y, 2.f, 0.01f);
    const Scene cornell = vct::loadScene((root / "mcguire_CornellBox-Original.glb").string());
    EXPECT_EQ(cornell.triangleCount(), 32u);
    bool emissive = false;
    for (const vct::Material& m : cornell.materials) emissive = emissive || m.isEmissive();
    EXPECT_TRUE(emissive);
    EXPECT_NEAR(cornell.bounds.max.y, 1.99f, 0.01f);
}
