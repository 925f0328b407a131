// <case>.html: the comparison page of one case. A viewer shows two images A and B split by a
// draggable line (or flipped), beside the false-colour error map, all at one synchronized
// zoom and pan (gallery.js); then the error-against-time plots, the records, every error map
// and the case's metadata. All image URLs are static attributes, so the site can be checked
// by reading the HTML.
#include "gallery/error_time_plot.h"
#include "gallery/html.h"
#include "gallery/scene_credits.h"
#include "gallery/site_model.h"

#include <cmath>
#include <set>
#include <sstream>

namespace vct {

namespace {

const char* kGroups[] = {"AO", "Indirect", "Beauty", "Error"};

std::string optionTag(const SiteCase& c, const SiteImage& im, const std::string& selectedId) {
    std::ostringstream s;
    s << "<option value=\"" << escapeHtml(im.id) << "\" data-group=\"" << im.group << "\" data-src=\""
      << encodeUrlPath(im.src) << "\"";
    if (const SiteImage* e = im.errorId.empty() ? nullptr : c.image(im.errorId))
        s << " data-error=\"" << escapeHtml(e->id) << "\" data-error-src=\"" << encodeUrlPath(e->src)
          << "\" data-error-scale=\"" << formatNumber(e->errorScale, 6) << "\"";
    if (im.group == "Error")
        s << " data-error-src=\"" << encodeUrlPath(im.src) << "\" data-error-scale=\""
          << formatNumber(im.errorScale, 6) << "\"";
    s << (im.id == selectedId ? " selected" : "") << ">" << escapeHtml(im.label) << "</option>";
    return s.str();
}

std::string imageSelect(const SiteCase& c, const std::string& id, const std::string& selectedId) {
    std::ostringstream s;
    s << "<select id=\"" << id << "\">";
    for (const char* g : kGroups) {
        bool open = false;
        for (const auto& im : c.images) {
            if (im.group != g) continue;
            if (!open) s << "<optgroup label=\"" << g << (std::string(g) == "Error" ? " maps" : "") << "\">";
            open = true;
            s << optionTag(c, im, selectedId);
        }
        if (open) s << "</optgroup>";
    }
    s << "</select>";
    return s.str();
}

std::string viewerSection(const SiteCase& c, const SiteImage* a, const SiteImage* b) {
    const int W = c.input.results.value("width", 0), H = c.input.results.value("height", 0);
    const SiteImage* err = nullptr;
    if (b && !b->errorId.empty()) err = c.image(b->errorId);
    std::ostringstream s;
    // decoding="sync": a state change (a new A or B, a followed link) paints the new image in the
    // frame that shows it, never the previous one or an empty layer while a decoder thread runs.
    auto img = [&](const char* id, const SiteImage* im, const char* alt) {
        s << "<img class=\"px\" id=\"" << id << "\" src=\"" << (im ? encodeUrlPath(im->src) : "")
          << "\" width=\"" << W << "\" height=\"" << H << "\" alt=\"" << alt
          << "\" decoding=\"sync\" draggable=\"false\">";
    };
    s << "<section class=\"compare\" id=\"compare\">\n<h2>Compare</h2>\n<div class=\"controls\">\n"
      << "<label>A (left) " << imageSelect(c, "sel-a", a ? a->id : "") << "</label>\n"
      << "<label>B (right) " << imageSelect(c, "sel-b", b ? b->id : "") << "</label>\n"
      << "<span class=\"group\"><button type=\"button\" id=\"btn-mode-slider\" "
         "class=\"active\">slider</button>"
      << "<button type=\"button\" id=\"btn-mode-flip\">flip</button>"
      << "<button type=\"button\" id=\"btn-flip\" title=\"show the other image (key F)\">A &harr; B "
         "(F)</button>"
      << "</span>\n<span class=\"group\"><button type=\"button\" id=\"btn-fit\" title=\"key 0\">fit</button>"
      << "<button type=\"button\" id=\"btn-1x\" title=\"one image pixel per screen pixel (key "
         "1)\">1:1</button>"
      << "<button type=\"button\" id=\"btn-zoom-in\" title=\"key +\">+</button>"
      << "<button type=\"button\" id=\"btn-zoom-out\" title=\"key -\">&minus;</button></span>\n";
    if (!c.roiOutline.empty())
        s << "<label class=\"group\"><input type=\"checkbox\" id=\"chk-roi\"> ROI outline (R)</label>\n";
    s << "<span class=\"readout\" id=\"zoom-readout\"></span> <span class=\"readout\" "
         "id=\"pixel-readout\"></span>\n"
      << "</div>\n<input type=\"range\" id=\"slider-range\" min=\"0\" max=\"1000\" value=\"500\" "
         "aria-label=\"split position\">\n<div class=\"views\">\n<figure class=\"view-fig\">\n"
      << "<div class=\"viewport\" id=\"view-main\" data-w=\"" << W << "\" data-h=\"" << H
      << "\" style=\"aspect-ratio: " << W << " / " << H << "\">\n<div class=\"layer\" id=\"layer-a\">";
    img("img-a", a, "image A");
    s << "</div>\n<div class=\"layer\" id=\"layer-b\">";
    img("img-b", b, "image B");
    s << "</div>\n";
    if (!c.roiOutline.empty()) {
        s << "<div class=\"layer overlay roi-layer\" hidden><img class=\"px\" src=\""
          << encodeUrlPath(c.roiOutline) << "\" width=\"" << W << "\" height=\"" << H
          << "\" alt=\"ROI outline\" decoding=\"sync\" draggable=\"false\"></div>\n";
    }
    s << "<div class=\"split\" id=\"split\"><div class=\"knob\"></div></div>\n"
      << "<span class=\"tag tag-a\" id=\"tag-a\">" << (a ? escapeHtml(a->label) : "") << "</span>"
      << "<span class=\"tag tag-b\" id=\"tag-b\">" << (b ? escapeHtml(b->label) : "") << "</span>\n</div>\n"
      << "<figcaption>Drag the line to move the split; drag elsewhere to pan; wheel to zoom (about the "
         "cursor); double-click to fit. Keys: F flip, S slider, R ROI, 0 fit, 1 1:1, +/- zoom.</figcaption>\n"
      << "</figure>\n<figure class=\"view-fig\">\n<div class=\"viewport\" id=\"view-error\" "
         "style=\"aspect-ratio: "
      << W << " / " << H << "\">\n<div class=\"layer\">";
    img("img-err", err, "error map");
    s << "</div>\n";
    if (!c.roiOutline.empty())
        s << "<div class=\"layer overlay roi-layer\" hidden><img class=\"px\" src=\""
          << encodeUrlPath(c.roiOutline) << "\" width=\"" << W << "\" height=\"" << H
          << "\" alt=\"ROI outline\" decoding=\"sync\" draggable=\"false\"></div>\n";
    s << "<span class=\"tag tag-a\" id=\"err-title\">" << (err ? escapeHtml(err->label) : "no error map")
      << "</span>\n"
      << "</div>\n<figcaption><div class=\"legend\"><img src=\"" << encodeUrlPath(c.legend)
      << "\" alt=\"error colour scale\"><div class=\"legend-labels\"><span id=\"leg-lo\">&minus;"
      << (err ? formatNumber(err->errorScale) : "") << "</span><span>0</span><span id=\"leg-hi\">+"
      << (err ? formatNumber(err->errorScale) : "")
      << "</span></div></div>Signed error, method &minus; reference: blue too dark, red too bright, grey not "
         "scored. Same zoom and pan as the comparison.</figcaption>\n</figure>\n</div>\n</section>\n";
    return s.str();
}

std::string plotsSection(const SiteCase& c) {
    const auto& records = c.input.results["records"];
    std::ostringstream s;
    s << "<section class=\"plots\">\n<h2>Error against time</h2>\n<p class=\"small\">Median time per frame "
         "on "
      << escapeHtml(c.input.results.value("gl_renderer", std::string("?")))
      << " (log axis) against the error to the reference. The dashed staircase is the Pareto front: no other "
         "variant is both faster and more accurate than a ringed point. Click a point to show it in the "
         "viewer.</p>\n<div class=\"plot-row\">\n";
    struct Plot {
        const char* kind;
        const char* key;
        const char* title;
    };
    const Plot plots[] = {{"ao", "rmse", "AO RMSE (valid pixels)"},
                          {"ao", "roi_rmse", "AO RMSE inside the ROI"},
                          {"gi", "rmse", "indirect radiance RMSE"},
                          {"gi", "roi_rmse", "indirect radiance RMSE inside the ROI"}};
    int written = 0;
    for (const Plot& p : plots) {
        std::vector<PlotPoint> points;
        for (size_t i = 0; i < records.size(); ++i) {
            const auto& r = records[i];
            if (r.value("kind", "ao") != p.kind) continue;
            PlotPoint pt;
            pt.label = recordLabel(r, false);
            pt.timeMs = jsonNumber(r, "time_ms");
            pt.error = jsonNumber(r, p.key);
            pt.group = r.value("method", pt.label);
            if (c.recordImage[i] >= 0) pt.href = "#b=" + c.images[c.recordImage[i]].id;
            if (std::isfinite(pt.error)) points.push_back(pt);
        }
        if (points.empty()) continue;
        PlotStyle style;
        style.errorLabel = p.title;
        style.id = std::string("plot-") + p.kind + "-" + p.key;
        s << "<figure>" << errorTimeSvg(points, style) << "<figcaption>" << escapeHtml(p.title)
          << " against time</figcaption></figure>\n";
        ++written;
    }
    if (!written) s << "<p>No timed, scored records.</p>\n";
    s << "</div>\n</section>\n";
    return s.str();
}

std::string recordsSection(const SiteCase& c) {
    const auto& records = c.input.results["records"];
    std::ostringstream s;
    s << "<section>\n<h2>Results</h2>\n<table class=\"records sortable\" id=\"records\">\n<thead><tr>"
      << "<th data-type=\"text\">variant</th><th data-type=\"text\">kind</th><th "
         "data-type=\"text\">parameters</th>"
      << "<th data-type=\"num\">time (ms)</th><th data-type=\"text\">passes (ms)</th><th "
         "data-type=\"num\">RMSE</th>"
      << "<th data-type=\"num\">ROI RMSE</th><th data-type=\"num\">non-ROI RMSE</th><th "
         "data-type=\"num\">MAE</th>"
      << "<th data-type=\"num\">bias</th><th data-type=\"num\">max |e|</th><th data-type=\"num\">PSNR "
         "(dB)</th>"
      << "<th data-type=\"num\">SSIM</th><th data-type=\"text\">files</th></tr></thead>\n<tbody>\n";
    for (size_t i = 0; i < records.size(); ++i) {
        const auto& r = records[i];
        const int im = c.recordImage[i];
        s << "<tr><td>";
        if (im >= 0)
            s << "<a href=\"#b=" << escapeHtml(c.images[im].id) << "\">" << escapeHtml(recordLabel(r, false))
              << "</a>";
        else
            s << escapeHtml(recordLabel(r, false));
        s << "</td><td>" << escapeHtml(r.value("kind", "ao")) << "</td><td class=\"params\">";
        if (r.contains("params") && r["params"].is_object() && !r["params"].empty()) {
            for (auto it = r["params"].begin(); it != r["params"].end(); ++it)
                s << "<code>" << escapeHtml(it.key()) << "="
                  << escapeHtml(it->is_string() ? it->get<std::string>() : it->dump()) << "</code> ";
        } else {
            s << "defaults";
        }
        const double t = jsonNumber(r, "time_ms");
        s << "</td><td class=\"num\" data-value=\"" << (std::isfinite(t) ? formatNumber(t, 9) : "") << "\">"
          << formatNumber(t) << "</td><td class=\"passes\">";
        if (r.contains("passes") && r["passes"].is_object())
            for (auto it = r["passes"].begin(); it != r["passes"].end(); ++it)
                s << escapeHtml(it.key()) << " "
                  << (it->is_number() ? formatNumber(it->get<double>(), 3) : "?") << "<br>";
        s << "</td>";
        for (const char* key :
             {"rmse", "roi_rmse", "nonroi_rmse", "mae", "bias", "max_abs", "psnr", "ssim"}) {
            const double v = jsonNumber(r, key);
            s << "<td class=\"num\" data-value=\"" << (std::isfinite(v) ? formatNumber(v, 9) : "") << "\">"
              << formatNumber(v) << "</td>";
        }
        s << "<td class=\"files\">";
        if (im >= 0) {
            const SiteImage& img = c.images[im];
            s << "<a href=\"" << encodeUrlPath(img.src) << "\">PNG</a>";
            if (!img.exr.empty()) s << " <a href=\"" << encodeUrlPath(img.exr) << "\" download>EXR</a>";
            if (const SiteImage* e = img.errorId.empty() ? nullptr : c.image(img.errorId))
                s << " <a href=\"" << encodeUrlPath(e->src) << "\">error</a>";
        }
        s << "</td></tr>\n";
    }
    s << "</tbody></table>\n</section>\n";
    return s.str();
}

std::string errorMapsSection(const SiteCase& c) {
    std::ostringstream s;
    bool any = false;
    for (const auto& im : c.images) any = any || im.group == "Error";
    if (!any) return "";
    s << "<section>\n<h2>Error maps</h2>\n<p class=\"small\">Signed error against the reference, saturating "
         "at "
         "&plusmn;scale (below each map). Click a map to compare its image with the reference.</p>\n"
      << "<div class=\"tiles\">\n";
    for (const auto& im : c.images) {
        if (im.group != "Error") continue;
        std::string owner;
        for (const auto& o : c.images)
            if (o.errorId == im.id) owner = o.id;
        s << "<figure class=\"tile\"><a href=\"#b=" << escapeHtml(owner) << "\"><img class=\"px\" src=\""
          << encodeUrlPath(im.src) << "\" alt=\"" << escapeHtml(im.label) << "\"></a><figcaption>"
          << escapeHtml(im.label) << "<br>scale &plusmn;" << formatNumber(im.errorScale)
          << "</figcaption></figure>\n";
    }
    s << "</div>\n</section>\n";
    return s.str();
}

std::string vec3(const nlohmann::json& j) {
    if (!j.is_array()) return j.dump();
    std::string out = "(";
    for (size_t i = 0; i < j.size(); ++i)
        out += (i ? ", " : "") + (j[i].is_number() ? formatNumber(j[i].get<double>(), 4) : j[i].dump());
    return out + ")";
}

std::string metadataSection(const SiteCase& c, const std::string& generated) {
    const auto& d = c.input.results;
    std::ostringstream s;
    auto row = [&](const std::string& k, const std::string& v) {
        s << "<tr><th>" << escapeHtml(k) << "</th><td>" << escapeHtml(v) << "</td></tr>\n";
    };
    auto num = [&](const char* key) { return formatNumber(jsonNumber(d, key), 6); };
    s << "<section class=\"meta\" id=\"metadata\">\n<h2>Metadata</h2>\n<table class=\"kv\">\n";
    const std::string scene = d.value("scene", std::string("?"));
    row("scene", scene);
    row("scene credit", sceneCredit(scene));
    row("results directory", c.input.dir);
    row("resolution",
        std::to_string(d.value("width", 0)) + " x " + std::to_string(d.value("height", 0)) + " px");
    if (d.contains("camera") && d["camera"].is_object()) {
        const auto& cam = d["camera"];
        row("camera", "eye " + vec3(cam.value("eye", nlohmann::json())) + ", target " +
                          vec3(cam.value("target", nlohmann::json())) + ", vertical fov " +
                          formatNumber(jsonNumber(cam, "fov_deg"), 4) + " deg");
    }
    row("AO radius R", num("radius"));
    std::set<std::string> shown = {"scene",
                                   "width",
                                   "height",
                                   "camera",
                                   "radius",
                                   "records",
                                   "reference",
                                   "gl_renderer",
                                   "cores",
                                   "roi_pixels",
                                   "roi_pixels_gi",
                                   "offscreen_occluders"};
    if (d.contains("reference") && d["reference"].is_object()) {
        std::string ref;
        for (auto it = d["reference"].begin(); it != d["reference"].end(); ++it)
            ref += (ref.empty() ? "" : ", ") + it.key() + " " +
                   (it->is_number() ? formatNumber(it->get<double>(), 4) : it->dump());
        row("reference (ray traced)", ref);
    }
    if (d.contains("roi_pixels") && !d["roi_pixels"].is_null())
        row("ROI (off-screen occluders)", d["roi_pixels"].dump() +
                                              " pixels where removing the off-screen occluders "
                                              "changes the reference AO by more than 3 standard errors");
    else
        row("ROI (off-screen occluders)", "none: the scene has no off-screen occluders");
    if (d.contains("roi_pixels_gi") && !d["roi_pixels_gi"].is_null())
        row("GI ROI (off-screen surfaces)", d["roi_pixels_gi"].dump() +
                                                " pixels where removing the off-screen surfaces changes the "
                                                "reference's indirect light by more than 3 standard errors");
    row("GL renderer", d.value("gl_renderer", std::string("?")));
    row("CPU cores", d.contains("cores") ? d["cores"].dump() : "?");
    for (auto it = d.begin(); it != d.end(); ++it)  // whatever else the comparison recorded
        if (!shown.count(it.key()))
            row(it.key(), it->is_number_float() ? formatNumber(it->get<double>(), 6) : it->dump());
    row("measured",
        c.input.measuredDate.empty() ? "unknown" : c.input.measuredDate + " (results.json written)");
    row("page generated", generated);
    s << "</table>\n<h3>Downloads</h3>\n<ul class=\"downloads\">\n";
    for (const auto& [label, path] : c.downloads)
        s << "<li><a href=\"" << encodeUrlPath(path) << "\" download>" << escapeHtml(label) << "</a></li>\n";
    for (const auto& im : c.images)
        if (!im.exr.empty() && im.record < 0)
            s << "<li><a href=\"" << encodeUrlPath(im.exr) << "\" download>" << escapeHtml(im.label)
              << " (EXR)</a></li>\n";
    if (!c.roiMask.empty())
        s << "<li><a href=\"" << encodeUrlPath(c.roiMask) << "\">ROI mask (PNG, 0/1)</a></li>\n";
    if (!c.validMask.empty())
        s << "<li><a href=\"" << encodeUrlPath(c.validMask) << "\">valid-pixel mask (PNG, 0/1)</a></li>\n";
    s << "</ul>\n</section>\n";
    return s.str();
}

}  // namespace

std::string scenePage(const SiteCase& c, const std::vector<SiteCase>& all, const std::string& generated) {
    // Default view: the reference against the first method that has an image.
    const SiteImage* a = nullptr;
    const SiteImage* b = nullptr;
    for (const auto& im : c.images)
        if (im.record >= 0 && im.group != "Error") {
            b = &im;
            break;
        }
    const std::string refId = b && b->group == "Indirect" ? "reference_gi" : "reference_ao";
    a = c.image(refId);
    if (!a)
        for (const auto& im : c.images)
            if (im.record < 0) {
                a = &im;
                break;
            }
    if (!a) a = b;
    if (!b) b = a;

    std::ostringstream s;
    s << pageHead(c.input.title + " - vct gallery")
      << "<body class=\"scene-page\">\n<header><nav><a href=\"index.html\">"
      << "&larr; all cases</a>";
    for (const auto& other : all)
        if (other.page != c.page)
            s << " &middot; <a href=\"" << encodeUrlPath(other.page) << "\">" << escapeHtml(other.input.title)
              << "</a>";
    const auto& d = c.input.results;
    s << "</nav>\n<h1>" << escapeHtml(c.input.title) << "</h1>\n<p class=\"summary\"><code>"
      << escapeHtml(d.value("scene", std::string("?"))) << "</code> &middot; " << d.value("width", 0)
      << "&times;" << d.value("height", 0) << " px &middot; R = " << formatNumber(jsonNumber(d, "radius"))
      << " &middot; " << escapeHtml(d.value("gl_renderer", std::string("?"))) << " &middot; measured "
      << escapeHtml(c.input.measuredDate.empty() ? "?" : c.input.measuredDate)
      << " &middot; <a href=\"#metadata\">"
      << "all metadata</a></p>\n</header>\n";
    s << viewerSection(c, a, b) << plotsSection(c) << recordsSection(c) << errorMapsSection(c)
      << metadataSection(c, generated) << pageFooter({&c}, generated) << "</body>\n</html>\n";
    return s.str();
}

}  // namespace vct
