#include "gallery/error_time_plot.h"

#include "gallery/html.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace vct {

std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points) {
    std::vector<size_t> front;
    for (size_t i = 0; i < points.size(); ++i) {
        bool dominated = false;
        for (size_t j = 0; j < points.size() && !dominated; ++j) {
            if (i == j) continue;
            const PlotPoint &a = points[i], &b = points[j];
            dominated =
                b.timeMs <= a.timeMs && b.error <= a.error && (b.timeMs < a.timeMs || b.error < a.error);
        }
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](size_t a, size_t b) {
        return points[a].timeMs < points[b].timeMs || (points[a].timeMs == points[b].timeMs && a < b);
    });
    return front;
}

namespace {

// Ticks at m 10^k for a log axis over [lo, hi]: decades, refined with 2 and 5, then with every
// digit, until there are at least three.
std::vector<double> logTicks(double lo, double hi) {
    const int k0 = int(std::floor(std::log10(lo))), k1 = int(std::ceil(std::log10(hi)));
    std::vector<double> ticks;
    for (const auto& mantissas : {std::vector<double>{1}, std::vector<double>{1, 2, 5},
                                  std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
        ticks.clear();
        for (int k = k0; k <= k1; ++k)
            for (double m : mantissas) {
                double t = m * std::pow(10.0, k);
                if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
            }
        if (ticks.size() >= 3) break;
    }
    return ticks;
}

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#d62728"};

}  // namespace

std::vector<double> linearTicks(double lo, double hi) {
    const double span = hi - lo;
    const double rough = span / 5;
    const double mag = std::pow(10.0, std::floor(std::log10(rough)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= rough) {
            step = m * mag;
            break;
        }
    std::vector<double> ticks;
    for (double t = std::ceil(lo / step) * step; t <= hi + 1e-12 * span; t += step) ticks.push_back(t);
    return ticks;
}

const char* plotColour(size_t index) { return kPalette[index % std::size(kPalette)]; }

std::string errorTimeSvg(const std::vector<PlotPoint>& all, const PlotStyle& style) {
    std::vector<PlotPoint> points;
    for (const auto& p : all)
        if (std::isfinite(p.timeMs) && p.timeMs > 0 && std::isfinite(p.error) && p.error >= 0)
            points.push_back(p);
    std::ostringstream s;
    const int W = style.width, H = style.height;
    const double left = 64, right = 16, top = 14, bottom = 46;
    s << "<svg class=\"plot\" viewBox=\"0 0 " << W << ' ' << H << "\" width=\"" << W << "\" height=\"" << H
      << "\" role=\"img\"";
    if (!style.id.empty()) s << " id=\"" << escapeHtml(style.id) << "\"";
    s << "><title>" << escapeHtml(style.errorLabel) << " against time</title>\n";
    if (points.empty()) {
        s << "<text x=\"" << W / 2 << "\" y=\"" << H / 2
          << "\" text-anchor=\"middle\">no timed results</text></svg>";
        return s.str();
    }
    // Axis ranges with a margin; error axis log only when the data span > 30x and are all > 0.
    double tLo = 1e300, tHi = 0, eLo = 1e300, eHi = 0;
    for (const auto& p : points) {
        tLo = std::min(tLo, p.timeMs), tHi = std::max(tHi, p.timeMs);
        eLo = std::min(eLo, p.error), eHi = std::max(eHi, p.error);
    }
    tLo /= 1.5, tHi *= 1.5;
    const bool logError = eLo > 0 && eHi / eLo > 30;
    if (logError)
        eLo /= 1.5, eHi *= 1.5;
    else {
        const double pad = std::max(0.08 * (eHi - eLo), eHi > 0 ? 0.05 * eHi : 1e-3);
        eLo = std::max(0.0, eLo - pad), eHi += pad;
    }
    const double pw = W - left - right, ph = H - top - bottom;
    auto px = [&](double t) {
        return left + pw * (std::log(t) - std::log(tLo)) / (std::log(tHi) - std::log(tLo));
    };
    auto py = [&](double e) {
        double u = logError ? (std::log(e) - std::log(eLo)) / (std::log(eHi) - std::log(eLo))
                            : (e - eLo) / (eHi - eLo);
        return top + ph * (1 - u);
    };
    auto num = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%.1f", v);
        return std::string(b);
    };
    // Frame, grid and ticks.
    s << "<rect class=\"frame\" x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\""
      << ph << "\" fill=\"none\" stroke=\"#888\"/>\n";
    for (double t : logTicks(tLo, tHi)) {
        s << "<line class=\"grid\" x1=\"" << num(px(t)) << "\" x2=\"" << num(px(t)) << "\" y1=\"" << top
          << "\" y2=\"" << top + ph << "\" stroke=\"#ddd\"/><text class=\"tick\" x=\"" << num(px(t))
          << "\" y=\"" << top + ph + 15 << "\" text-anchor=\"middle\" font-size=\"11\">" << formatNumber(t, 3)
          << "</text>\n";
    }
    for (double e : logError ? logTicks(eLo, eHi) : linearTicks(eLo, eHi)) {
        s << "<line class=\"grid\" x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << num(py(e))
          << "\" y2=\"" << num(py(e)) << "\" stroke=\"#ddd\"/><text class=\"tick\" x=\"" << left - 5
          << "\" y=\"" << num(py(e) + 4) << "\" text-anchor=\"end\" font-size=\"11\">" << formatNumber(e, 3)
          << "</text>\n";
    }
    s << "<text class=\"axis-title\" x=\"" << left + pw / 2 << "\" y=\"" << H - 8
      << "\" text-anchor=\"middle\" font-size=\"12\">time per frame (ms, log scale)</text>\n";
    s << "<text class=\"axis-title\" transform=\"translate(14," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">" << escapeHtml(style.errorLabel)
      << (logError ? " (log scale)" : "") << "</text>\n";
    // Pareto staircase: from each front point go right to the next point's time, then down.
    const std::vector<size_t> front = paretoFront(points);
    std::ostringstream path;
    for (size_t k = 0; k < front.size(); ++k) {
        const PlotPoint& p = points[front[k]];
        if (k == 0)
            path << "M" << num(px(p.timeMs)) << ' ' << num(py(p.error));
        else
            path << " H" << num(px(p.timeMs)) << " V" << num(py(p.error));
    }
    path << " H" << num(left + pw);
    s << "<path class=\"pareto\" d=\"" << path.str()
      << "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\""
      << " stroke-dasharray=\"5 3\"/>\n";
    // Points: colour by group; front points larger, ringed, and labelled.
    std::map<std::string, const char*> colours;
    for (const auto& p : points)
        if (!colours.count(p.group)) colours[p.group] = plotColour(colours.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        if (!p.href.empty()) s << "<a href=\"" << escapeHtml(p.href) << "\">";
        s << "<circle class=\"point" << (onFront ? " front" : "") << "\" cx=\"" << num(px(p.timeMs))
          << "\" cy=\"" << num(py(p.error)) << "\" r=\"" << (onFront ? 6 : 4.5) << "\" fill=\""
          << colours[p.group] << "\""
          << (onFront ? " stroke=\"#d62728\" stroke-width=\"2\"" : " stroke=\"#fff\" stroke-width=\"1\"")
          << "><title>" << escapeHtml(p.label) << ": " << formatMs(p.timeMs) << ", "
          << escapeHtml(style.errorLabel) << " " << formatNumber(p.error)
          << (onFront ? " (Pareto front)" : "") << "</title></circle>";
        if (onFront || points.size() <= 12)  // label every point while that stays readable
            s << "<text class=\"point-label" << (onFront ? " front" : "") << "\" x=\""
              << num(px(p.timeMs) + 8) << "\" y=\"" << num(py(p.error) - 6) << "\" font-size=\"11\""
              << (onFront ? " font-weight=\"bold\"" : " fill=\"#555\"") << ">" << escapeHtml(p.label)
              << "</text>";
        if (!p.href.empty()) s << "</a>";
        s << "\n";
    }
    s << "</svg>";
    return s.str();
}

}  // namespace vct
