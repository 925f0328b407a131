#include "gallery/gallery.h"

#include "core/errors.h"
#include "gallery/assets/gallery_assets.h"
#include "gallery/gallery_input.h"
#include "gallery/html.h"
#include "gallery/site_model.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;

namespace {

// Written under a temporary name and renamed, so a reader never sees half a page.
void writeText(const fs::path& path, const std::string& text) {
    fs::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
        out << text;
        if (!out) throw std::runtime_error("error writing " + tmp.string());
    }
    fs::rename(tmp, path);
}

}  // namespace

GallerySummary writeGallery(const GallerySettings& settings) {
    if (settings.inputs.empty()) throw UsageError("vct gallery: no input directory");
    if (settings.outputDir.empty()) throw UsageError("vct gallery: no output directory (-o)");
    if (settings.thumbnailWidth < 16) throw UsageError("vct gallery: --thumb-width must be >= 16");
    const std::vector<GalleryInput> inputs = findGalleryInputs(settings.inputs);
    const fs::path site(settings.outputDir);
    for (const auto& in : inputs)
        if (fs::exists(site) && fs::equivalent(fs::path(in.dir), site))
            throw UsageError("vct gallery: the output directory is an input directory: " + in.dir);
    fs::create_directories(site / "assets");
    fs::create_directories(site / "data");
    writeText(site / "assets" / "gallery.css", galleryCss());
    writeText(site / "assets" / "gallery.js", galleryJs());

    GallerySummary summary;
    std::vector<SiteCase> cases;
    for (const auto& in : inputs) {
        if (settings.progress) settings.progress("case " + in.id + " from " + in.dir);
        cases.push_back(
            in.sequence ? buildSequenceCase(in, site.string(), settings.thumbnailWidth, summary.imageCount)
                        : buildSiteCase(in, site.string(), settings.thumbnailWidth, summary.imageCount));
    }
    const std::string generated = utcNowString();
    writeText(site / "index.html", indexPage(cases, settings.title, generated));
    summary.pages.push_back("index.html");
    for (const auto& c : cases) {
        writeText(site / c.page,
                  c.input.sequence ? sequencePage(c, cases, generated) : scenePage(c, cases, generated));
        summary.pages.push_back(c.page);
    }
    summary.caseCount = int(cases.size());
    return summary;
}

}  // namespace vct
