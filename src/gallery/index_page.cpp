// index.html: a scenes x methods grid of thumbnails with time and error, whose method columns
// can be ordered by mean error rank or mean time rank, and a sortable table of every record.
#include "gallery/html.h"
#include "gallery/site_model.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

namespace vct {

namespace {

struct Column {
    std::string key;  // "ao: gtao"
    double errorRankSum = 0, timeRankSum = 0;
    int rows = 0;
    int order = 0;  // first appearance
};

// Rank (0 = best) of values[i] among the finite values of a row, normalized to [0, 1].
std::vector<double> normalizedRanks(const std::vector<double>& values) {
    std::vector<double> ranks(values.size(), std::nan(""));
    std::vector<size_t> idx;
    for (size_t i = 0; i < values.size(); ++i)
        if (std::isfinite(values[i])) idx.push_back(i);
    std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    for (size_t k = 0; k < idx.size(); ++k)
        ranks[idx[k]] = idx.size() > 1 ? double(k) / (idx.size() - 1) : 0.0;
    return ranks;
}

std::string numAttr(double v) { return std::isfinite(v) ? formatNumber(v, 9) : ""; }

using Cases = std::vector<std::reference_wrapper<const SiteCase>>;

// One tile per sequence (its reference's first frame, linking to its page) and a table of every
// sequence record: the sequence's own scores, mean and worst RMSE, instability, frame cost.
std::string sequencesSection(const Cases& sequences) {
    if (sequences.empty()) return "";
    std::ostringstream s;
    s << "<section>\n<h2>Sequences</h2>\n<p class=\"small\">Comparisons along a camera path: each page plays "
         "every method's frames beside the reference's, with per-frame error and temporal instability.</p>\n"
      << "<div class=\"tiles\">\n";
    for (const SiteCase& c : sequences) {
        s << "<figure class=\"tile\"><a href=\"" << encodeUrlPath(c.page) << "\">";
        if (!c.sequenceThumb.empty())
            s << "<img src=\"" << encodeUrlPath(c.sequenceThumb) << "\" alt=\"" << escapeHtml(c.input.title)
              << "\">";
        s << escapeHtml(c.input.title) << "</a><figcaption>" << c.input.results["frames"].dump()
          << " frames, " << c.input.results.value("width", 0) << "&times;"
          << c.input.results.value("height", 0) << "</figcaption></figure>\n";
    }
    s << "</div>\n<table class=\"records sortable\" id=\"sequence-records\">\n<thead><tr>"
      << "<th data-type=\"text\">sequence</th><th data-type=\"text\">kind</th>"
      << "<th data-type=\"text\">method</th>"
      << "<th data-type=\"num\">frames</th><th data-type=\"num\">RMSE mean</th><th data-type=\"num\">RMSE "
         "worst</th><th data-type=\"num\">instability</th><th data-type=\"num\">frame (ms)</th>"
      << "<th data-type=\"num\">time (ms)</th></tr></thead>\n<tbody>\n";
    for (const SiteCase& c : sequences) {
        const auto& records = c.input.results["records"];
        for (size_t i = 0; i < records.size(); ++i) {
            const auto& r = records[i];
            const std::string href =
                encodeUrlPath(c.page) + (c.recordFrames[i].empty() ? "" : "#rec-" + std::to_string(i));
            s << "<tr><td><a href=\"" << href << "\">" << escapeHtml(c.input.title) << "</a></td><td>"
              << escapeHtml(r.value("kind", "ao")) << "</td><td>" << escapeHtml(recordLabel(r, false))
              << "</td><td class=\"num\" data-value=\"" << c.input.results["frames"].dump() << "\">"
              << c.input.results["frames"].dump() << "</td>";
            for (const char* key : {"rmse_mean", "rmse_worst", "instability", "frame_ms", "time_ms"}) {
                const double v = jsonNumber(r, key);
                s << "<td class=\"num\" data-value=\"" << numAttr(v) << "\">" << formatNumber(v) << "</td>";
            }
            s << "</tr>\n";
        }
    }
    s << "</tbody></table>\n</section>\n";
    return s.str();
}

// The scenes x methods grid and the table of every record of the still comparisons.
std::string stillSections(const Cases& cases, const std::vector<Column>& columns,
                          std::map<std::string, size_t>& columnOf, bool withKind) {
    std::ostringstream s;
    // The grid.
    s << "<section>\n<h2>Scenes &times; methods</h2>\n<div class=\"sortbar\">Order method columns by: "
      << "<button type=\"button\" data-order=\"run\" class=\"active\">run order</button> "
      << "<button type=\"button\" data-order=\"error\">error (mean rank)</button> "
      << "<button type=\"button\" data-order=\"time\">time (mean rank)</button></div>\n"
      << "<div class=\"grid-wrap\"><table class=\"grid\" id=\"grid\">\n<thead><tr><th "
         "class=\"scene-col\">scene / "
         "reference</th>";
    for (const Column& col : columns) {
        const double n = std::max(1, col.rows);
        s << "<th data-col=\"" << col.order << "\" data-run=\"" << col.order << "\" data-error=\""
          << formatNumber(col.errorRankSum / n, 6) << "\" data-time=\""
          << formatNumber(col.timeRankSum / n, 6) << "\">" << escapeHtml(col.key) << "</th>";
    }
    s << "</tr></thead>\n<tbody>\n";
    for (const SiteCase& c : cases) {
        const auto& records = c.input.results["records"];
        s << "<tr><th class=\"scene-col\"><a href=\"" << encodeUrlPath(c.page) << "\">"
          << escapeHtml(c.input.title) << "</a>";
        for (const char* refId : {"reference_ao", "reference_gi"})
            if (const SiteImage* ref = c.image(refId))
                s << "<a class=\"thumb\" href=\"" << encodeUrlPath(c.page) << "#b=" << ref->id
                  << "\"><img src=\"" << encodeUrlPath(ref->thumb) << "\" alt=\"" << escapeHtml(ref->label)
                  << "\" title=\"" << escapeHtml(ref->label) << "\"></a>";
        s << "<div class=\"small\">" << c.input.results.value("width", 0) << "&times;"
          << c.input.results.value("height", 0)
          << ", R = " << formatNumber(jsonNumber(c.input.results, "radius")) << "</div></th>";
        // Best error and time of the row per kind, for highlighting.
        std::map<std::string, double> bestErrOf, bestTimeOf;
        for (const auto& r : records) {
            const std::string kind = r.value("kind", "ao");
            double e = jsonNumber(r, "rmse"), t = jsonNumber(r, "time_ms");
            if (!bestErrOf.count(kind)) bestErrOf[kind] = INFINITY, bestTimeOf[kind] = INFINITY;
            if (std::isfinite(e)) bestErrOf[kind] = std::min(bestErrOf[kind], e);
            if (std::isfinite(t)) bestTimeOf[kind] = std::min(bestTimeOf[kind], t);
        }
        std::vector<std::string> cells(columns.size(), "");
        for (size_t i = 0; i < records.size(); ++i) {
            const auto& r = records[i];
            const size_t col = columnOf[recordLabel(r, withKind)];
            const double bestErr = bestErrOf[r.value("kind", "ao")], bestTime = bestTimeOf[r.value("kind", "ao")];
            if (!cells[col].empty()) continue;  // same label twice in a case: the first one
            std::ostringstream cell;
            const double e = jsonNumber(r, "rmse"), t = jsonNumber(r, "time_ms"),
                         roi = jsonNumber(r, "roi_rmse");
            const int im = c.recordImage[i];
            if (im >= 0) {
                const SiteImage& img = c.images[im];
                cell << "<a class=\"thumb\" href=\"" << encodeUrlPath(c.page) << "#b=" << img.id
                     << "\"><img src=\"" << encodeUrlPath(img.thumb) << "\" alt=\"" << escapeHtml(img.label)
                     << "\" title=\"" << escapeHtml(img.label) << "\"></a>";
            }
            cell << "<div class=\"nums\"><span class=\"time" << (t == bestTime ? " best" : "") << "\">"
                 << formatMs(t) << "</span><span class=\"err" << (e == bestErr ? " best" : "") << "\">RMSE "
                 << formatNumber(e) << "</span>";
            if (std::isfinite(roi)) cell << "<span class=\"roi\">ROI " << formatNumber(roi) << "</span>";
            cell << "</div>";
            cells[col] = cell.str();
        }
        for (size_t k = 0; k < columns.size(); ++k)
            s << "<td data-col=\"" << columns[k].order << "\">"
              << (cells[k].empty() ? "<span class=\"na\">&ndash;</span>" : cells[k]) << "</td>";
        s << "</tr>\n";
    }
    s << "</tbody></table></div>\n</section>\n";

    // Every record, sortable by any column.
    s << "<section>\n<h2>All results</h2>\n<p class=\"small\">Click a column header to sort.</p>\n"
      << "<table class=\"records sortable\" id=\"all-records\">\n<thead><tr>"
      << "<th data-type=\"text\">case</th><th data-type=\"text\">kind</th><th data-type=\"text\">method</th>"
      << "<th data-type=\"num\">time (ms)</th><th data-type=\"num\">frame (ms)</th><th data-type=\"num\">RMSE</th><th data-type=\"num\">ROI "
         "RMSE</th>"
      << "<th data-type=\"num\">non-ROI RMSE</th><th data-type=\"num\">MAE</th><th "
         "data-type=\"num\">bias</th>"
      << "<th data-type=\"num\">PSNR (dB)</th><th data-type=\"num\">SSIM</th>"
      << "<th data-type=\"num\">fetches / px</th><th data-type=\"num\">rays / px</th></tr></thead>\n<tbody>\n";
    for (const SiteCase& c : cases) {
        const auto& records = c.input.results["records"];
        for (size_t i = 0; i < records.size(); ++i) {
            const auto& r = records[i];
            const int im = c.recordImage[i];
            const std::string href = encodeUrlPath(c.page) + (im >= 0 ? "#b=" + c.images[im].id : "");
            s << "<tr><td><a href=\"" << href << "\">" << escapeHtml(c.input.title) << "</a></td><td>"
              << escapeHtml(r.value("kind", "ao")) << "</td><td>" << escapeHtml(recordLabel(r, false))
              << "</td>";
            for (const char* key :
                 {"time_ms", "frame_ms", "rmse", "roi_rmse", "nonroi_rmse", "mae", "bias", "psnr", "ssim"}) {
                const double v = jsonNumber(r, key);
                s << "<td class=\"num\" data-value=\"" << numAttr(v) << "\">" << formatNumber(v) << "</td>";
            }
            // Device-independent cost (eval/comparison.h): what carries to another GPU.
            const nlohmann::json cost = r.value("cost", nlohmann::json::object());
            for (const char* key : {"fetches_per_pixel", "rays_per_pixel"}) {
                const double v = jsonNumber(cost, key);
                s << "<td class=\"num\" data-value=\"" << numAttr(v) << "\">" << formatNumber(v) << "</td>";
            }
            s << "</tr>\n";
        }
    }
    s << "</tbody></table>\n</section>\n";
    return s.str();
}

}  // namespace

std::string indexPage(const std::vector<SiteCase>& allCases, const std::string& title,
                      const std::string& generated) {
    // Sequences get their own section: their records score frames along a path, not one image.
    Cases cases, sequences;
    for (const SiteCase& c : allCases) (c.input.sequence ? sequences : cases).push_back(c);
    bool anyGi = false, anyAo = false, anyRoi = false;
    for (const SiteCase& c : cases)
        for (const auto& r : c.input.results["records"])
            (r.value("kind", "ao") == "gi" ? anyGi : anyAo) = true;
    const bool withKind = anyGi && anyAo;
    // Columns and their mean ranks (error: rmse; time: time_ms) over the rows that have them.
    std::vector<Column> columns;
    std::map<std::string, size_t> columnOf;
    for (const SiteCase& c : cases) {
        const auto& records = c.input.results["records"];
        std::vector<double> err, time;
        std::vector<size_t> cols;
        for (const auto& r : records) {
            const std::string key = recordLabel(r, withKind);
            if (!columnOf.count(key)) {
                columnOf[key] = columns.size();
                columns.push_back({key, 0, 0, 0, int(columns.size())});
            }
            cols.push_back(columnOf[key]);
            err.push_back(jsonNumber(r, "rmse"));
            time.push_back(jsonNumber(r, "time_ms"));
        }
        // Ranks among the records of the same kind: AO and GI errors have different units.
        for (const char* kind : {"ao", "gi"}) {
            std::vector<double> kindErr(err.size(), std::nan("")), kindTime(time.size(), std::nan(""));
            for (size_t i = 0; i < records.size(); ++i)
                if (records[i].value("kind", "ao") == kind) kindErr[i] = err[i], kindTime[i] = time[i];
            const auto er = normalizedRanks(kindErr), tr = normalizedRanks(kindTime);
            for (size_t i = 0; i < cols.size(); ++i) {
                if (records[i].value("kind", "ao") != kind) continue;
                Column& col = columns[cols[i]];
                if (std::isfinite(er[i])) col.errorRankSum += er[i];
                if (std::isfinite(tr[i])) col.timeRankSum += tr[i];
                col.rows++;
            }
        }
        if (!c.roiOutline.empty()) anyRoi = true;
    }

    std::ostringstream s;
    s << pageHead(title) << "<body class=\"index\">\n<header><h1>" << escapeHtml(title) << "</h1>\n<p>";
    if (!cases.empty())
        s << cases.size() << " case(s), " << columns.size()
          << " method variant(s). Each thumbnail links to its comparison page; numbers are the median time "
             "per frame and the RMSE against the ray-traced reference on valid pixels"
          << (anyRoi ? " (ROI: RMSE inside the region darkened by off-screen occluders)" : "") << ".";
    if (!sequences.empty())
        s << (cases.empty() ? "" : " ") << sequences.size() << " sequence(s) along camera paths (below).";
    s << "</p>\n</header>\n";

    if (!cases.empty()) s << stillSections(cases, columns, columnOf, withKind);
    s << sequencesSection(sequences);
    std::vector<const SiteCase*> all;
    for (const SiteCase& c : allCases) all.push_back(&c);
    s << pageFooter(all, generated) << "</body>\n</html>\n";
    return s.str();
}

}  // namespace vct
