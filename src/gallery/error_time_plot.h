// The error-against-time plot of one scene as inline SVG: log time axis, error axis (log when
// the errors span more than a decade and a half), the Pareto front (no other point is both
// faster and more accurate) drawn as a staircase and its points highlighted.
#pragma once

#include <string>
#include <vector>

namespace vct {

struct PlotPoint {
    std::string label;  // shown in the tooltip and beside front points
    double timeMs = 0;  // > 0 (plotted on a log axis; non-positive times are left out)
    double error = 0;   // >= 0, finite (others are left out)
    std::string href;   // link of the point (e.g. "#b=ao_gtao"); empty: no link
    std::string group;  // colour group (e.g. the method family); points of a group share a colour
};

// Indices of the Pareto-optimal points (minimize time and error), sorted by time. A point is
// on the front when no other point has time <= and error <= with at least one strictly less.
std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points);

struct PlotStyle {
    int width = 560;                  // SVG width in px
    int height = 340;                 // SVG height in px
    std::string errorLabel = "RMSE";  // y axis title
    std::string id;                   // id attribute of the <svg> (for CSS/JS); empty: none
};

// The SVG element (a string starting with "<svg"), self-contained: no external references.
std::string errorTimeSvg(const std::vector<PlotPoint>& points, const PlotStyle& style = {});

// Shared by the gallery's plots (frame_plot.cpp too), so they look alike.
// Round ticks (1, 2 or 5 times a power of ten apart, about five of them) over [lo, hi], hi > lo.
std::vector<double> linearTicks(double lo, double hi);
// The colour of group `index` (cycles through ten).
const char* plotColour(size_t index);

}  // namespace vct
