// What `vct gallery` reads: comparison directories (results.json + images, as `vct compare`
// writes them) and sweep directories whose cases/<case>/ are each such a directory.
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
};

// Expands each directory: a comparison dir gives one input; a sweep dir (no results.json but
// cases/*/results.json) gives one per case, in name order. Ids are made unique by a suffix.
// Throws UsageError naming a directory that is neither, and std::runtime_error
// naming a results.json that cannot be parsed or lacks "records".
std::vector<GalleryInput> findGalleryInputs(const std::vector<std::string>& dirs);

// `text` with every character outside [A-Za-z0-9._-] replaced by '_' (never empty: "case").
std::string fileSafeName(const std::string& text);

}  // namespace vct
