#include "gallery/site_images.h"

#include "core/errors.h"
#include "eval/image_io.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {

const char* const kToneMappingNote =
    "PNG images are made from the EXRs: AO as stored (values in [0,1], clamped, no gamma); radiance "
    "(indirect, beauty) with exposure 0 EV and the sRGB transfer function, clamped. Error maps: signed "
    "error (method - reference), blue = too dark, white = 0, red = too bright, saturating at +-scale; grey = "
    "not scored (sky). The EXR links hold the linear 32-bit data.";

namespace {

Image channelsOf(const Image& img, int first, int count) {
    Image out(img.width, img.height, count);
    for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
        for (int c = 0; c < count; ++c) out.pixels[i * count + c] = img.pixels[i * img.channels + first + c];
    return out;
}

}  // namespace

Image displayImage(const Image& linear, DisplayEncoding encoding) {
    if (linear.empty()) throw InternalError("displayImage", "empty image");
    if (encoding == DisplayEncoding::AoAsStored) {
        Image out = channelsOf(linear, 0, 1);
        for (float& v : out.pixels) v = std::isfinite(v) ? std::clamp(v, 0.f, 1.f) : 0.f;
        return out;
    }
    Image rgb = linear.channels >= 3 ? channelsOf(linear, 0, 3) : channelsOf(linear, 0, 1);
    for (float& v : rgb.pixels)
        if (!std::isfinite(v)) v = 0.f;
    return toneMapToSrgb(rgb, 0.f);
}

Image displayFromExr(const std::string& exrPath, DisplayEncoding encoding) {
    Image img = readImage(exrPath);
    if (encoding == DisplayEncoding::AoAsStored && img.channels > 1) {
        const auto names = channelNamesOf(exrPath);
        for (size_t c = 0; c < names.size() && int(c) < img.channels; ++c)
            if (names[c] == "ao") return displayImage(channelsOf(img, int(c), 1), encoding);
    }
    return displayImage(img, encoding);
}

Image thumbnailOf(const Image& display, int maxWidth) {
    if (maxWidth < 1) throw InternalError("thumbnailOf", "maxWidth must be >= 1");
    if (display.width <= maxWidth) return display;
    const int factor = (display.width + maxWidth - 1) / maxWidth;
    const int w = std::max(1, display.width / factor), h = std::max(1, display.height / factor);
    Image out(w, h, display.channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < display.channels; ++c) {
                double sum = 0;
                for (int dy = 0; dy < factor; ++dy)
                    for (int dx = 0; dx < factor; ++dx)
                        sum += display.at(std::min(display.width - 1, x * factor + dx),
                                          std::min(display.height - 1, y * factor + dy), c);
                out.at(x, y, c) = float(sum / (factor * factor));
            }
    return out;
}

Image roiOutline(const Image& mask, float r, float g, float b) {
    if (mask.empty()) throw InternalError("roiOutline", "empty mask");
    auto inside = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < mask.width && y < mask.height && mask.at(x, y, 0) > 0.5f;
    };
    Image out(mask.width, mask.height, 4, 0.f);
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            if (!inside(x, y)) continue;
            if (inside(x - 1, y) && inside(x + 1, y) && inside(x, y - 1) && inside(x, y + 1)) continue;
            out.at(x, y, 0) = r;
            out.at(x, y, 1) = g;
            out.at(x, y, 2) = b;
            out.at(x, y, 3) = 1.f;
        }
    return out;
}

}  // namespace vct
