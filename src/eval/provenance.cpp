#include "eval/provenance.h"

#include "methods/registry.h"
#include "vct_git_commit.h"

#include <openssl/evp.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace vct {

std::string buildCommit() { return VCT_GIT_COMMIT; }

std::string fileSha256(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read the file to hash it");
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("SHA-256 is not available from OpenSSL");
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        if (in.gcount() > 0) EVP_DigestUpdate(ctx.get(), buffer.data(), size_t(in.gcount()));
    }
    if (in.bad()) throw std::runtime_error(path + ": read error while hashing");
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx.get(), digest, &length);
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (unsigned int i = 0; i < length; ++i) {
        out += hex[digest[i] >> 4];
        out += hex[digest[i] & 15];
    }
    return out;
}

nlohmann::json resolvedParams(MethodKind kind, const std::string& method, const ParamMap& params) {
    nlohmann::json out = nlohmann::json::object();
    const Method* m = findMethod(kind, method);
    if (!m || !m->settings) return out;
    for (const SettingDoc& d : m->settings()) out[d.key] = params.has(d.key) ? params.values().at(d.key) : d.defaultValue;
    if (m->presetValues)
        for (const auto& [key, value] : m->presetValues(params))
            if (!params.has(key)) out[key] = value;
    return out;
}

nlohmann::json runProvenance(const std::string& scenePath, uint32_t seed) {
    // A scene built in memory (tests, the Python module's own scenes) has no file to hash.
    std::error_code ec;
    const bool file = !scenePath.empty() && std::filesystem::is_regular_file(scenePath, ec);
    return {{"commit", buildCommit()},
            {"scene", scenePath},
            {"scene_sha256", file ? nlohmann::json(fileSha256(scenePath)) : nlohmann::json(nullptr)},
            {"seed", seed}};
}

}  // namespace vct
