// Recognising and checking a sequence comparison (`vct compare --path P --frames N`) before the
// gallery writes anything: the sequence page indexes per-frame arrays by frame and shows every
// frame file, so a short array or a missing frame would otherwise become a page that plays the
// wrong frames or a half-copied site.
#include "gallery/gallery_input.h"

#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;

bool isSequenceResults(const nlohmann::json& results) {
    if (!results.is_object()) return false;
    if (results.contains("frames")) return true;
    if (results.contains("records") && results["records"].is_array())
        for (const auto& r : results["records"])
            if (r.is_object() && r.contains("per_frame")) return true;
    return false;
}

std::string sequenceFrameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "%04d.png", frame);
    return name;
}

namespace {

struct Checker {
    fs::path dir;
    std::string file;  // DIR/results.json, the name every message starts with
    int frames = 0;

    [[noreturn]] void fail(const std::string& element, const std::string& what) const {
        throw std::runtime_error(file + ": " + element + ": " + what);
    }

    // An array of `n` numbers; null stands for a value the comparison could not compute (NaN).
    void numbers(const nlohmann::json& j, const std::string& element, int n, const char* per) const {
        if (!j.is_array()) fail(element, "expected an array of numbers");
        if (int(j.size()) != n)
            fail(element, std::to_string(j.size()) + " values for " + std::to_string(frames) +
                              " frames (expected " + std::to_string(n) + ", one per " + per + ")");
        for (size_t i = 0; i < j.size(); ++i)
            if (!j[i].is_number() && !j[i].is_null())
                fail(element + "[" + std::to_string(i) + "]", "expected a number, got " + j[i].dump());
    }

    // A path from results.json must stay inside the comparison directory.
    void relativeInside(const std::string& path, const std::string& element) const {
        const fs::path p(path);
        bool up = false;
        for (const auto& part : p) up = up || part == "..";
        if (path.empty() || p.is_absolute() || p.has_root_name() || up ||
            path.find('\\') != std::string::npos)
            fail(element, "\"" + path + "\" is not a relative path inside the results directory");
    }

    void framesExist(const std::string& relDir, const std::string& element) const {
        for (int f = 0; f < frames; ++f) {
            const fs::path frame = dir / relDir / sequenceFrameName(f);
            if (!fs::is_regular_file(frame))
                fail(element, "frame " + std::to_string(f) + " is missing: " + frame.string());
        }
    }

    void checkFrameCount(const nlohmann::json& doc) {
        if (!doc.contains("frames") || !doc["frames"].is_number_integer())
            fail("frames", "expected the number of frames (a sequence's records have \"per_frame\")");
        const auto n = doc["frames"].get<long long>();
        if (n < 1 || n > 100000) fail("frames", std::to_string(n) + " is not in [1, 100000]");
        frames = int(n);
        if (doc.contains("times")) numbers(doc["times"], "times", frames, "frame");
        if (doc.contains("reference") && !doc["reference"].is_object())
            fail("reference", "expected an object");
    }

    // Returns the record's kind.
    std::string checkRecord(const nlohmann::json& r, const std::string& element) const {
        if (!r.is_object()) fail(element, "expected an object");
        const std::string kind =
            r.contains("kind") && r["kind"].is_string() ? r["kind"].get<std::string>() : "";
        if (kind != "ao" && kind != "gi") fail(element + ".kind", "expected \"ao\" or \"gi\"");
        if (r.contains("label") && !r["label"].is_string()) fail(element + ".label", "expected a string");
        if (r.contains("temporal") && !r["temporal"].is_object())
            fail(element + ".temporal", "expected an object");
        if (!r.contains("per_frame") || !r["per_frame"].is_object())
            fail(element + ".per_frame", "missing (every record of a sequence has its per-frame values)");
        const nlohmann::json& pf = r["per_frame"];
        for (const char* key : {"rmse", "frame_ms"}) {
            if (!pf.contains(key)) fail(element + ".per_frame." + key, "missing");
            numbers(pf[key], element + ".per_frame." + key, frames, "frame");
        }
        if (!pf.contains("instability")) fail(element + ".per_frame.instability", "missing");
        numbers(pf["instability"], element + ".per_frame.instability", frames - 1,
                "pair of consecutive frames");
        if (r.contains("frames_dir")) {
            if (!r["frames_dir"].is_string()) fail(element + ".frames_dir", "expected a string");
            const std::string framesDir = r["frames_dir"].get<std::string>();
            relativeInside(framesDir, element + ".frames_dir");
            framesExist(framesDir, element + ".frames_dir");
        }
        return kind;
    }
};

}  // namespace

void checkSequenceResults(const nlohmann::json& results, const std::string& dir) {
    Checker c{fs::path(dir), (fs::path(dir) / "results.json").string(), 0};
    if (!results.is_object() || !results.contains("records") || !results["records"].is_array())
        c.fail("records", "expected an array");
    c.checkFrameCount(results);
    // Kinds whose method frames are shown: the reference's frames of that kind are shown beside them.
    std::set<std::string> framedKinds;
    const auto& records = results["records"];
    for (size_t i = 0; i < records.size(); ++i) {
        const std::string element = "records[" + std::to_string(i) + "]";
        const std::string kind = c.checkRecord(records[i], element);
        if (records[i].contains("frames_dir")) framedKinds.insert(kind);
    }
    for (const std::string& kind : framedKinds)
        c.framesExist("frames/reference_" + kind, "the reference's " + kind + " frames");
}

}  // namespace vct
