// Copying one sequence comparison into the site: its frame PNGs as `vct compare` wrote them
// (they already carry the gallery's encoding: AO clamped as stored, radiance at 0 EV through
// sRGB), results.json and .csv, and one thumbnail for the index.
#include "gallery/site_model.h"

#include "eval/image_io.h"
#include "gallery/site_images.h"

#include <filesystem>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;

namespace {

void copyInto(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec)
        throw std::runtime_error("cannot copy " + from.string() + " to " + to.string() + ": " + ec.message());
}

struct SequenceWriter {
    const GalleryInput& in;
    fs::path site;
    std::string dataDir;  // site-relative
    int frames;
    SiteCase out;

    // Copies DIR/relDir/0000.png .. into SITE/data/<id>/relDir/ and returns their site paths.
    // relDir was checked to stay inside DIR, so the copy stays inside the case's folder.
    std::vector<std::string> copyFrames(const std::string& relDir) {
        std::vector<std::string> paths;
        for (int f = 0; f < frames; ++f) {
            const std::string rel = dataDir + "/" + relDir + "/" + sequenceFrameName(f);
            copyInto(fs::path(in.dir) / relDir / sequenceFrameName(f), site / rel);
            paths.push_back(rel);
        }
        return paths;
    }
};

}  // namespace

SiteCase buildSequenceCase(const GalleryInput& input, const std::string& siteDir, int thumbnailWidth,
                           int& imageCount) {
    SequenceWriter w{input, fs::path(siteDir), "data/" + input.id, input.results["frames"].get<int>(), {}};
    SiteCase& c = w.out;
    c.input = input;
    c.page = input.id + ".html";
    c.dataDir = w.dataDir;
    fs::create_directories(w.site / w.dataDir);
    const auto& records = input.results["records"];
    c.recordImage.assign(records.size(), -1);  // no still images: the still pages' tables stay in bounds
    c.recordFrames.assign(records.size(), {});
    for (size_t r = 0; r < records.size(); ++r) {
        if (!records[r].contains("frames_dir")) continue;
        c.recordFrames[r] = w.copyFrames(records[r]["frames_dir"].get<std::string>());
        imageCount += w.frames;
        const std::string kind = records[r]["kind"].get<std::string>();
        if (!c.referenceFrames.count(kind)) {
            c.referenceFrames[kind] = w.copyFrames("frames/reference_" + kind);
            imageCount += w.frames;
        }
    }
    // The index thumbnail: the reference's first frame (AO first), else the first method's.
    std::string first;
    for (const char* kind : {"ao", "gi"})
        if (first.empty() && c.referenceFrames.count(kind)) first = c.referenceFrames[kind].front();
    for (const auto& fr : c.recordFrames)
        if (first.empty() && !fr.empty()) first = fr.front();
    if (!first.empty()) {
        const Image frame0 = readImage((w.site / first).string());
        if (frame0.width > thumbnailWidth) {
            c.sequenceThumb = w.dataDir + "/thumbs/sequence.png";
            fs::create_directories(w.site / w.dataDir / "thumbs");
            writeImage((w.site / c.sequenceThumb).string(), thumbnailOf(frame0, thumbnailWidth));
            ++imageCount;
        } else {
            c.sequenceThumb = first;
        }
    }
    for (const char* name : {"results.json", "results.csv"})
        if (fs::exists(fs::path(input.dir) / name)) {
            const std::string rel = w.dataDir + "/" + name;
            copyInto(fs::path(input.dir) / name, w.site / rel);
            c.downloads.push_back({name, rel});
        }
    return c;
}

}  // namespace vct
