// <case>.html of a sequence comparison (`vct compare --path P --frames N`): every method's frames
// beside the reference's, playing in sync as a flipbook (one control bar: play/pause, a slider
// to scrub, the frame number); per-frame RMSE and instability plots whose marker follows the
// flipbook; the table of the sequence's scores with the reference's own instability; and the
// metadata. Every frame is a static <img src>, so the site can be checked by reading the HTML
// and plays offline; the small script inline reads everything it needs from the page's
// attributes, so no text from results.json ever lands inside <script>.
#include "gallery/frame_plot.h"
#include "gallery/html.h"
#include "gallery/scene_credits.h"
#include "gallery/site_model.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace vct {

namespace {

const char* const kKinds[] = {"ao", "gi"};

const char* kindTitle(const std::string& kind) {
    return kind == "gi" ? "Indirect light (GI)" : "Ambient occlusion (AO)";
}

std::string referenceLabel(const nlohmann::json& results, const std::string& kind) {
    const nlohmann::json ref = results.value("reference", nlohmann::json::object());
    const std::string spp = ref.contains("spp") ? " (" + ref["spp"].dump() + " spp)" : "";
    return std::string(kind == "gi" ? "reference indirect" : "reference AO") + spp;
}

// A per-frame array as numbers; null (a value the comparison could not compute) becomes NaN.
std::vector<double> numbersOf(const nlohmann::json& array) {
    std::vector<double> out;
    for (const auto& v : array) out.push_back(v.is_number() ? v.get<double>() : std::nan(""));
    return out;
}

bool hasKind(const nlohmann::json& records, const std::string& kind) {
    for (const auto& r : records)
        if (r.value("kind", "") == kind) return true;
    return false;
}

// The path's own rate, (N - 1) / duration frames per second (what a video of it plays at).
double pathFps(const nlohmann::json& results) {
    const auto& times = results.value("times", nlohmann::json::array());
    if (times.size() < 2 || !times.front().is_number() || !times.back().is_number()) return NAN;
    const double duration = times.back().get<double>() - times.front().get<double>();
    return duration > 0 ? double(times.size() - 1) / duration : NAN;
}

// One <img> per frame, all but the current one hidden: the browser loads every frame once, so
// playback never waits on the disk; decoding="sync" so a shown frame is never a stale one.
std::string frameStack(const std::vector<std::string>& frames, int W, int H, const std::string& alt) {
    std::ostringstream s;
    s << "<div class=\"seq-stack\" style=\"aspect-ratio: " << std::max(1, W) << " / " << std::max(1, H)
      << "\">";
    for (size_t f = 0; f < frames.size(); ++f)
        s << "<img class=\"px\" src=\"" << encodeUrlPath(frames[f]) << "\" width=\"" << W << "\" height=\""
          << H << "\" alt=\"" << escapeHtml(alt) << ", frame " << f << "\" data-frame=\"" << f << "\""
          << (f ? " hidden" : "") << " decoding=\"sync\">";
    s << "</div>";
    return s.str();
}

// Values the script shows for the current frame, space-separated in an attribute.
std::string perFrameAttr(const std::vector<double>& values) {
    std::string out;
    for (size_t i = 0; i < values.size(); ++i) out += (i ? " " : "") + formatNumber(values[i]);
    return out;
}

std::string controls(const SiteCase& c, int frames) {
    const double rate = pathFps(c.input.results);
    std::ostringstream s;
    s << "<div class=\"controls seq-controls\">\n"
      << "<button type=\"button\" id=\"seq-play\" aria-pressed=\"false\""
      << (frames < 2 ? " disabled" : "") << " title=\"key space\">play</button>"
      << "<button type=\"button\" id=\"seq-prev\" title=\"previous frame (key &larr;)\">&#9664;</button>"
      << "<button type=\"button\" id=\"seq-next\" title=\"next frame (key &rarr;)\">&#9654;</button>\n"
      << "<input type=\"range\" id=\"seq-frame\" min=\"0\" max=\"" << frames - 1
      << "\" step=\"1\" value=\"0\" aria-label=\"frame\">\n"
      << "<span class=\"readout\" id=\"seq-readout\">frame 0 / " << frames - 1 << "</span>\n"
      << "<label>speed <select id=\"seq-fps\">";
    bool selected = false;
    if (std::isfinite(rate)) {
        s << "<option value=\"" << formatNumber(rate, 6) << "\" selected>path rate (" << formatNumber(rate, 3)
          << " fps)</option>";
        selected = true;
    }
    for (int fps : {1, 2, 5, 10, 24, 30}) {
        s << "<option value=\"" << fps << "\"" << (!selected && fps == 5 ? " selected" : "") << ">" << fps
          << " fps</option>";
    }
    s << "</select></label>\n</div>\n";
    return s.str();
}

std::string flipbookSection(const SiteCase& c) {
    const auto& d = c.input.results;
    const auto& records = d["records"];
    const int frames = d["frames"].get<int>(), W = d.value("width", 0), H = d.value("height", 0);
    std::ostringstream s;
    s << "<section class=\"flipbook\" id=\"flipbook\" data-frames=\"" << frames << "\" data-times=\"";
    if (d.contains("times"))
        for (size_t i = 0; i < d["times"].size(); ++i)
            s << (i ? " " : "")
              << formatNumber(d["times"][i].is_number() ? d["times"][i].get<double>() : NAN, 4);
    s << "\">\n<h2>Frames</h2>\n<p class=\"small\">Each method's frames (left) beside the reference's at the "
         "same camera (right), all playing in sync. The frames are the PNGs <code>vct compare</code> wrote: "
         "AO as stored (clamped to [0, 1], no gamma), indirect light at exposure 0 EV through the sRGB "
         "transfer function, clamped. Keys: space play/pause, &larr; &rarr; step.</p>\n"
      << controls(c, frames);
    bool any = false;
    for (const char* kind : kKinds) {
        if (!c.referenceFrames.count(kind)) continue;
        const std::vector<std::string>& ref = c.referenceFrames.at(kind);
        s << "<h3>" << kindTitle(kind) << "</h3>\n";
        for (size_t i = 0; i < records.size(); ++i) {
            const auto& r = records[i];
            if (r.value("kind", "") != kind || c.recordFrames[i].empty()) continue;
            any = true;
            const std::string label = recordLabel(r, false);
            const nlohmann::json pf = r.value("per_frame", nlohmann::json::object());
            const std::vector<double> rmse = numbersOf(pf.value("rmse", nlohmann::json::array()));
            s << "<div class=\"seq-pair\" id=\"rec-" << i << "\">\n<figure class=\"seq-view\">"
              << frameStack(c.recordFrames[i], W, H, label) << "<figcaption><b>" << escapeHtml(label)
              << "</b> &middot; RMSE <span class=\"seq-value\" data-per-frame=\"" << perFrameAttr(rmse)
              << "\">" << formatNumber(rmse.empty() ? NAN : rmse[0]) << "</span></figcaption></figure>\n"
              << "<figure class=\"seq-view\">" << frameStack(ref, W, H, referenceLabel(d, kind))
              << "<figcaption>" << escapeHtml(referenceLabel(d, kind)) << "</figcaption></figure>\n</div>\n";
        }
    }
    if (!any) s << "<p>This comparison wrote no frames.</p>\n";
    s << "</section>\n";
    return s.str();
}

std::string plotsSection(const SiteCase& c) {
    const auto& d = c.input.results;
    const auto& records = d["records"];
    const nlohmann::json ref = d.value("reference", nlohmann::json::object());
    std::ostringstream s;
    s << "<section class=\"plots\">\n<h2>Per frame</h2>\n<p class=\"small\">RMSE against each frame's "
         "reference (valid pixels) and the temporal instability of each pair of consecutive frames: the RMS of the "
         "method's change from the previous frame minus the reference's, reprojected, with the reference's "
         "noise taken out (docs/sequences.md). The dashed line is the reference's own instability over the "
         "sequence; the red line marks the frame the flipbook shows. Click a plot to go to a frame.</p>\n"
      << "<div class=\"plot-row\">\n";
    for (const char* kind : kKinds) {
        if (!hasKind(records, kind)) continue;
        std::vector<FrameSeries> series;
        for (const auto& r : records) {
            if (r.value("kind", "") != kind) continue;
            const nlohmann::json pf = r.value("per_frame", nlohmann::json::object());
            series.push_back({recordLabel(r, false), numbersOf(pf.value("rmse", nlohmann::json::array())),
                              numbersOf(pf.value("instability", nlohmann::json::array()))});
        }
        FramePlotStyle style;
        style.id = std::string("plot-frames-") + kind;
        style.title = std::string(kindTitle(kind)) + ": RMSE and instability per frame";
        style.referenceInstability =
            jsonNumber(ref.value(std::string(kind) + "_temporal", nlohmann::json::object()), "instability");
        s << "<figure>" << perFrameSvg(series, d["frames"].get<int>(), style) << "<figcaption>"
          << kindTitle(kind) << "</figcaption></figure>\n";
    }
    s << "</div>\n</section>\n";
    return s.str();
}

std::string numCell(double v) {
    return "<td class=\"num\" data-value=\"" + (std::isfinite(v) ? formatNumber(v, 9) : "") + "\">" +
           formatNumber(v) + "</td>";
}

std::string tableSection(const SiteCase& c) {
    const auto& d = c.input.results;
    const auto& records = d["records"];
    const nlohmann::json ref = d.value("reference", nlohmann::json::object());
    std::ostringstream s;
    s << "<section>\n<h2>Results</h2>\n<p class=\"small\">RMSE: mean and worst over the frames. Instability "
         "and its resolution (below it, zero within the reference's noise), change RMS (the method's own change "
         "from frame to frame): over all frame pairs. Frame: median cost of frames 1.. as the sequence paid "
         "it; time: the cold cost of frame 0. Click a column header to sort.</p>\n"
      << "<table class=\"records sortable\" id=\"sequence-records\">\n<thead><tr>"
      << "<th data-type=\"text\">variant</th><th data-type=\"text\">kind</th>"
      << "<th data-type=\"num\">RMSE mean</th><th data-type=\"num\">RMSE worst</th>"
      << "<th data-type=\"num\">instability</th><th data-type=\"num\">resolution</th>"
      << "<th data-type=\"num\">change RMS</th><th data-type=\"num\">frame (ms)</th>"
      << "<th data-type=\"num\">time (ms)</th></tr></thead>\n<tbody>\n";
    for (size_t i = 0; i < records.size(); ++i) {
        const auto& r = records[i];
        const nlohmann::json temporal = r.value("temporal", nlohmann::json::object());
        double instability = jsonNumber(r, "instability");
        if (!std::isfinite(instability)) instability = jsonNumber(temporal, "instability");
        s << "<tr><td>";
        if (!c.recordFrames[i].empty())
            s << "<a href=\"#rec-" << i << "\">" << escapeHtml(recordLabel(r, false)) << "</a>";
        else
            s << escapeHtml(recordLabel(r, false));
        s << "</td><td>" << escapeHtml(r.value("kind", "")) << "</td>" << numCell(jsonNumber(r, "rmse_mean"))
          << numCell(jsonNumber(r, "rmse_worst")) << numCell(instability)
          << numCell(jsonNumber(temporal, "resolution")) << numCell(jsonNumber(temporal, "change_rms"))
          << numCell(jsonNumber(r, "frame_ms")) << numCell(jsonNumber(r, "time_ms")) << "</tr>\n";
    }
    s << "</tbody>\n<tfoot>\n";
    // The reference's own change beyond its noise (zero within resolution when the reprojection
    // is right): the floor the methods' instability is read against. In <tfoot>, so sorting
    // keeps it last.
    for (const char* kind : kKinds) {
        const std::string key = std::string(kind) + "_temporal";
        if (!ref.contains(key) || !ref[key].is_object()) continue;
        const nlohmann::json& t = ref[key];
        s << "<tr class=\"reference\"><td>" << escapeHtml(referenceLabel(d, kind)) << "</td><td>" << kind
          << "</td>" << numCell(NAN) << numCell(NAN) << numCell(jsonNumber(t, "instability"))
          << numCell(jsonNumber(t, "resolution")) << numCell(jsonNumber(t, "change_rms"))
          << numCell(jsonNumber(ref, (std::string(kind) + "_frame_ms").c_str())) << numCell(NAN) << "</tr>\n";
    }
    s << "</tfoot></table>\n</section>\n";
    return s.str();
}

std::string metadataSection(const SiteCase& c, const std::string& generated) {
    const auto& d = c.input.results;
    std::ostringstream s;
    auto row = [&](const std::string& k, const std::string& v) {
        s << "<tr><th>" << escapeHtml(k) << "</th><td>" << escapeHtml(v) << "</td></tr>\n";
    };
    s << "<section class=\"meta\" id=\"metadata\">\n<h2>Metadata</h2>\n<table class=\"kv\">\n";
    const std::string scene = d.value("scene", std::string("?"));
    row("scene", scene);
    row("scene credit", sceneCredit(scene));
    row("results directory", c.input.dir);
    row("resolution",
        std::to_string(d.value("width", 0)) + " x " + std::to_string(d.value("height", 0)) + " px");
    row("AO radius R", formatNumber(jsonNumber(d, "radius"), 6));
    if (d.contains("path") && d["path"].is_object()) {
        const auto& p = d["path"];
        const size_t keys = p.contains("keys") && p["keys"].is_array() ? p["keys"].size() : 0;
        row("camera path", p.value("source", std::string("?")) + ": " +
                               p.value("interpolation", std::string("?")) + ", " + std::to_string(keys) +
                               " key(s)");
    }
    row("frames", d["frames"].dump());
    if (d.contains("times")) {
        std::string times;
        for (const auto& t : d["times"])
            times += (times.empty() ? "" : ", ") + formatNumber(t.is_number() ? t.get<double>() : NAN, 4);
        row("frame times (s)", times);
    }
    if (d.contains("per_frame_seeds") && d["per_frame_seeds"].is_boolean())
        row("frame seeds", d["per_frame_seeds"].get<bool>() ? "per frame (each frame its own seed)"
                                                            : "fixed (every frame the same seed)");
    if (d.contains("reference") && d["reference"].contains("spp"))
        row("reference (ray traced)", d["reference"]["spp"].dump() + " samples per pixel, every frame");
    row("GL renderer", d.value("gl_renderer", std::string("?")));
    row("CPU cores", d.contains("cores") ? d["cores"].dump() : "?");
    const std::set<std::string> shown = {"scene",     "width",   "height",      "radius",
                                         "path",      "frames",  "times",       "per_frame_seeds",
                                         "reference", "records", "gl_renderer", "cores"};
    for (auto it = d.begin(); it != d.end(); ++it)  // whatever else the comparison recorded
        if (!shown.count(it.key()))
            row(it.key(), it->is_number_float() ? formatNumber(it->get<double>(), 6) : it->dump());
    row("measured",
        c.input.measuredDate.empty() ? "unknown" : c.input.measuredDate + " (results.json written)");
    row("page generated", generated);
    s << "</table>\n<h3>Downloads</h3>\n<ul class=\"downloads\">\n";
    for (const auto& [label, path] : c.downloads)
        s << "<li><a href=\"" << encodeUrlPath(path) << "\" download>" << escapeHtml(label) << "</a></li>\n";
    s << "</ul>\n</section>\n";
    return s.str();
}

const char* flipbookStyle() {
    return R"CSS(<style>
.seq-controls input[type=range] { flex: 1 1 240px; max-width: 520px; }
.seq-pair { display: flex; flex-wrap: wrap; gap: 12px; margin: 8px 0 14px; }
.seq-view { margin: 0; flex: 1 1 260px; max-width: 480px; }
.seq-stack { position: relative; width: 100%; background: #222; border: 1px solid #555; }
.seq-stack img { position: absolute; inset: 0; width: 100%; height: 100%; }
.seq-stack img[hidden] { display: none; }
.seq-value { font-variant-numeric: tabular-nums; }
svg.frame-plot { cursor: crosshair; }
tr.reference td { background: #f4f4f4; font-style: italic; }
table.kv td { overflow-wrap: anywhere; }
</style>
)CSS";
}

// The flipbook: one frame index drives every stack, the per-frame values, the plots' markers,
// the slider and the readout. Plain ES5, no network; gallery.js (sortable table) runs beside it.
const char* flipbookScript() {
    return R"JS(<script>
(function () {
  'use strict';
  var root = document.getElementById('flipbook');
  if (!root) return;
  function each(list, fn) { Array.prototype.forEach.call(list, fn); }
  var n = Math.max(1, parseInt(root.getAttribute('data-frames'), 10) || 1);
  var times = (root.getAttribute('data-times') || '').split(' ').filter(Boolean);
  var range = document.getElementById('seq-frame'), play = document.getElementById('seq-play');
  var fps = document.getElementById('seq-fps'), readout = document.getElementById('seq-readout');
  var frame = 0, timer = null;
  function show(f) {
    frame = ((f % n) + n) % n;
    each(document.querySelectorAll('.seq-stack'), function (stack) {
      each(stack.children, function (img) { img.hidden = parseInt(img.getAttribute('data-frame'), 10) !== frame; });
    });
    each(document.querySelectorAll('[data-per-frame]'), function (el) {
      el.textContent = el.getAttribute('data-per-frame').split(' ')[frame] || '\u2013';
    });
    each(document.querySelectorAll('svg.frame-plot'), function (svg) {
      var x = parseFloat(svg.getAttribute('data-x0')) + frame * parseFloat(svg.getAttribute('data-dx'));
      each(svg.querySelectorAll('.frame-marker'), function (m) { m.setAttribute('x1', x); m.setAttribute('x2', x); });
    });
    range.value = frame;
    readout.textContent = 'frame ' + frame + ' / ' + (n - 1) + (times[frame] ? ' \u00b7 t = ' + times[frame] + ' s' : '');
    root.setAttribute('data-frame', frame);
  }
  function stop() {
    if (timer) clearInterval(timer);
    timer = null;
    play.textContent = 'play';
    play.setAttribute('aria-pressed', 'false');
  }
  function start() {
    stop();
    if (n < 2) return;
    timer = setInterval(function () { show(frame + 1); }, 1000 / Math.max(0.1, parseFloat(fps.value) || 5));
    play.textContent = 'pause';
    play.setAttribute('aria-pressed', 'true');
  }
  play.addEventListener('click', function () { if (timer) stop(); else start(); });
  fps.addEventListener('change', function () { if (timer) start(); });
  range.addEventListener('input', function () { stop(); show(parseInt(range.value, 10) || 0); });
  document.getElementById('seq-prev').addEventListener('click', function () { stop(); show(frame - 1); });
  document.getElementById('seq-next').addEventListener('click', function () { stop(); show(frame + 1); });
  // A click on a plot goes to the frame under the pointer (viewBox units: the SVG may be scaled).
  each(document.querySelectorAll('svg.frame-plot'), function (svg) {
    svg.addEventListener('click', function (ev) {
      var box = svg.getBoundingClientRect(), vb = svg.viewBox.baseVal;
      var x = (ev.clientX - box.left) * (vb && vb.width ? vb.width / box.width : 1);
      var f = Math.round((x - parseFloat(svg.getAttribute('data-x0'))) / parseFloat(svg.getAttribute('data-dx')));
      stop();
      show(Math.min(n - 1, Math.max(0, f)));
    });
  });
  document.addEventListener('keydown', function (ev) {
    var tag = ev.target && ev.target.tagName;
    if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA' || tag === 'BUTTON' || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    if (ev.key === ' ') { if (timer) stop(); else start(); }
    else if (ev.key === 'ArrowLeft') { stop(); show(frame - 1); }
    else if (ev.key === 'ArrowRight') { stop(); show(frame + 1); }
    else return;
    ev.preventDefault();
  });
  show(0);
  document.body.setAttribute('data-flipbook-ready', '1');
})();
</script>
)JS";
}

}  // namespace

