#include "eval/metrics.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "eval/validate.h"

namespace vct {

namespace {

void requireChannel(int channel, const Image& image, const std::string& what) {
    if (channel < -1 || channel >= image.channels)
        throw InternalError(what, "channel " + std::to_string(channel) + " out of range [-1, " +
                                      std::to_string(image.channels - 1) + "]");
}

void requirePeak(double peak) {
    if (!(peak > 0.0) || !std::isfinite(peak))
        throw InternalError("metrics", "peak must be finite and > 0, got " + std::to_string(peak));
}

// Channels [begin, end) selected by `channel` (-1 = all).
std::pair<int, int> channelRange(int channel, const Image& image) {
    return channel < 0 ? std::pair<int, int>(0, image.channels) : std::pair<int, int>(channel, channel + 1);
}

void validatePair(const Image& estimate, const Image& reference, const Image* mask, int channel,
                  double peak) {
    requireFinite(estimate, "estimate");
    requireFinite(reference, "reference");
    requireSameShape(estimate, "estimate", reference, "reference");
    requireMaskFits(mask, estimate, "estimate");
    requireChannel(channel, estimate, "metrics");
    requirePeak(peak);
}

// Truncated Gaussian of Wang et al. 2004: 11 taps, sigma 1.5 (normalization cancels below).
constexpr int kSsimRadius = 5;
constexpr double kSsimSigma = 1.5;

// out = separable Gaussian blur of `in` (w x h) with zero padding outside the image.
void gaussianBlur(const std::vector<double>& in, std::vector<double>& out, int w, int h,
                  const double* taps) {
    // Rows are independent, so the parallel loop is deterministic.
    std::vector<double> rows(in.size(), 0.0);
    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            double sum = 0.0;
            for (int i = -kSsimRadius; i <= kSsimRadius; ++i) {
                int xi = x + i;
                if (xi >= 0 && xi < w) sum += taps[i + kSsimRadius] * in[size_t(y) * w + xi];
            }
            rows[size_t(y) * w + x] = sum;
        }
    });
    out.assign(in.size(), 0.0);
    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            double sum = 0.0;
            for (int i = -kSsimRadius; i <= kSsimRadius; ++i) {
                int yi = y + i;
                if (yi >= 0 && yi < h) sum += taps[i + kSsimRadius] * rows[size_t(yi) * w + x];
            }
            out[size_t(y) * w + x] = sum;
        }
    });
}

// Mean SSIM of one channel over the valid pixels; inputs already validated.
double ssimChannel(const Image& e, const Image& r, const Image* mask, int c, double peak, size_t validCount) {
    double taps[2 * kSsimRadius + 1];
    for (int i = -kSsimRadius; i <= kSsimRadius; ++i)
        taps[i + kSsimRadius] = std::exp(-double(i * i) / (2.0 * kSsimSigma * kSsimSigma));

    int w = e.width, h = e.height;
    size_t n = size_t(w) * h;
    // Masked moments: blurring m, m x, m y, m x^2, m y^2, m x y and dividing by blur(m) gives the
    // Gaussian-weighted statistics renormalized over the valid pixels in each window.
    std::vector<double> m(n), mx(n), my(n), mxx(n), myy(n), mxy(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = size_t(y) * w + x;
            double valid = maskSelects(mask, x, y) ? 1.0 : 0.0;
            double a = e.at(x, y, c), b = r.at(x, y, c);
            m[i] = valid;
            mx[i] = valid * a;
            my[i] = valid * b;
            mxx[i] = valid * a * a;
            myy[i] = valid * b * b;
            mxy[i] = valid * a * b;
        }
    std::vector<double> W, Sx, Sy, Sxx, Syy, Sxy;
    gaussianBlur(m, W, w, h, taps);
    gaussianBlur(mx, Sx, w, h, taps);
    gaussianBlur(my, Sy, w, h, taps);
    gaussianBlur(mxx, Sxx, w, h, taps);
    gaussianBlur(myy, Syy, w, h, taps);
    gaussianBlur(mxy, Sxy, w, h, taps);

    const double C1 = (0.01 * peak) * (0.01 * peak), C2 = (0.03 * peak) * (0.03 * peak);
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (m[i] == 0.0) continue;
        double wsum = W[i];  // > 0: the centre pixel itself is valid
        double muX = Sx[i] / wsum, muY = Sy[i] / wsum;
        // Clamp: E[x^2] - E[x]^2 can round slightly below 0 on flat windows.
        double varX = std::max(0.0, Sxx[i] / wsum - muX * muX);
        double varY = std::max(0.0, Syy[i] / wsum - muY * muY);
        double covXY = Sxy[i] / wsum - muX * muY;
        sum += ((2.0 * muX * muY + C1) * (2.0 * covXY + C2)) /
               ((muX * muX + muY * muY + C1) * (varX + varY + C2));
    }
    return sum / double(validCount);
}

