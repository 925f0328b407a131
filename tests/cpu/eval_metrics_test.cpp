// Error metrics against hand-computed values, closed forms and OIIO's compare() as an
// independent path.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/errors.h"
#include "eval/metrics.h"

namespace vct {
namespace {

Image gradient(int w, int h, int channels = 1) {
    Image img(w, h, channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.at(x, y, c) = 0.2f + 0.5f * (x + 2 * y + c) / float(w + 2 * h);
    return img;
}

Image noise(int w, int h, int channels, unsigned seed, float lo = 0.f, float hi = 1.f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    Image img(w, h, channels);
    for (float& v : img.pixels) v = u(rng);
    return img;
}

Image offset(const Image& img, float c) {
    Image out = img;
    for (float& v : out.pixels) v += c;
    return out;
}

TEST(EvalMetrics, ConstantOffsetGivesClosedForms) {
    Image ref = gradient(32, 32);
    for (float c : {0.1f, -0.1f, 0.25f}) {
        ErrorMetrics m = computeErrorMetrics(offset(ref, c), ref);
        EXPECT_NEAR(m.rmse, std::abs(c), 1e-6) << "c = " << c;
        EXPECT_NEAR(m.mae, std::abs(c), 1e-6) << "c = " << c;
        EXPECT_NEAR(m.bias, c, 1e-6) << "c = " << c;
        EXPECT_NEAR(m.maxAbs, std::abs(c), 1e-6) << "c = " << c;
        EXPECT_NEAR(m.psnr, -20.0 * std::log10(std::abs(c)), 1e-4) << "c = " << c;
        EXPECT_EQ(m.pixelCount, 32u * 32u);
    }
    // The brief's example: offset 0.1 with peak 1 is 20 dB; with peak 2 it is 20 + 20 log10 2.
    EXPECT_NEAR(computeErrorMetrics(offset(ref, 0.1f), ref).psnr, 20.0, 1e-4);
    EXPECT_NEAR(computeErrorMetrics(offset(ref, 0.1f), ref, nullptr, -1, 2.0).psnr,
                20.0 + 20.0 * std::log10(2.0), 1e-4);
}

TEST(EvalMetrics, HandComputedTwoByTwo) {
    Image ref(2, 2, 1, 0.5f), est(2, 2, 1, 0.5f);
    est.at(1, 0) = 0.625f;   // +0.125
    est.at(0, 1) = 0.25f;    // -0.25
    est.at(1, 1) = 0.5625f;  // +0.0625
    ErrorMetrics m = computeErrorMetrics(est, ref);
    double sq = 0.125 * 0.125 + 0.25 * 0.25 + 0.0625 * 0.0625;
    EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(sq / 4));
    EXPECT_DOUBLE_EQ(m.mae, (0.125 + 0.25 + 0.0625) / 4);
    EXPECT_DOUBLE_EQ(m.bias, (0.125 - 0.25 + 0.0625) / 4);
    EXPECT_DOUBLE_EQ(m.maxAbs, 0.25);
    EXPECT_NEAR(m.psnr, 10.0 * std::log10(4 / sq), 1e-12);
}

TEST(EvalMetrics, MaskRestrictsStatistics) {
    const int w = 32, h = 32;
    Image ref = gradient(w, h), est = ref, mask(w, h, 1, 0.f);
    size_t errorPixels = 0;
    for (int y = 4; y < 12; ++y)
        for (int x = 8; x < 14; ++x) {
            est.at(x, y) += 0.2f;
            mask.at(x, y) = 1.f;
            ++errorPixels;
        }
    ErrorMetrics inside = computeErrorMetrics(est, ref, &mask);
    EXPECT_EQ(inside.pixelCount, errorPixels);
    EXPECT_NEAR(inside.rmse, 0.2, 1e-6);
    EXPECT_NEAR(inside.bias, 0.2, 1e-6);
    EXPECT_NEAR(inside.mae, 0.2, 1e-6);

    ErrorMetrics all = computeErrorMetrics(est, ref);
    EXPECT_NEAR(all.rmse, 0.2 * std::sqrt(double(errorPixels) / (w * h)), 1e-6);
    EXPECT_NEAR(all.bias, 0.2 * double(errorPixels) / (w * h), 1e-6);

    Image outsideMask = mask;
    for (float& v : outsideMask.pixels) v = 1.f - v;
    ErrorMetrics outside = computeErrorMetrics(est, ref, &outsideMask);
    EXPECT_EQ(outside.pixelCount, size_t(w * h) - errorPixels);
    EXPECT_EQ(outside.rmse, 0.0);
    EXPECT_EQ(outside.maxAbs, 0.0);
    EXPECT_EQ(outside.psnr, kMaxPsnrDb);
}

TEST(EvalMetrics, EmptyMaskIsZeroNotNaN) {
    Image ref = gradient(16, 16), mask(16, 16, 1, 0.f);
    ErrorMetrics m = computeErrorMetrics(offset(ref, 0.3f), ref, &mask);
    EXPECT_EQ(m.pixelCount, 0u);
    for (double v : {m.rmse, m.mae, m.bias, m.maxAbs, m.psnr, m.ssim}) EXPECT_EQ(v, 0.0);
    EXPECT_EQ(imageMean(ref, &mask, -1), 0.0);
}

TEST(EvalMetrics, ChannelSelection) {
    Image ref = gradient(16, 16, 3), est = ref;
    const float offsets[3] = {0.1f, -0.2f, 0.3f};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) est.at(x, y, c) += offsets[c];
    for (int c = 0; c < 3; ++c) {
        ErrorMetrics m = computeErrorMetrics(est, ref, nullptr, c);
        EXPECT_NEAR(m.bias, offsets[c], 1e-6);
        EXPECT_NEAR(m.rmse, std::abs(offsets[c]), 1e-6);
    }
    ErrorMetrics all = computeErrorMetrics(est, ref);
    EXPECT_NEAR(all.rmse, std::sqrt((0.01 + 0.04 + 0.09) / 3), 1e-6);
    EXPECT_NEAR(all.bias, (0.1 - 0.2 + 0.3) / 3, 1e-6);
    EXPECT_NEAR(all.maxAbs, 0.3, 1e-6);
    EXPECT_EQ(all.pixelCount, 256u);
    EXPECT_THROW(computeErrorMetrics(est, ref, nullptr, 3), InternalError);
}

TEST(EvalMetrics, AgreesWithOiioCompare) {
    Image ref = noise(40, 24, 2, 1), est = noise(40, 24, 2, 2);
    OIIO::ImageSpec spec(40, 24, 2, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf a(spec, est.pixels.data()), b(spec, ref.pixels.data());
    auto cmp = OIIO::ImageBufAlgo::compare(a, b, 1.0, 1.0);
    ErrorMetrics m = computeErrorMetrics(est, ref);
    EXPECT_NEAR(m.rmse, cmp.rms_error, 1e-6);
    EXPECT_NEAR(m.mae, cmp.meanerror, 1e-6);
    EXPECT_NEAR(m.maxAbs, cmp.maxerror, 1e-6);
}

TEST(EvalMetrics, ImageMean) {
    Image img = gradient(8, 4, 2), mask(8, 4, 1, 0.f);
    mask.at(2, 1) = 1.f;
    mask.at(5, 3) = 0.75f;
    mask.at(6, 3) = 0.5f;  // not > 0.5: excluded
    EXPECT_NEAR(imageMean(img, &mask, 1), (img.at(2, 1, 1) + img.at(5, 3, 1)) / 2.0, 1e-7);
    double all = 0.0;
    for (float v : img.pixels) all += v;
    EXPECT_NEAR(imageMean(img, nullptr, -1), all / img.pixels.size(), 1e-7);
}

TEST(EvalSsim, IdentityIsOne) {
    Image img = noise(48, 32, 3, 7);
    EXPECT_NEAR(computeSsim(img, img), 1.0, 1e-12);
    EXPECT_NEAR(computeErrorMetrics(img, img).ssim, 1.0, 1e-12);
    EXPECT_EQ(computeErrorMetrics(img, img).psnr, kMaxPsnrDb);
}

// Constant images a and b: every window has zero variance and covariance, so Wang's
// formula reduces to (2ab + C1) / (a^2 + b^2 + C1).
TEST(EvalSsim, ConstantImagesClosedForm) {
    const double a = 0.6, b = 0.4, C1 = 1e-4;
    Image x(24, 24, 1, float(a)), y(24, 24, 1, float(b));
    double expected = (2 * a * b + C1) / (a * a + b * b + C1);
    EXPECT_NEAR(computeSsim(x, y), expected, 1e-6);

    // Masked-out pixels must not enter the windows: scribble noise outside the mask.
    Image mask(24, 24, 1, 0.f);
    Image xs = x, ys = y, scribble = noise(24, 24, 1, 3);
    for (int yy = 0; yy < 24; ++yy)
        for (int xx = 0; xx < 24; ++xx) {
            bool valid = (xx + yy) % 3 != 0;
            mask.at(xx, yy) = valid ? 1.f : 0.f;
            if (!valid) xs.at(xx, yy) = scribble.at(xx, yy), ys.at(xx, yy) = 1.f - scribble.at(xx, yy);
        }
    EXPECT_NEAR(computeSsim(xs, ys, &mask), expected, 1e-6);
    EXPECT_LT(computeSsim(xs, ys), expected - 0.01);  // without the mask the scribble lowers it
}

TEST(EvalSsim, ShiftAndNoiseLowerIt) {
    const int w = 64, h = 64;
    Image img(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = 0.5f + 0.4f * std::sin(0.35f * x) * std::cos(0.25f * y);
    Image shifted(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) shifted.at(x, y) = img.at(std::min(x + 2, w - 1), y);
    double sShift = computeSsim(shifted, img);
    EXPECT_LT(sShift, 0.99);
    EXPECT_GT(sShift, -1.0);

    double previous = 1.0;
    for (float amplitude : {0.02f, 0.1f, 0.3f}) {
        Image noisy = img, n = noise(w, h, 1, 11, -amplitude, amplitude);
        for (size_t i = 0; i < noisy.pixels.size(); ++i) noisy.pixels[i] += n.pixels[i];
        double s = computeSsim(noisy, img);
        EXPECT_LT(s, previous) << "noise amplitude " << amplitude;
        previous = s;
    }
}

TEST(EvalMetrics, RejectsNaNAndMismatches) {
    Image ref = gradient(8, 8), est = ref;
    est.at(3, 5) = std::numeric_limits<float>::quiet_NaN();
    try {
        computeErrorMetrics(est, ref);
        FAIL() << "NaN accepted";
    } catch (const InternalError& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find("estimate"), std::string::npos) << msg;
        EXPECT_NE(msg.find("(3, 5)"), std::string::npos) << msg;
    }
    Image inf = ref;
    inf.at(0, 0) = std::numeric_limits<float>::infinity();
    EXPECT_THROW(computeErrorMetrics(ref, inf), InternalError);
    EXPECT_THROW(imageMean(est), InternalError);
    EXPECT_THROW(computeErrorMetrics(gradient(8, 8), gradient(8, 9)), InternalError);
    Image smallMask(4, 4, 1, 1.f);
    EXPECT_THROW(computeErrorMetrics(ref, ref, &smallMask), InternalError);
    EXPECT_THROW(computeErrorMetrics(ref, ref, nullptr, -1, 0.0), InternalError);
    EXPECT_THROW(computeErrorMetrics(Image(), Image()), InternalError);
}

}  // namespace
}  // namespace vct
