// Region of interest derived from two reference renders: the pixels whose
// reference AO changes, beyond the references' own noise, when an off-screen occluder is added.
#pragma once

#include <cstddef>

#include "image/image.h"

namespace vct {

// Absolute floor added to the noise threshold, so that noise-free (stderr 0) pixels with
// bit-identical or rounding-level differences are not selected.
constexpr double kRoiAbsoluteFloor = 1e-6;

// 1-channel 0/1 mask: 1 where |aoWith - aoWithout| > k sqrt(seWith^2 + seWithout^2) + floor,
// i.e. the difference of two independent estimates exceeds k of its standard errors.
// All four images must share width, height and channel count; with several channels a pixel
// is selected when any channel exceeds its threshold. Throws InternalError on
// NaN/Inf, negative standard errors, mismatched shapes or k < 0.
Image deriveRoiMask(const Image& aoWith, const Image& aoWithout, const Image& stderrWith,
                    const Image& stderrWithout, double k = 3.0);

// Pixels whose channel 0 is > 0.5 (the selection rule of every mask in src/eval).
size_t countMask(const Image& mask);

}  // namespace vct
