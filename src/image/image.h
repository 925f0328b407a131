// A linear float image on the CPU: what passes hand to the writers, the metrics and the
// tests. Row 0 is the TOP row (file order); GL readbacks are flipped into this order.
#pragma once

#include <string>
#include <vector>

namespace vct {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // row-major, top row first, interleaved channels

    Image() = default;
    Image(int w, int h, int c, float fill = 0.f)
        : width(w), height(h), channels(c), pixels(size_t(w) * size_t(h) * size_t(c), fill) {}
    float& at(int x, int y, int c = 0) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c = 0) const { return pixels[(size_t(y) * width + x) * channels + c]; }
    bool empty() const { return pixels.empty(); }
};

// One channel: the mean of each pixel's channels, summed in channel order.
inline Image channelMean(const Image& img) {
    Image out(img.width, img.height, 1);
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        float sum = 0.f;
        for (int c = 0; c < img.channels; ++c) sum += img.pixels[i * size_t(img.channels) + size_t(c)];
        out.pixels[i] = sum / float(img.channels);
    }
    return out;
}

}  // namespace vct
