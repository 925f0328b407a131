// The images of a gallery: display PNGs made from the comparison's EXRs with one stated tone
// mapping, small thumbnails, and the ROI outline overlay.
#pragma once

#include <string>

#include "image/image.h"

namespace vct {

// How linear EXR values become 8-bit display values. Stated on every page (kToneMappingNote).
enum class DisplayEncoding {
    AoAsStored,  // AO in [0, 1] written as stored (clamped), no gamma: the value IS the figure
    Radiance,    // exposure 0 EV, sRGB OETF (IEC 61966-2-1), clamped to [0, 1]
};

// The note shown on the pages (plain text).
extern const char* const kToneMappingNote;

// Display version of a linear image: AO keeps its first channel (or the one named "ao" in the
// file, see displayFromExr); radiance keeps the first three channels.
Image displayImage(const Image& linear, DisplayEncoding encoding);

// Reads an EXR and returns its display version (AO: the channel named "ao" when present, else
// channel 0). Throws std::runtime_error naming the path when it cannot be read.
Image displayFromExr(const std::string& exrPath, DisplayEncoding encoding);

// Box-filtered downsample so the width is at most maxWidth (integer factor; the image is
// returned unchanged when already small enough).
Image thumbnailOf(const Image& display, int maxWidth);

// RGBA overlay of the mask's boundary: pixels inside the mask (channel 0 > 0.5) with at least
// one 4-neighbour outside it (or on the image border) get `rgb` with alpha 1; every other
// pixel is transparent. Drawn over the comparison at the same pixel grid.
Image roiOutline(const Image& mask, float r = 1.f, float g = 0.85f, float b = 0.f);

}  // namespace vct
