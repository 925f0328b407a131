#include "eval/temporal.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {

namespace {

// Below this a tap's weight is rounding, not a sample: a pixel reprojected onto itself must not
// be masked because its neighbour 1e-6 of a pixel away lies on another surface.
constexpr float kMinTapWeight = 1e-3f;
// Same surface: normals within acos(0.8) ~ 37 deg.
constexpr float kMinNormalCos = 0.8f;

float valueAt(const Image& img, size_t pixel) {
    if (img.channels == 1) return img.pixels[pixel];
    float s = 0.f;
    for (int c = 0; c < img.channels; ++c) s += img.pixels[pixel * size_t(img.channels) + size_t(c)];
    return s / float(img.channels);
}

glm::vec3 vec3At(const Image& img, size_t pixel) {
    const float* p = &img.pixels[pixel * size_t(img.channels)];
    return glm::vec3(p[0], p[1], p[2]);
}

void checkSize(const Image& img, int w, int h, const char* what) {
    if (img.width != w || img.height != h)
        throw std::invalid_argument(std::string("temporal: ") + what + " is not the frame's size");
}

}  // namespace

size_t Reprojection::validCount() const {
    return size_t(std::count(valid.begin(), valid.end(), uint8_t(1)));
}

Reprojection reprojectFrame(const View& view, const Image& position, const Image& depth, const Image& normal,
                            const View& previousView, const Image& previousPosition, const Image& previousDepth,
                            const Image& previousNormal) {
    const int w = position.width, h = position.height;
    for (const Image* img : {&depth, &normal, &previousPosition, &previousDepth, &previousNormal})
        checkSize(*img, w, h, "a G-buffer image");
    Reprojection r;
    r.width = w;
    r.height = h;
    const size_t n = size_t(w) * size_t(h);
    r.taps.assign(4 * n, -1);
    r.weights.assign(4 * n, 0.f);
    r.valid.assign(n, 0);
    const glm::vec3 previousEye = previousView.camera.eye;
    const float focal = previousView.focalPx();
    const bool still = view.clipFromWorld == previousView.clipFromWorld && view.width == previousView.width &&
                       view.height == previousView.height;
    for (size_t p = 0; p < n; ++p) {
        if (!(depth.pixels[p] > 0.f)) continue;
        const glm::vec3 x = vec3At(position, p);
        const glm::vec3 nx = glm::normalize(vec3At(normal, p));
        const glm::vec4 clip = previousView.clipFromWorld * glm::vec4(x, 1.f);
        if (!(clip.w > 0.f)) continue;
        // Pixel centres at i + 0.5; row 0 is the top row (image/image.h).
        float qx = (0.5f * clip.x / clip.w + 0.5f) * float(w) - 0.5f;
        float qy = (0.5f - 0.5f * clip.y / clip.w) * float(h) - 0.5f;
        if (still) {
            qx = float(p % size_t(w));
            qy = float(p / size_t(w));
        }
        if (!(qx > -0.5f && qx < float(w) - 0.5f && qy > -0.5f && qy < float(h) - 0.5f)) continue;
        qx = std::clamp(qx, 0.f, float(w - 1));
        qy = std::clamp(qy, 0.f, float(h - 1));
        const int x0 = int(std::floor(qx)), y0 = int(std::floor(qy));
        const float fx = qx - float(x0), fy = qy - float(y0);
        const float tau = 2.f * glm::length(x - previousEye) / focal + 1e-5f * glm::length(x);
        bool ok = true;
        float total = 0.f;
        int k = 0;
        for (int dy = 0; dy < 2 && ok; ++dy)
            for (int dx = 0; dx < 2 && ok; ++dx, ++k) {
                const float wk = (dx ? fx : 1.f - fx) * (dy ? fy : 1.f - fy);
                if (wk < kMinTapWeight) continue;
                const int tx = x0 + dx, ty = y0 + dy;
                if (tx < 0 || ty < 0 || tx >= w || ty >= h) { ok = false; break; }
                const size_t t = size_t(ty) * size_t(w) + size_t(tx);
                if (!(previousDepth.pixels[t] > 0.f)) { ok = false; break; }
                const glm::vec3 xt = vec3At(previousPosition, t);
                const glm::vec3 nt = glm::normalize(vec3At(previousNormal, t));
                if (std::abs(glm::dot(xt - x, nx)) > tau || glm::dot(nt, nx) < kMinNormalCos) { ok = false; break; }
                r.taps[4 * p + size_t(k)] = int32_t(t);
                r.weights[4 * p + size_t(k)] = wk;
                total += wk;
            }
        if (!ok || !(total > 0.f)) {
            for (int j = 0; j < 4; ++j) { r.taps[4 * p + size_t(j)] = -1; r.weights[4 * p + size_t(j)] = 0.f; }
            continue;
        }
        for (int j = 0; j < 4; ++j) r.weights[4 * p + size_t(j)] /= total;
        r.valid[p] = 1;
    }
    return r;
}

