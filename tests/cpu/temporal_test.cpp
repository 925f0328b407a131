// Temporal instability (eval/temporal.h) on G-buffers built here by casting each pixel's ray at
// a ground plane: the reprojection against the plane's own closed form, and the score against
// noise of known variance (the reference's noise is subtracted, a method's own flicker is not).
#include "eval/temporal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using vct::Image;

struct Frame {
    vct::View view;
    Image position, depth, normal;
};

// The plane y = 0 seen by `camera`; pixels whose ray misses it are sky (depth 0).
Frame planeFrame(const glm::vec3& eye, const glm::vec3& target, int w, int h) {
    vct::Camera c;
    c.eye = eye;
    c.target = target;
    c.yfov = 0.9f;
    Frame f{vct::makeView(c, w, h), Image(w, h, 3), Image(w, h, 1), Image(w, h, 3)};
    const glm::mat4 worldFromClip = glm::inverse(f.view.clipFromWorld);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec2 ndc((x + 0.5f) / w * 2.f - 1.f, 1.f - (y + 0.5f) / h * 2.f);
            glm::vec4 nearPoint = worldFromClip * glm::vec4(ndc, 1.f, 1.f);
            const glm::vec3 d = glm::normalize(glm::vec3(nearPoint) / nearPoint.w - eye);
            if (!(d.y < -1e-4f)) continue;
            const glm::vec3 p = eye + d * (-eye.y / d.y);
            for (int k = 0; k < 3; ++k) f.position.at(x, y, k) = p[k];
            f.depth.at(x, y) = glm::length(p - eye);
            f.normal.at(x, y, 1) = 1.f;
        }
    return f;
}

// A smooth view-independent field on the plane, sampled at each frame's points.
Image fieldOn(const Frame& f) {
    Image img(f.depth.width, f.depth.height, 1);
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        const float x = f.position.pixels[3 * i], z = f.position.pixels[3 * i + 2];
        img.pixels[i] = f.depth.pixels[i] > 0.f ? 0.5f + 0.3f * std::sin(0.7f * x) * std::cos(0.5f * z) : 1.f;
    }
    return img;
}

Image plusNoise(const Image& img, float sigma, std::mt19937& rng) {
    std::normal_distribution<float> n(0.f, sigma);
    Image out = img;
    for (float& v : out.pixels) v += n(rng);
    return out;
}

vct::Reprojection reproject(const Frame& now, const Frame& before) {
    return vct::reprojectFrame(now.view, now.position, now.depth, now.normal, before.view, before.position,
                               before.depth, before.normal);
}

// Looking down at 50 deg: the plane fills the view, no horizon (where a pixel spans kilometres).
const glm::vec3 kEye(0.f, 5.f, 4.f), kTarget(0.f, 0.f, 0.f);

TEST(Temporal, AStillCameraReprojectsEveryPixelOntoItself) {
    Frame a = planeFrame(kEye, kTarget, 96, 64);
    vct::Reprojection r = reproject(a, a);
    size_t ground = 0;
    for (float d : a.depth.pixels) ground += d > 0.f;
    ASSERT_GT(ground, 1000u);
    EXPECT_EQ(r.validCount(), ground);
    const Image f = fieldOn(a);
    const Image back = vct::reprojectImage(r, f);
    for (size_t i = 0; i < f.pixels.size(); ++i) {
        if (r.valid[i]) {
            ASSERT_NEAR(back.pixels[i], f.pixels[i], 1e-4f) << "pixel " << i;
        }
    }
}

TEST(Temporal, APanReadsThePreviousFrameWhereThePointWas) {
    Frame a = planeFrame(kEye, kTarget, 128, 96);
    const glm::vec3 pan(0.37f, 0.f, 0.11f);  // a few pixels, not a whole number of them
    Frame b = planeFrame(kEye + pan, kTarget + pan, 128, 96);
    vct::Reprojection r = reproject(b, a);
    EXPECT_GT(r.validCount(), size_t(0.7 * 128 * 96));
    const Image now = fieldOn(b);
    const Image back = vct::reprojectImage(r, fieldOn(a));
    double worst = 0.0;
    for (size_t i = 0; i < now.pixels.size(); ++i)
        if (r.valid[i]) worst = std::max(worst, double(std::abs(back.pixels[i] - now.pixels[i])));
    // Bilinear reading of a field that changes by up to ~0.05 per pixel (far away): the error is
    // second order, an eighth of the second difference.
    EXPECT_LT(worst, 1e-2);
    // Without the reprojection (reading the same pixel), the pan is a change of its own.
    vct::Reprojection still = reproject(a, a);
    vct::TemporalScore wrong = vct::scoreFramePair(still, now, fieldOn(a), nullptr, nullptr, nullptr, nullptr);
    vct::TemporalScore right = vct::scoreFramePair(r, now, fieldOn(a), nullptr, nullptr, nullptr, nullptr);
    EXPECT_GT(wrong.changeRms(), 10.0 * right.changeRms());
}

