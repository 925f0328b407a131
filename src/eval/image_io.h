// Image files through OpenImageIO. EXR holds linear 32-bit float data (never half: AO
// differences of 1e-4 matter and half has ~3 decimal digits); PNG holds 8-bit display values.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace vct {

// Writes `.exr` (FLOAT, zip-compressed, lossless) or `.png` (8-bit). PNG expects values the
// caller has already tone-mapped to [0, 1] (toneMapToSrgb); they are clamped and rounded to
// round(255 v), with no gamma applied here. channelNames, when given, must have one name per
// channel (EXR stores them; PNG takes its layout from the count: Y, YA, RGB, RGBA); default:
// "Y" for one channel, R, G, B, A otherwise. The file is written under a temporary name in the
// same directory and renamed into place, so a failure never leaves a partial file: the
// temporary is removed and std::runtime_error names the path and OIIO's error.
// Throws InternalError for NaN/Inf pixels, an unknown extension or a bad name count.
void writeImage(const std::string& path, const Image& image,
                const std::vector<std::string>& channelNames = {});

// Reads every channel of the first subimage as float, top row first. 8-bit files come back
// as v / 255 (no linearization). Throws std::runtime_error naming the path.
// Channel ORDER follows the file, not the writer: OpenEXR sorts channels by name (OIIO puts
// R, G, B, A first), so {"stderr", "ao"} reads back as {"ao", "stderr"}. Find channels by
// name with channelNamesOf(path) rather than by the index used when writing.
Image readImage(const std::string& path);

// The channel names stored in a file (EXR: as written; others: OIIO's defaults).
std::vector<std::string> channelNamesOf(const std::string& path);

// Display encoding for PNG figures: scale by 2^exposure, apply the sRGB OETF (IEC 61966-2-1),
// clamp to [0, 1]. With 4 channels the 4th (alpha) is copied untouched.
Image toneMapToSrgb(const Image& linear, float exposure = 0.f);

// The sRGB OETF of one linear value in [0, 1] (clamped).
float srgbFromLinear(float linear);

}  // namespace vct
