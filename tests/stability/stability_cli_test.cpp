// Invalid input through the command line, as a user meets it: .gltf files with NaN or
// infinite values are refused with exit code 1, a message naming the element, and no
// output file; parameters out of range are refused with exit code 2 and their valid range.
#include "stability/stability_harness.h"

#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace stab;

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i + 1 == bytes.size()) {
        unsigned v = bytes[i] << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == bytes.size()) {
        unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

// A one-quad .gltf (positions and normals in one embedded buffer) with hooks to poison it.
struct TinyGltf {
    std::vector<float> positions = {-1, 0, -1, -1, 0, 1, 1, 0, 1, 1, 0, -1};
    std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    std::string nodeExtra;   // JSON members added to the mesh node
    std::string lightJson;   // a KHR_lights_punctual light, if non-empty

    std::string json() const {
        std::vector<unsigned char> bytes((positions.size() + normals.size()) * 4 + 6 * 2);
        std::memcpy(bytes.data(), positions.data(), positions.size() * 4);
        std::memcpy(bytes.data() + positions.size() * 4, normals.data(), normals.size() * 4);
        const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
        std::memcpy(bytes.data() + (positions.size() + normals.size()) * 4, idx, sizeof idx);
        const size_t pb = positions.size() * 4, nb = normals.size() * 4;
        std::string j = "{\"asset\":{\"version\":\"2.0\"},";
        if (!lightJson.empty())
            j += "\"extensionsUsed\":[\"KHR_lights_punctual\"],\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[" +
                 lightJson + "]}},";
        j += "\"scene\":0,\"scenes\":[{\"nodes\":[0" + std::string(lightJson.empty() ? "" : ",1") + "]}],";
        j += "\"nodes\":[{\"name\":\"quad_node\",\"mesh\":0" + nodeExtra + "}";
        if (!lightJson.empty()) j += ",{\"name\":\"lamp\",\"translation\":[0,2,0],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}";
        j += "],";
        j += "\"meshes\":[{\"name\":\"quad\",\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2}]}],";
        j += "\"accessors\":[";
        j += "{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\",\"min\":[-1,0,-1],\"max\":[1,0,1]},";
        j += "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},";
        j += "{\"bufferView\":2,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],";
        j += "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" + std::to_string(pb) + "},";
        j += "{\"buffer\":0,\"byteOffset\":" + std::to_string(pb) + ",\"byteLength\":" + std::to_string(nb) + "},";
        j += "{\"buffer\":0,\"byteOffset\":" + std::to_string(pb + nb) + ",\"byteLength\":12}],";
        j += "\"buffers\":[{\"byteLength\":" + std::to_string(bytes.size()) +
             ",\"uri\":\"data:application/octet-stream;base64," + base64(bytes) + "\"}]}";
        return j;
    }
};

struct BadFile {
    std::string caseName;
    TinyGltf gltf;
    std::vector<std::string> mustMention;  // substrings the error message must contain
};

bool mentionsAll(const std::string& text, const std::vector<std::string>& parts) {
    for (const auto& p : parts)
        if (text.find(p) == std::string::npos) return false;
    return true;
}

}  // namespace

