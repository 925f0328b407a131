// The per-frame plot of a sequence page as inline SVG: two panels over one frame axis, the
// RMSE of every method at each frame above, its instability for each pair of consecutive
// frames below (drawn at the later frame of the pair), and a marker line at the frame the
// page's flipbook shows (moved by the page's script through data-x0 / data-dx).
#pragma once

#include <string>
#include <vector>

namespace vct {

struct FrameSeries {
    std::string label;                // legend and tooltips
    std::vector<double> rmse;         // one per frame; NaN: not computed (a gap in the line)
    std::vector<double> instability;  // one per pair (f - 1, f), f = 1 .. frames - 1
};

struct FramePlotStyle {
    int width = 560;
    int height = 380;
    std::string id;                    // id attribute of the <svg>; empty: none
    std::string title;                 // <title> of the SVG, e.g. "AO per frame"
    double referenceInstability = -1;  // the reference's own, as a dashed line; < 0 or NaN: none
};

// The SVG element (a string starting with "<svg"), self-contained: no external references.
// `frames` >= 1 sets the axis; series values beyond it are ignored.
std::string perFrameSvg(const std::vector<FrameSeries>& series, int frames, const FramePlotStyle& style = {});

}  // namespace vct