Image reprojectImage(const Reprojection& r, const Image& previous) {
    checkSize(previous, r.width, r.height, "the previous frame");
    Image out(r.width, r.height, previous.channels, 0.f);
    const size_t c = size_t(previous.channels);
    for (size_t p = 0; p < r.valid.size(); ++p) {
        if (!r.valid[p]) continue;
        for (int j = 0; j < 4; ++j) {
            const int32_t t = r.taps[4 * p + size_t(j)];
            if (t < 0) continue;
            for (size_t ch = 0; ch < c; ++ch)
                out.pixels[p * c + ch] += r.weights[4 * p + size_t(j)] * previous.pixels[size_t(t) * c + ch];
        }
    }
    return out;
}

TemporalScore scoreFramePair(const Reprojection& r, const Image& method, const Image& methodPrevious,
                             const Image* reference, const Image* referencePrevious, const Image* stderrNow,
                             const Image* stderrPrevious) {
    checkSize(method, r.width, r.height, "the method's frame");
    checkSize(methodPrevious, r.width, r.height, "the method's previous frame");
    if (bool(reference) != bool(referencePrevious) || bool(stderrNow) != bool(stderrPrevious))
        throw std::invalid_argument("temporal: a reference or standard error needs both frames");
    TemporalScore s;
    for (size_t p = 0; p < r.valid.size(); ++p) {
        if (!r.valid[p]) continue;
        double mPrev = 0.0, rPrev = 0.0, noisePrev = 0.0;
        for (int j = 0; j < 4; ++j) {
            const int32_t t = r.taps[4 * p + size_t(j)];
            if (t < 0) continue;
            const double wk = r.weights[4 * p + size_t(j)];
            mPrev += wk * valueAt(methodPrevious, size_t(t));
            if (reference) rPrev += wk * valueAt(*referencePrevious, size_t(t));
            if (stderrPrevious) {
                const double se = valueAt(*stderrPrevious, size_t(t));
                noisePrev += wk * wk * se * se;  // the variance of a weighted sum of independent pixels
            }
        }
        const double dm = double(valueAt(method, p)) - mPrev;
        const double dr = reference ? double(valueAt(*reference, p)) - rPrev : 0.0;
        double noise = 0.0;
        if (stderrNow) {
            const double se = valueAt(*stderrNow, p);
            noise = se * se + noisePrev;
        }
        const double excess = (dm - dr) * (dm - dr) - noise;
        s.sumDiff2 += (dm - dr) * (dm - dr);
        s.sumNoise2 += noise;
        s.sumExcess2 += excess * excess;
        s.sumChange2 += dm * dm;
        ++s.samples;
    }
    return s;
}

double TemporalScore::instability() const {
    return samples ? std::sqrt(std::max(0.0, (sumDiff2 - sumNoise2) / double(samples))) : 0.0;
}
double TemporalScore::rawRms() const { return samples ? std::sqrt(sumDiff2 / double(samples)) : 0.0; }
double TemporalScore::changeRms() const { return samples ? std::sqrt(sumChange2 / double(samples)) : 0.0; }
double TemporalScore::noiseRms() const { return samples ? std::sqrt(sumNoise2 / double(samples)) : 0.0; }

double TemporalScore::resolution() const {
    if (samples < 2) return 0.0;
    const double n = double(samples), mean = (sumDiff2 - sumNoise2) / n;
    const double variance = std::max(0.0, sumExcess2 / n - mean * mean);
    return std::sqrt(2.0 * std::sqrt(variance / n));
}

void TemporalScore::add(const TemporalScore& o) {
    sumExcess2 += o.sumExcess2;
    sumDiff2 += o.sumDiff2;
    sumNoise2 += o.sumNoise2;
    sumChange2 += o.sumChange2;
    samples += o.samples;
}

nlohmann::json temporalScoreJson(const TemporalScore& s) {
    return {{"instability", s.instability()}, {"resolution", s.resolution()}, {"raw_rms", s.rawRms()}, {"change_rms", s.changeRms()},
            {"reference_noise_rms", s.noiseRms()}, {"samples", s.samples}};
}

}  // namespace vct
