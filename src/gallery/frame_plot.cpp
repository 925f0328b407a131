#include "gallery/frame_plot.h"

#include "gallery/error_time_plot.h"
#include "gallery/html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace vct {

namespace {

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", v);
    return b;
}

// Frame ticks 1, 2 or 5 times a power of ten apart, at most about ten of them.
std::vector<int> frameTicks(int frames) {
    int step = 1;
    for (int mag = 1;; mag *= 10) {
        for (int m : {1, 2, 5})
            if (frames <= 10 * m * mag) {
                step = m * mag;
                break;
            }
        if (frames <= 10 * step) break;
    }
    std::vector<int> ticks;
    for (int f = 0; f < frames; f += step) ticks.push_back(f);
    return ticks;
}

// One panel's vertical axis: [0, the largest value] with a margin; a flat 0 gets a small range
// so the line shows at the bottom rather than dividing by zero.
double axisTop(const std::vector<FrameSeries>& series, bool rmse, double extra) {
    double hi = std::isfinite(extra) ? std::max(0.0, extra) : 0.0;
    for (const auto& s : series)
        for (double v : rmse ? s.rmse : s.instability)
            if (std::isfinite(v)) hi = std::max(hi, v);
    return hi > 0 ? hi * 1.1 : 1e-3;
}

struct Panel {
    double top, height, hi;
    double y(double v) const { return top + height * (1 - std::clamp(v / hi, 0.0, 1.0)); }
};

}  // namespace

