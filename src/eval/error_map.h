// False-colour maps of signed error for figures: a diverging blue-white-red ramp.
// Output values are display-ready [0, 1] (already "tone-mapped"): write them to PNG as they are.
#pragma once

#include <array>

#include "image/image.h"

namespace vct {

// Colour of a normalized signed error t in [-1, 1] (clamped): -1 = saturated blue (estimate
// too dark), 0 = white, +1 = saturated red (too bright). Linear ramps from white to the end
// points of Moreland's cool-warm map, whose ends have similar lightness so neither sign
// looks more severe than the other.
std::array<float, 3> divergingColor(double t);

// Grey for pixels outside the mask: distinct from white (zero error).
constexpr float kMaskedGrey = 0.5f;

// RGB image of (estimate - reference), saturating at +-scale (scale > 0, same units as the
// images). Multi-channel images use the mean signed error over their channels. Pixels with
// mask channel 0 <= 0.5 are kMaskedGrey. Throws InternalError on NaN/Inf input,
// mismatched shapes or scale <= 0.
Image falseColorError(const Image& estimate, const Image& reference, double scale,
                      const Image* mask = nullptr);

// A horizontal legend bar (RGB, width x height): the left column is -scale, the right
// column +scale, column x shows the error -scale + 2 scale (x + 0.5) / width. Labels are the
// caller's business (the figure script knows the units).
Image falseColorLegend(int width, int height, double scale);

}  // namespace vct