std::string sequencePage(const SiteCase& c, const std::vector<SiteCase>& all, const std::string& generated) {
    const auto& d = c.input.results;
    std::ostringstream s;
    s << pageHead(c.input.title + " - vct gallery", flipbookStyle())
      << "<body class=\"scene-page sequence-page\">\n<header><nav><a href=\"index.html\">&larr; all "
         "cases</a>";
    for (const auto& other : all)
        if (other.page != c.page)
            s << " &middot; <a href=\"" << encodeUrlPath(other.page) << "\">" << escapeHtml(other.input.title)
              << "</a>";
    const nlohmann::json path = d.value("path", nlohmann::json::object());
    s << "</nav>\n<h1>" << escapeHtml(c.input.title) << "</h1>\n<p class=\"summary\"><code>"
      << escapeHtml(d.value("scene", std::string("?"))) << "</code> &middot; " << d["frames"].dump()
      << " frames along <code>" << escapeHtml(path.value("source", std::string("?"))) << "</code> &middot; "
      << d.value("width", 0) << "&times;" << d.value("height", 0)
      << " px &middot; R = " << formatNumber(jsonNumber(d, "radius")) << " &middot; "
      << escapeHtml(d.value("gl_renderer", std::string("?"))) << " &middot; measured "
      << escapeHtml(c.input.measuredDate.empty() ? "?" : c.input.measuredDate)
      << " &middot; <a href=\"#metadata\">all metadata</a></p>\n</header>\n";
    s << flipbookSection(c) << plotsSection(c) << tableSection(c) << metadataSection(c, generated)
      << pageFooter({&c}, generated) << flipbookScript() << "</body>\n</html>\n";
    return s.str();
}

}  // namespace vct
