// The gallery's view of one comparison after its files are copied into the site: what the
// page writers (index_page.cpp, scene_page.cpp) render. Paths are relative to the site root,
// where every page lives, so they are also the pages' relative URLs.
#pragma once

#include "gallery/gallery_input.h"

#include <map>
#include <string>
#include <vector>

namespace vct {

struct SiteImage {
    std::string id;         // unique in the case: "reference_ao", "ao_gtao", "ao_gtao_error"
    std::string label;      // for people: "gtao", "reference AO (64 spp)", "gtao: error"
    std::string group;      // "AO", "Indirect", "Beauty" or "Error"
    std::string src;        // display PNG
    std::string thumb;      // thumbnail PNG (may equal src)
    std::string exr;        // linear EXR for download ("" if none)
    std::string errorId;    // method images: id of their error map ("" if none)
    double errorScale = 0;  // error maps: the +-scale at which the colours saturate
    int record = -1;        // index into results["records"], -1 for references
};

struct SiteCase {
    GalleryInput input;
    std::string page;     // "<id>.html"
    std::string dataDir;  // "data/<id>"
    std::vector<SiteImage> images;
    std::vector<int> recordImage;     // per record: index into images of its main view, or -1
    std::string roiMask, roiOutline;  // "" when the scene has no off-screen occluders
    std::string legend, validMask;    // "" when absent
    std::vector<std::pair<std::string, std::string>> downloads;  // (label, path): json, csv, EXRs
    // Sequence cases (input.sequence) only: the frame PNGs, one list per record (empty when the
    // record wrote no frames) and per reference kind ("ao", "gi"; absent when not compared),
    // each frames[f] the site path of frame f; and the index thumbnail ("" when no frames).
    std::vector<std::vector<std::string>> recordFrames;
    std::map<std::string, std::vector<std::string>> referenceFrames;
    std::string sequenceThumb;

    const SiteImage* image(const std::string& id) const {
        for (const auto& im : images)
            if (im.id == id) return &im;
        return nullptr;
    }
};

// Copies and converts one comparison's files into SITE/data/<id>/ and returns its model.
// `imageCount` is increased by the PNGs written.
SiteCase buildSiteCase(const GalleryInput& input, const std::string& siteDir, int thumbnailWidth,
                       int& imageCount);

// Copies one sequence comparison's frames into SITE/data/<id>/frames/ (sequence_files.cpp);
// the input has passed checkSequenceResults.
SiteCase buildSequenceCase(const GalleryInput& input, const std::string& siteDir, int thumbnailWidth,
                           int& imageCount);

// Shared page parts (page_common.cpp).
// `extraHead`: more of <head> (a page's own <style>), written as given.
std::string pageHead(const std::string& title, const std::string& extraHead = "");
std::string pageFooter(const std::vector<const SiteCase*>& cases, const std::string& generated);
std::string recordLabel(const nlohmann::json& record, bool withKind);
double jsonNumber(const nlohmann::json& j, const char* key);  // NaN when missing or null

std::string indexPage(const std::vector<SiteCase>& cases, const std::string& title,
                      const std::string& generated);
std::string scenePage(const SiteCase& c, const std::vector<SiteCase>& all, const std::string& generated);
// The page of a sequence case (sequence_page.cpp): flipbooks, per-frame plots, the table.
std::string sequencePage(const SiteCase& c, const std::vector<SiteCase>& all, const std::string& generated);

}  // namespace vct
