// Merging sweep results: every case directory's results.json (and case.json) folded into
// one table of flattened records with their Pareto flags.
#include "eval/sweep.h"

#include "core/errors.h"
#include "util/atomic_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json readJsonFile(const fs::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    try {
        return json::parse(in);
    } catch (const json::parse_error& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

struct LoadedCase {
    json caseInfo;  // case.json, or what can be derived without it
    json results;   // results.json
    std::string dir;
};

void loadCaseDir(const fs::path& dir, std::vector<LoadedCase>& out, const std::function<void(const std::string&)>& warn) {
    LoadedCase lc;
    lc.dir = dir.string();
    lc.results = readJsonFile(dir / "results.json");
    if (fs::exists(dir / "case.json")) {
        lc.caseInfo = readJsonFile(dir / "case.json");
    } else {  // a plain `vct compare` directory
        const std::string scene = lc.results.value("scene", std::string());
        lc.caseInfo = {{"id", dir.filename().string()},
                       {"scene", fs::path(scene).stem().string()},
                       {"scene_path", scene},
                       {"camera", {{"label", "default"}}},
                       {"radius", lc.results.value("radius", 0.0)}};
        if (warn) warn(dir.string() + ": no case.json, using results.json alone");
    }
    out.push_back(std::move(lc));
}

}  // namespace

json mergeSweepResults(const std::vector<std::string>& dirs, const std::function<void(const std::string&)>& warn) {
    std::vector<LoadedCase> cases;
    for (const std::string& d : dirs) {
        const fs::path dir(d);
        if (fs::is_directory(dir / "cases")) {
            std::vector<fs::path> subs;
            for (const auto& e : fs::directory_iterator(dir / "cases"))
                if (e.is_directory()) subs.push_back(e.path());
            std::sort(subs.begin(), subs.end());
            for (const fs::path& sub : subs) {
                if (fs::exists(sub / "results.json")) loadCaseDir(sub, cases, warn);
                else if (warn) warn(sub.string() + ": no results.json (not run yet, or interrupted): left out");
            }
            if (fs::exists(dir / "sweep.json") && warn) {
                json sw = readJsonFile(dir / "sweep.json");
                size_t present = 0;
                for (const auto& id : sw["cases"])
                    present += fs::exists(dir / "cases" / id.get<std::string>() / "results.json");
                if (present < sw["cases"].size())
                    warn(d + ": " + std::to_string(present) + " of " + std::to_string(sw["cases"].size()) +
                         " cases have results (other shards, absent scenes or unfinished cases)");
            }
        } else if (fs::exists(dir / "results.json")) {
            loadCaseDir(dir, cases, warn);
        } else {
            throw UsageError("merge: " + d + " holds neither cases/ nor results.json");
        }
    }
    std::stable_sort(cases.begin(), cases.end(), [](const LoadedCase& a, const LoadedCase& b) {
        const long long ia = a.caseInfo.value("index", -1LL), ib = b.caseInfo.value("index", -1LL);
        const std::string ida = a.caseInfo.value("id", std::string()), idb = b.caseInfo.value("id", std::string());
        // Plain comparison dirs (no index) go last.
        if ((ia < 0) != (ib < 0)) return ib < 0;
        return ia != ib ? ia < ib : ida < idb;
    });

    json merged = {{"cases", json::array()}, {"records", json::array()}, {"sources", dirs}};
    std::set<std::string> seen;
    for (LoadedCase& lc : cases) {
        const std::string id = lc.caseInfo.value("id", std::string());
        if (!seen.insert(id).second) {
            if (warn) warn(lc.dir + ": case " + id + " seen already in an earlier directory: left out");
            continue;
        }
        json doc = lc.results;
        doc["case"] = lc.caseInfo;
        doc["case_dir"] = lc.dir;
        const json& ref = doc.value("reference", json::object());
        // A sequence comparison's document (a path case, or a `vct compare --path` directory).
        const bool sequence = lc.results.contains("frames") && lc.results.contains("path");
        for (const json& r : lc.results["records"]) {
            json flat = r;
            const bool ao = r.value("kind", std::string("ao")) == "ao";
            flat["case"] = id;
            flat["scene"] = lc.caseInfo.value("scene", std::string());
            flat["scene_path"] = lc.results.value("scene", std::string());
            flat["camera"] = lc.caseInfo.contains("camera") ? lc.caseInfo["camera"].value("label", std::string()) : "";
            flat["radius"] = lc.results.value("radius", 0.0);
            flat["width"] = lc.results.value("width", 0);
            flat["height"] = lc.results.value("height", 0);
            flat["gl_renderer"] = lc.results.value("gl_renderer", std::string());
            flat["ref_spp"] = ref.value("spp", 0);
            const char* stderrKey = ao ? "ao_rms_pixel_stderr" : "gi_rms_pixel_stderr";
            flat["ref_stderr"] = ref.contains(stderrKey) ? ref[stderrKey] : json(nullptr);
            if (sequence) {
                if (!flat.contains("rmse")) flat["rmse"] = r.value("rmse_mean", json(nullptr));
                flat["frames"] = lc.results["frames"];
                flat["camera_path"] = lc.results["path"].value("source", std::string());
                flat["frame_seeds"] = lc.results.value("per_frame_seeds", true) ? "per-frame" : "fixed";
                if (flat.contains("frames_dir") && flat["frames_dir"].is_string())
                    flat["frames_dir"] = (fs::path(lc.dir) / flat["frames_dir"].get<std::string>()).string();
            }
            if (flat.contains("images") && flat["images"].is_object())
                for (auto it = flat["images"].begin(); it != flat["images"].end(); ++it)
                    if (it.value().is_string()) it.value() = (fs::path(lc.dir) / it.value().get<std::string>()).string();
            merged["records"].push_back(std::move(flat));
        }
        merged["cases"].push_back(std::move(doc));
    }
    markParetoFronts(merged["records"]);
    return merged;
}

void writeMerged(const json& merged, const std::string& outDir) {
    fs::create_directories(outDir);
    writeTextFileAtomic((fs::path(outDir) / "results.json").string(), merged.dump(2) + "\n");
    writeTextFileAtomic((fs::path(outDir) / "results.csv").string(), mergedCsv(merged));
}

}  // namespace vct
