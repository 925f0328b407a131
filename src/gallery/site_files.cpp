// Copying one comparison into the site: display PNGs converted from the EXRs (one stated tone
// mapping for every image, whatever the comparison wrote), EXRs and error maps copied,
// thumbnails and the ROI outline made here.
#include "gallery/site_model.h"

#include "eval/error_map.h"
#include "eval/image_io.h"
#include "gallery/site_images.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace vct {

namespace fs = std::filesystem;

namespace {

// A file name from results.json must name a file in the comparison directory itself.
bool plainFileName(const std::string& name) {
    return !name.empty() && name.find('/') == std::string::npos && name.find('\\') == std::string::npos &&
           name != "." && name != "..";
}

void copyInto(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec)
        throw std::runtime_error("cannot copy " + from.string() + " to " + to.string() + ": " + ec.message());
}

struct CaseWriter {
    const GalleryInput& in;
    fs::path site;
    std::string dataDir;  // site-relative
    int thumbWidth;
    int& imageCount;
    SiteCase out;

    fs::path source(const std::string& name) const { return fs::path(in.dir) / name; }
    fs::path target(const std::string& rel) const { return site / rel; }
    std::string rel(const std::string& name) const { return dataDir + "/" + name; }

    void writePng(const std::string& relPath, const Image& img) {
        writeImage(target(relPath).string(), img);
        ++imageCount;
    }

    // Display PNG (+ thumbnail, + EXR copy) of a linear image `stem`.exr; falls back on the
    // comparison's own `stem`.png when there is no EXR. Returns false when neither exists.
    bool addView(SiteImage& im, const std::string& exrName, const std::string& pngName, DisplayEncoding enc) {
        const std::string stem = fs::path(!exrName.empty() ? exrName : pngName).stem().string();
        Image display;
        if (!exrName.empty() && plainFileName(exrName) && fs::exists(source(exrName))) {
            display = displayFromExr(source(exrName).string(), enc);
            copyInto(source(exrName), target(rel(exrName)));
            im.exr = rel(exrName);
        } else if (!pngName.empty() && plainFileName(pngName) && fs::exists(source(pngName))) {
            display = readImage(source(pngName).string());
        } else {
            return false;
        }
        im.src = rel(stem + ".png");
        writePng(im.src, display);
        if (display.width > thumbWidth) {
            im.thumb = rel("thumbs/" + stem + ".png");
            writePng(im.thumb, thumbnailOf(display, thumbWidth));
        } else {
            im.thumb = im.src;
        }
        return true;
    }

    void addError(SiteImage& owner, const std::string& pngName, double scale) {
        if (!plainFileName(pngName) || !fs::exists(source(pngName))) return;
        SiteImage e;
        e.id = owner.id + "_error";
        e.label = owner.label + ": error";
        e.group = "Error";
        e.src = rel(pngName);
        copyInto(source(pngName), target(e.src));
        e.thumb = e.src;
        e.errorScale = scale;
        e.record = owner.record;
        owner.errorId = e.id;
        out.images.push_back(e);
    }

    void addReferences() {
        const nlohmann::json& ref = in.results.value("reference", nlohmann::json::object());
        const std::string spp = ref.contains("spp") ? " (" + ref["spp"].dump() + " spp)" : "";
        struct RefKind {
            const char* stem;
            const char* label;
            const char* group;
            DisplayEncoding enc;
        };
        const RefKind kinds[] = {
            {"reference_ao", "reference AO", "AO", DisplayEncoding::AoAsStored},
            {"reference_gi", "reference indirect", "Indirect", DisplayEncoding::Radiance},
            {"reference_beauty", "reference beauty", "Beauty", DisplayEncoding::Radiance}};
        for (const RefKind& k : kinds) {
            SiteImage im;
            im.id = k.stem;
            im.label = std::string(k.label) + spp;
            im.group = k.group;
            if (addView(im, std::string(k.stem) + ".exr", std::string(k.stem) + ".png", k.enc))
                out.images.push_back(im);
            const std::string se = std::string(k.stem) + "_stderr.exr";
            if (fs::exists(source(se))) {
                copyInto(source(se), target(rel(se)));
                out.downloads.push_back({std::string(k.label) + " standard error (EXR)", rel(se)});
            }
        }
    }

