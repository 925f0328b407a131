#include "gallery/gallery_input.h"

#include "core/errors.h"
#include "gallery/html.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;

std::string fileSafeName(const std::string& text) {
    std::string out;
    for (unsigned char c : text) out += (std::isalnum(c) || c == '.' || c == '-' || c == '_') ? char(c) : '_';
    while (!out.empty() && out.front() == '.') out.erase(out.begin());  // no hidden or ".." names
    return out.empty() ? "case" : out;
}

namespace {

nlohmann::json loadResults(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
    }
    if (!doc.is_object() || !doc.contains("records") || !doc["records"].is_array())
        throw std::runtime_error(file.string() + ": no \"records\" array (not a vct compare results file)");
    return doc;
}

std::string sceneStem(const nlohmann::json& doc) {
    if (doc.contains("scene") && doc["scene"].is_string())
        return fs::path(doc["scene"].get<std::string>()).stem().string();
    return "scene";
}

// The directory's own name, also for "." or a trailing slash.
std::string dirName(const fs::path& dir) {
    fs::path abs = fs::weakly_canonical(fs::absolute(dir));
    std::string name = abs.filename().string();
    return name.empty() ? abs.parent_path().filename().string() : name;
}

}  // namespace

std::vector<GalleryInput> findGalleryInputs(const std::vector<std::string>& dirs) {
    std::vector<GalleryInput> inputs;
    std::set<std::string> usedIds;
    auto add = [&](const fs::path& dir, const std::string& idBase, const std::string& where) {
        GalleryInput in;
        in.dir = dir.string();
        in.results = loadResults(dir / "results.json");
        in.measuredDate = fileTimeString((dir / "results.json").string());
        in.sequence = isSequenceResults(in.results);
        if (in.sequence) checkSequenceResults(in.results, in.dir);
        std::string id = fileSafeName(idBase);
        for (int k = 2; usedIds.count(id); ++k) id = fileSafeName(idBase) + "-" + std::to_string(k);
        usedIds.insert(id);
        in.id = id;
        in.title = sceneStem(in.results) + "  (" + where + ")";
        inputs.push_back(std::move(in));
    };
    for (const std::string& d : dirs) {
        const fs::path dir(d);
        if (!fs::is_directory(dir))
            throw UsageError("gallery input '" + d + "' is not a directory");
        if (fs::exists(dir / "results.json")) {
            add(dir, dirName(dir), dirName(dir));
            continue;
        }
        std::vector<fs::path> cases;
        if (fs::is_directory(dir / "cases"))
            for (const auto& e : fs::directory_iterator(dir / "cases"))
                if (e.is_directory() && fs::exists(e.path() / "results.json")) cases.push_back(e.path());
        if (cases.empty())
            throw UsageError(
                "gallery input '" + d +
                "' has neither results.json (vct compare) nor cases/*/results.json (vct sweep)");
        std::sort(cases.begin(), cases.end());
        for (const auto& c : cases) {
            const std::string caseName = c.filename().string();
            add(c, dirName(dir) + "-" + caseName, dirName(dir) + " / " + caseName);
        }
    }
    return inputs;
}

}  // namespace vct