std::string perFrameSvg(const std::vector<FrameSeries>& series, int frames, const FramePlotStyle& style) {
    frames = std::max(1, frames);
    const int W = style.width, H = style.height;
    const double left = 64, right = 16, legendRow = 16, bottom = 40, gap = 20;
    // The legend wraps over as many rows as it needs above the panels.
    std::vector<std::pair<double, double>> legendAt;  // (x, y) per series
    double lx = left, ly = 12;
    for (const auto& s : series) {
        const double w = 24 + 6.5 * double(s.label.size()) + 14;
        if (lx + w > W - right && lx > left) lx = left, ly += legendRow;
        legendAt.push_back({lx, ly});
        lx += w;
    }
    const double top = ly + 12, pw = W - left - right;
    const double panels = H - top - bottom - gap;
    const Panel rm{top, panels * 0.5, axisTop(series, true, NAN)};
    const Panel in{top + panels * 0.5 + gap, panels * 0.5,
                   axisTop(series, false, style.referenceInstability)};
    // Frame f sits at the middle of its 1/frames of the axis: no point lies on the frame.
    const double dx = pw / frames, x0 = left + dx / 2;
    auto px = [&](int f) { return x0 + dx * f; };

    std::ostringstream s;
    s << "<svg class=\"plot frame-plot\" viewBox=\"0 0 " << W << ' ' << H << "\" width=\"" << W
      << "\" height=\"" << H << "\" role=\"img\" data-frames=\"" << frames << "\" data-x0=\"" << num(x0)
      << "\" data-dx=\"" << formatNumber(dx, 6) << "\"";
    if (!style.id.empty()) s << " id=\"" << escapeHtml(style.id) << "\"";
    s << "><title>" << escapeHtml(style.title) << "</title>\n";
    for (size_t i = 0; i < series.size(); ++i)
        s << "<g class=\"legend\"><line x1=\"" << num(legendAt[i].first) << "\" x2=\""
          << num(legendAt[i].first + 18) << "\" y1=\"" << num(legendAt[i].second - 4) << "\" y2=\""
          << num(legendAt[i].second - 4) << "\" stroke=\"" << plotColour(i)
          << "\" stroke-width=\"2\"/><text x=\"" << num(legendAt[i].first + 24) << "\" y=\""
          << num(legendAt[i].second) << "\" font-size=\"11\">" << escapeHtml(series[i].label)
          << "</text></g>\n";

    // Frames, grids and the vertical ticks of both panels; the frame ticks under the lower one.
    auto frame = [&](const Panel& p, const char* title) {
        s << "<rect class=\"frame\" x=\"" << left << "\" y=\"" << num(p.top) << "\" width=\"" << pw
          << "\" height=\"" << num(p.height) << "\" fill=\"none\" stroke=\"#888\"/>\n";
        for (double v : linearTicks(0, p.hi))
            s << "<line class=\"grid\" x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << num(p.y(v))
              << "\" y2=\"" << num(p.y(v)) << "\" stroke=\"#ddd\"/><text class=\"tick\" x=\"" << left - 5
              << "\" y=\"" << num(p.y(v) + 4) << "\" text-anchor=\"end\" font-size=\"11\">"
              << formatNumber(v, 3) << "</text>\n";
        s << "<text class=\"axis-title\" transform=\"translate(14," << num(p.top + p.height / 2)
          << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">" << title << "</text>\n";
    };
    frame(rm, "RMSE");
    frame(in, "instability");
    for (int f : frameTicks(frames)) {
        s << "<line class=\"grid\" x1=\"" << num(px(f)) << "\" x2=\"" << num(px(f)) << "\" y1=\""
          << num(in.top) << "\" y2=\"" << num(in.top + in.height)
          << "\" stroke=\"#eee\"/><text class=\"tick\" x=\"" << num(px(f)) << "\" y=\""
          << num(in.top + in.height + 15) << "\" text-anchor=\"middle\" font-size=\"11\">" << f
          << "</text>\n";
    }
    s << "<text class=\"axis-title\" x=\"" << left + pw / 2 << "\" y=\"" << H - 8
      << "\" text-anchor=\"middle\" font-size=\"12\">frame (instability: of the pair ending there)</text>\n";

    if (std::isfinite(style.referenceInstability) && style.referenceInstability >= 0) {
        const double y = in.y(style.referenceInstability);
        s << "<line class=\"reference\" x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << num(y)
          << "\" y2=\"" << num(y) << "\" stroke=\"#555\" stroke-dasharray=\"4 3\"><title>the reference's own "
          << "instability over the sequence: " << formatNumber(style.referenceInstability)
          << "</title></line><text x=\"" << left + pw - 4 << "\" y=\"" << num(y - 4)
          << "\" text-anchor=\"end\" font-size=\"10\" fill=\"#555\">reference</text>\n";
    }

    // Lines break where a value is missing; points carry the exact value as a tooltip (while
    // there are few enough of them to hover).
    auto line = [&](const std::vector<double>& values, int firstFrame, const Panel& p, size_t colour,
                    const std::string& what) {
        std::ostringstream d, dots;
        bool pen = false;
        for (size_t k = 0; k < values.size() && firstFrame + int(k) < frames; ++k) {
            const int f = firstFrame + int(k);
            if (!std::isfinite(values[k])) {
                pen = false;
                continue;
            }
            d << (pen ? " L" : (d.tellp() > 0 ? " M" : "M")) << num(px(f)) << ' ' << num(p.y(values[k]));
            pen = true;
            if (frames <= 120)
                dots << "<circle cx=\"" << num(px(f)) << "\" cy=\"" << num(p.y(values[k]))
                     << "\" r=\"2.5\" fill=\"" << plotColour(colour) << "\"><title>" << what << ", frame "
                     << f << ": " << formatNumber(values[k]) << "</title></circle>";
        }
        if (d.tellp() > 0)
            s << "<path class=\"series\" d=\"" << d.str() << "\" fill=\"none\" stroke=\""
              << plotColour(colour) << "\" stroke-width=\"1.5\"/>";
        s << dots.str() << "\n";
    };
    for (size_t i = 0; i < series.size(); ++i) {
        const std::string label = escapeHtml(series[i].label);
        line(series[i].rmse, 0, rm, i, label + " RMSE");
        line(series[i].instability, 1, in, i, label + " instability");
    }
    s << "<line class=\"frame-marker\" x1=\"" << num(x0) << "\" x2=\"" << num(x0) << "\" y1=\"" << num(rm.top)
      << "\" y2=\"" << num(in.top + in.height) << "\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n</svg>";
    return s.str();
}

}  // namespace vct