TEST(Temporal, ADeterministicMethodOnAStillPathScoresZero) {
    Frame a = planeFrame(kEye, kTarget, 64, 48);
    const Image f = fieldOn(a);
    vct::TemporalScore s = vct::scoreFramePair(reproject(a, a), f, f, &f, &f, nullptr, nullptr);
    EXPECT_EQ(s.instability(), 0.0);
    EXPECT_EQ(s.changeRms(), 0.0);
    EXPECT_GT(s.samples, 0u);
}

TEST(Temporal, TheReferencesNoiseIsSubtractedAndAMethodsFlickerIsNot) {
    const float sigmaRef = 0.03f, sigmaMethod = 0.05f;
    std::mt19937 rng(5);
    Frame frames[4];
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 pan(0.21f * i, 0.f, -0.13f * i);
        frames[i] = planeFrame(kEye + pan, kTarget + pan, 128, 128);
    }
    vct::TemporalScore steady, flicker;
    Image refPrev = plusNoise(fieldOn(frames[0]), sigmaRef, rng);
    Image flickerPrev = plusNoise(fieldOn(frames[0]), sigmaMethod, rng);
    const Image se(128, 128, 1, sigmaRef);
    for (int i = 1; i < 4; ++i) {
        const vct::Reprojection r = reproject(frames[i], frames[i - 1]);
        const Image truth = fieldOn(frames[i]);
        const Image ref = plusNoise(truth, sigmaRef, rng);
        const Image flickering = plusNoise(truth, sigmaMethod, rng);
        steady.add(vct::scoreFramePair(r, truth, fieldOn(frames[i - 1]), &ref, &refPrev, &se, &se));
        flicker.add(vct::scoreFramePair(r, flickering, flickerPrev, &ref, &refPrev, &se, &se));
        refPrev = ref;
        flickerPrev = flickering;
    }
    // The exact method changes only as the truth does: what remains is the reference's noise,
    // which the score subtracts (raw RMS ~ 1.2-1.4 sigma, the score within 0.2 sigma of zero).
    EXPECT_GT(steady.rawRms(), 1.1 * sigmaRef);
    EXPECT_LT(steady.instability(), 0.2 * sigmaRef);
    EXPECT_NEAR(steady.noiseRms(), steady.rawRms(), 0.05 * sigmaRef);
    // A method with noise of its own flickers by that noise's change: sigma (1 + sum w^2)^(1/2),
    // between sigma and sqrt(2) sigma for bilinear weights.
    EXPECT_GT(flicker.instability(), 1.0 * sigmaMethod);
    EXPECT_LT(flicker.instability(), 1.45 * sigmaMethod);
}

TEST(Temporal, DisoccludedAndSkyPixelsAreMasked) {
    Frame a = planeFrame(kEye, kTarget, 64, 48);
    Frame moved = a;
    // A block of the previous frame shows another surface, 0.5 above the plane: a pixel whose
    // taps land there is disoccluded now.
    for (int y = 20; y < 30; ++y)
        for (int x = 20; x < 30; ++x) moved.position.at(x, y, 1) = 0.5f;
    vct::Reprojection r = reproject(a, moved);
    for (int y = 20; y < 30; ++y)
        for (int x = 20; x < 30; ++x) EXPECT_EQ(r.valid[size_t(y) * 64 + x], 0) << x << "," << y;
    EXPECT_EQ(r.valid[size_t(10) * 64 + 40], a.depth.at(40, 10) > 0.f ? 1 : 0);
    // Previous sky everywhere: nothing reprojects.
    Frame sky = a;
    for (float& d : sky.depth.pixels) d = 0.f;
    EXPECT_EQ(reproject(a, sky).validCount(), 0u);
}

}  // namespace
