// Error of an estimate against a reference image over valid (non-sky) pixels:
// RMSE, MAE, mean signed error, max absolute error, PSNR and SSIM (Wang et al. 2004).
//
// Conventions, shared by every function here:
//  - A pixel is valid when the mask's channel 0 is > 0.5 (no mask: every pixel). The mask must
//    have the images' width and height; a typical mask is "non-sky" or an ROI (eval/roi.h).
//  - channel = -1 averages over all channels (each (pixel, channel) sample counts once; SSIM is
//    the mean of the per-channel SSIMs); channel >= 0 restricts to that channel.
//  - An empty selection (pixelCount 0) defines every field as 0 (never NaN).
//  - NaN/Inf in any input throws InternalError naming the image and the pixel; shape
//    mismatches throw too.
#pragma once

#include <cstddef>

#include "image/image.h"

namespace vct {

struct ErrorMetrics {
    double rmse = 0.0;    // sqrt(mean (e - r)^2)
    double mae = 0.0;     // mean |e - r|
    double bias = 0.0;    // mean (e - r): > 0 means the estimate is too bright (AO: too open)
    double maxAbs = 0.0;  // max |e - r|
    double psnr = 0.0;    // dB, 10 log10(peak^2 / MSE); capped at kMaxPsnrDb when MSE == 0
    double ssim = 0.0;    // [-1, 1], 1 = identical; see computeSsim
    size_t pixelCount = 0;  // valid pixels (not samples): channels do not multiply it
};

// PSNR of identical images would be +infinity; it is reported as this finite cap instead
// (MSE 1e-20 at peak 1) so that tables and JSON stay finite.
constexpr double kMaxPsnrDb = 200.0;

// peak: the signal's dynamic range L, used for PSNR and for SSIM's C1 = (0.01 L)^2 and
// C2 = (0.03 L)^2. AO lives in [0, 1], hence the default 1.
ErrorMetrics computeErrorMetrics(const Image& estimate, const Image& reference, const Image* mask = nullptr,
                                 int channel = -1, double peak = 1.0);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, eq. 13 with the Gaussian window of
// section III-C: 11x11, sigma 1.5), averaged over windows centred on valid pixels.
// Window boundary: the window shrinks to the valid, in-image pixels it covers (the Gaussian
// weights are renormalized over them), so neither the image border nor masked-out pixels
// (e.g. sky) leak into the local statistics. Returns 0 for an empty selection.
double computeSsim(const Image& estimate, const Image& reference, const Image* mask = nullptr,
                   int channel = -1, double peak = 1.0);

// Mean of the valid pixels (channel -1: of all their channels); 0 for an empty selection.
double imageMean(const Image& image, const Image* mask = nullptr, int channel = -1);

}  // namespace vct
