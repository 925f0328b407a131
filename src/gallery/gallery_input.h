// What `vct gallery` reads: comparison directories (results.json + images, as `vct compare`
// writes them; or results.json + frames/, as `vct compare --path --frames` writes them) and
// sweep directories whose cases/<case>/ are each such a directory.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vct {

struct GalleryInput {
    std::string id;            // unique, file-name-safe: names the case's page and data folder
    std::string title;         // "offscreen_overhang  (g1)" for people
    std::string dir;           // the comparison directory
    nlohmann::json results;    // its results.json
    std::string measuredDate;  // results.json's modification time (UTC), "" if unknown
    bool sequence = false;     // a comparison along a camera path (checked by checkSequenceResults)
};

// Expands each directory: a comparison dir gives one input; a sweep dir (no results.json but
// cases/*/results.json) gives one per case, in name order. Ids are made unique by a suffix.
// Throws UsageError naming a directory that is neither, and std::runtime_error
// naming a results.json that cannot be parsed, lacks "records" or is a bad sequence
// (checkSequenceResults): every input is read and checked before the site is touched.
std::vector<GalleryInput> findGalleryInputs(const std::vector<std::string>& dirs);

// Whether a results.json is a sequence comparison: it has "frames" or a record has "per_frame"
// (either alone is a sequence gone wrong, which checkSequenceResults reports).
bool isSequenceResults(const nlohmann::json& results);

// Checks what the sequence page relies on, so that a bad directory fails before anything is
// written: "frames" N >= 1; "times", when present, N numbers; every record an object with
// kind "ao" or "gi" and per_frame {rmse: N, frame_ms: N, instability: N-1} (numbers or null);
// "frames_dir", when present, a relative path inside `dir` holding 0000.png .. N-1, and then
// frames/reference_<kind>/ holding the reference's N frames too. Throws std::runtime_error
// naming DIR/results.json and the element ("records[1].per_frame.rmse: 5 values for 6 frames")
// or the missing frame file.
void checkSequenceResults(const nlohmann::json& results, const std::string& dir);

// The file name of frame `frame` in a frames directory: "0007.png" (as vct compare writes them).
std::string sequenceFrameName(int frame);

// `text` with every character outside [A-Za-z0-9._-] replaced by '_' (never empty: "case").
std::string fileSafeName(const std::string& text);

}  // namespace vct