TEST(StabilityCli, NonFiniteSceneFilesAreRejectedNamingTheElement) {
    const std::string dir = vcttest::freshTempDir("stability_cli");
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<BadFile> files;
    {
        BadFile f{"file: NaN position", {}, {"POSITION", "element 2", "not finite"}};
        f.gltf.positions[7] = nan;
        files.push_back(f);
    }
    {
        BadFile f{"file: Inf position", {}, {"POSITION", "element 0", "not finite"}};
        f.gltf.positions[0] = -inf;
        files.push_back(f);
    }
    {
        BadFile f{"file: Inf normal", {}, {"NORMAL", "element 3", "not finite"}};
        f.gltf.normals[10] = inf;
        files.push_back(f);
    }
    {
        // 1e39 is finite as a JSON double and infinite as a float: still infinite input.
        BadFile f{"file: translation 1e39", {}, {"quad_node", "not finite"}};
        f.gltf.nodeExtra = ",\"translation\":[1e39,0,0]";
        files.push_back(f);
    }
    {
        BadFile f{"file: light intensity 1e39", {}, {"lamp"}};
        f.gltf.lightJson = "{\"name\":\"lamp\",\"type\":\"point\",\"intensity\":1e39}";
        files.push_back(f);
    }
    for (const auto& f : files) {
        const std::string scene = dir + "/bad.gltf", out = dir + "/out.png";
        std::filesystem::remove(out);
        {
            std::ofstream s(scene);
            s << f.gltf.json();
        }
        auto res = vcttest::runVct("render '" + scene + "' -o '" + out + "' --size 16 --ao gtao");
        const bool named = mentionsAll(res.output, f.mustMention);
        const bool noFile = !std::filesystem::exists(out);
        EXPECT_EQ(res.exitCode, 1) << f.caseName << ": " << res.output;
        EXPECT_TRUE(named) << f.caseName << ": the message does not name the element: " << res.output;
        EXPECT_TRUE(noFile) << f.caseName << ": an output file was written";
        std::string msg = res.output;
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r')) msg.pop_back();
        const auto nl = msg.rfind('\n');
        if (nl != std::string::npos) msg = msg.substr(nl + 1);
        if (const auto p = msg.find(scene); p != std::string::npos) msg.replace(p, scene.size(), "bad.gltf");
        recordCaseInfo(f.caseName, "a one-quad .gltf poisoned as named, rendered with `vct render`.", "");
        recordCell(f.caseName, "renderer",
                   {"exit " + std::to_string(res.exitCode) + ": " + msg, res.exitCode == 1 && named && noFile});
    }
}

TEST(StabilityCli, OutOfRangeParametersAreRejectedWithTheirRange) {
    struct Case {
        std::string args;
        std::string range;  // must appear in the message
    };
    const std::vector<Case> cases = {
        {"--radius -1", "> 0"},
        {"--radius nan", "finite"},
        {"--sky -1", ">= 0"},
        {"--spp 0", "[1, 1048576]"},
        {"--voxel-res 2", "[4, 1024]"},
        {"--size 0", "[1, 16384]"},
        {"--ao vct --param vct.aperture=179.5", "[1, 179]"},
        {"--ao vct --param vct.aperture=0.5", "[1, 179]"},
        {"--ao gtao --param gtao.slices=0", "gtao.slices"},
        {"--gi reference --param reference.bounces=0", "[1, 1024]"},
        {"--ao hbao --param hbao.steps=1000", "[1, 64]"},
    };
    const std::string dir = vcttest::freshTempDir("stability_cli_params");
    const std::string scene = vcttest::sourceDir() + "/scenes/cornell_box.gltf";
    const std::string name = "parameters out of range";
    recordCaseInfo(name, "`vct render` with each out-of-range value listed in the findings.", "");
    bool allOk = true;
    for (const auto& c : cases) {
        const std::string out = dir + "/o.png";
        const std::string size = c.args.find("--size") == std::string::npos ? "--size 16 " : "";
        auto res = vcttest::runVct("render '" + scene + "' -o '" + out + "' " + size + c.args);
        EXPECT_EQ(res.exitCode, 2) << c.args << ": " << res.output;
        EXPECT_NE(res.output.find(c.range), std::string::npos) << c.args << ": no range in: " << res.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
        const bool ok = res.exitCode == 2 && res.output.find(c.range) != std::string::npos;
        allOk = allOk && ok;
        std::string msg = res.output;
        while (!msg.empty() && msg.back() == '\n') msg.pop_back();
        if (const auto nl = msg.rfind('\n'); nl != std::string::npos) msg = msg.substr(nl + 1);  // the error line
        recordNote("`" + c.args + "` -> exit " + std::to_string(res.exitCode) + ": " + msg);
    }
    recordCell(name, "renderer", {allOk ? "refused with range (exit 2)" : "range missing", allOk});
}