    void addRecords() {
        const auto& records = in.results["records"];
        out.recordImage.assign(records.size(), -1);
        for (size_t r = 0; r < records.size(); ++r) {
            const nlohmann::json& rec = records[r];
            if (!rec.contains("images") || !rec["images"].is_object()) continue;
            const nlohmann::json& imgs = rec["images"];
            const bool isAo = rec.value("kind", "ao") == "ao";
            SiteImage im;
            im.record = int(r);
            im.label = recordLabel(rec, false);
            im.group = isAo ? "AO" : "Indirect";
            const std::string exr = imgs.value("exr", ""), png = imgs.value("png", "");
            im.id = fs::path(!exr.empty() ? exr : png).stem().string();
            if (im.id.empty() || out.image(im.id)) continue;
            if (!addView(im, exr, png, isAo ? DisplayEncoding::AoAsStored : DisplayEncoding::Radiance))
                continue;
            out.recordImage[r] = int(out.images.size());
            out.images.push_back(im);
            addError(out.images.back(), imgs.value("error_png", ""), jsonNumber(imgs, "error_scale"));
            // Extra versions a record may carry (e.g. "beauty_exr"): shown, not scored here.
            for (auto it = imgs.begin(); it != imgs.end(); ++it) {
                const std::string key = it.key();
                if (key.size() <= 4 || key.substr(key.size() - 4) != "_exr" || !it->is_string()) continue;
                const std::string what = key.substr(0, key.size() - 4);
                SiteImage extra;
                extra.record = int(r);
                extra.id = fs::path(it->get<std::string>()).stem().string();
                extra.label = recordLabel(rec, false) + " (" + what + ")";
                extra.group = what == "beauty" ? "Beauty" : what == "ao" ? "AO" : "Indirect";
                if (!extra.id.empty() && !out.image(extra.id) &&
                    addView(extra, it->get<std::string>(), imgs.value(what + "_png", ""),
                            what == "ao" ? DisplayEncoding::AoAsStored : DisplayEncoding::Radiance))
                    out.images.push_back(extra);
            }
        }
    }

    void addMasksAndData() {
        // The AO ROI, else the GI one (a comparison of GI methods alone writes only roi_gi.png).
        for (const char* name : {"roi.png", "roi_gi.png"}) {
            if (!fs::exists(source(name))) continue;
            out.roiMask = rel(name);
            copyInto(source(name), target(out.roiMask));
            out.roiOutline = rel("roi_outline.png");
            writePng(out.roiOutline, roiOutline(readImage(source(name).string())));
            break;
        }
        if (fs::exists(source("error_legend.png"))) {
            out.legend = rel("error_legend.png");
            copyInto(source("error_legend.png"), target(out.legend));
        } else {
            // A site made from results without a legend still gets one (same ramp as the maps).
            out.legend = rel("error_legend.png");
            writePng(out.legend, falseColorLegend(256, 16, 1.0));
        }
        if (fs::exists(source("valid.png"))) {
            out.validMask = rel("valid.png");
            copyInto(source("valid.png"), target(out.validMask));
        }
        for (const char* name : {"results.json", "results.csv"})
            if (fs::exists(source(name))) {
                copyInto(source(name), target(rel(name)));
                out.downloads.insert(out.downloads.begin(), {name, rel(name)});
            }
    }
};

}  // namespace

SiteCase buildSiteCase(const GalleryInput& input, const std::string& siteDir, int thumbnailWidth,
                       int& imageCount) {
    CaseWriter w{input, fs::path(siteDir), "data/" + input.id, thumbnailWidth, imageCount, {}};
    w.out.input = input;
    w.out.page = input.id + ".html";
    w.out.dataDir = w.dataDir;
    fs::create_directories(w.target(w.dataDir + "/thumbs"));
    w.addReferences();
    w.addRecords();
    w.addMasksAndData();
    return w.out;
}

}  // namespace vct