size_t countValid(const Image& image, const Image* mask) {
    if (!mask) return size_t(image.width) * image.height;
    size_t count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) count += maskSelects(mask, x, y) ? 1 : 0;
    return count;
}

double ssimValidated(const Image& e, const Image& r, const Image* mask, int channel, double peak) {
    size_t validCount = countValid(e, mask);
    if (validCount == 0) return 0.0;
    auto [c0, c1] = channelRange(channel, e);
    double sum = 0.0;
    for (int c = c0; c < c1; ++c) sum += ssimChannel(e, r, mask, c, peak, validCount);
    return sum / double(c1 - c0);
}

}  // namespace

ErrorMetrics computeErrorMetrics(const Image& estimate, const Image& reference, const Image* mask,
                                 int channel, double peak) {
    validatePair(estimate, reference, mask, channel, peak);
    auto [c0, c1] = channelRange(channel, estimate);

    // Sums in double: at 1080p a float accumulator would lose ~7 bits of the squared error.
    ErrorMetrics out;
    double sumSq = 0.0, sumAbs = 0.0, sumSigned = 0.0;
    for (int y = 0; y < estimate.height; ++y)
        for (int x = 0; x < estimate.width; ++x) {
            if (!maskSelects(mask, x, y)) continue;
            ++out.pixelCount;
            for (int c = c0; c < c1; ++c) {
                double d = double(estimate.at(x, y, c)) - double(reference.at(x, y, c));
                sumSq += d * d;
                sumAbs += std::abs(d);
                sumSigned += d;
                out.maxAbs = std::max(out.maxAbs, std::abs(d));
            }
        }
    if (out.pixelCount == 0) return out;  // every field 0 by definition

    double samples = double(out.pixelCount) * double(c1 - c0);
    double mse = sumSq / samples;
    out.rmse = std::sqrt(mse);
    out.mae = sumAbs / samples;
    out.bias = sumSigned / samples;
    out.psnr = mse > 0.0 ? std::min(kMaxPsnrDb, 10.0 * std::log10(peak * peak / mse)) : kMaxPsnrDb;
    out.ssim = ssimValidated(estimate, reference, mask, channel, peak);
    return out;
}

double computeSsim(const Image& estimate, const Image& reference, const Image* mask, int channel,
                   double peak) {
    validatePair(estimate, reference, mask, channel, peak);
    return ssimValidated(estimate, reference, mask, channel, peak);
}

double imageMean(const Image& image, const Image* mask, int channel) {
    requireFinite(image, "image");
    requireMaskFits(mask, image, "image");
    requireChannel(channel, image, "imageMean");
    auto [c0, c1] = channelRange(channel, image);
    double sum = 0.0;
    size_t count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!maskSelects(mask, x, y)) continue;
            ++count;
            for (int c = c0; c < c1; ++c) sum += image.at(x, y, c);
        }
    return count == 0 ? 0.0 : sum / (double(count) * double(c1 - c0));
}

}  // namespace vct
