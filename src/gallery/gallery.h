// `vct gallery`: a static web site (plain files, no server, no network) over one or more
// comparison results: an index grid of scenes x methods, one comparison page per case with
// a slider/flip viewer, synchronized pixel zoom, error maps, the error-against-time plot with
// its Pareto front, the ROI outline overlay, and the metadata and credits of every result;
// and a sequence page per comparison along a camera path: its frames as a flipbook beside the
// reference's, per-frame error and instability plots and the sequence's scores.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace vct {

struct GallerySettings {
    std::vector<std::string> inputs;  // compare dirs (also --path ones) or sweep dirs (see findGalleryInputs)
    std::string outputDir;            // the site; created; files in it are overwritten
    std::string title = "vct comparison gallery";
    int thumbnailWidth = 192;  // px, >= 16: index thumbnails are box-downsampled to this
    std::function<void(const std::string&)> progress;  // a line per case (may be empty)
};

struct GallerySummary {
    int caseCount = 0;
    int imageCount = 0;              // PNGs written (display, error maps, thumbnails, overlays)
    std::vector<std::string> pages;  // site-relative HTML files, index.html first
};

// Writes the site. Throws UsageError for bad settings or inputs, std::runtime_error
// for unreadable inputs or unwritable output (naming the file).
GallerySummary writeGallery(const GallerySettings& settings);

}  // namespace vct
