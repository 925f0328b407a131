// Input checks shared by the evaluation code: every public entry point rejects NaN/Inf and
// mismatched shapes with an InternalError that names the image and the pixel, so a
// broken estimator fails loudly instead of producing a NaN metric.
#pragma once

#include <string>

#include "image/image.h"

namespace vct {

// Throws InternalError "... <what>: non-finite value <v> at pixel (x, y) channel c".
void requireFinite(const Image& image, const std::string& what);

// Throws unless the image has pixels and a consistent buffer size.
void requireNonEmpty(const Image& image, const std::string& what);

// Throws unless a and b have the same width, height and channel count.
void requireSameShape(const Image& a, const std::string& aName, const Image& b, const std::string& bName);

// Throws unless the mask has the image's width and height (its channel 0 is read).
void requireMaskFits(const Image* mask, const Image& image, const std::string& imageName);

// A mask selects pixel (x, y) when its channel 0 is > 0.5; no mask selects every pixel.
inline bool maskSelects(const Image* mask, int x, int y) { return !mask || mask->at(x, y, 0) > 0.5f; }

}  // namespace vct
