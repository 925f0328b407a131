#include "eval/error_map.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "eval/validate.h"

namespace vct {

namespace {

// End points of Moreland's "cool to warm" diverging map (2009), sRGB-encoded.
constexpr std::array<float, 3> kCool = {0.230f, 0.299f, 0.754f};
constexpr std::array<float, 3> kWarm = {0.706f, 0.016f, 0.150f};

void requireScale(double scale) {
    if (!(scale > 0.0) || !std::isfinite(scale))
        throw InternalError("false colour", "scale must be finite and > 0, got " + std::to_string(scale));
}

}  // namespace

std::array<float, 3> divergingColor(double t) {
    t = std::clamp(t, -1.0, 1.0);
    const std::array<float, 3>& end = t < 0.0 ? kCool : kWarm;
    float s = float(std::abs(t));
    return {1.f + s * (end[0] - 1.f), 1.f + s * (end[1] - 1.f), 1.f + s * (end[2] - 1.f)};
}

Image falseColorError(const Image& estimate, const Image& reference, double scale, const Image* mask) {
    requireFinite(estimate, "estimate");
    requireFinite(reference, "reference");
    requireSameShape(estimate, "estimate", reference, "reference");
    requireMaskFits(mask, estimate, "estimate");
    requireScale(scale);

    Image out(estimate.width, estimate.height, 3);
    for (int y = 0; y < estimate.height; ++y)
        for (int x = 0; x < estimate.width; ++x) {
            std::array<float, 3> rgb = {kMaskedGrey, kMaskedGrey, kMaskedGrey};
            if (maskSelects(mask, x, y)) {
                double d = 0.0;
                for (int c = 0; c < estimate.channels; ++c)
                    d += double(estimate.at(x, y, c)) - double(reference.at(x, y, c));
                rgb = divergingColor(d / estimate.channels / scale);
            }
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = rgb[c];
        }
    return out;
}

Image falseColorLegend(int width, int height, double scale) {
    if (width <= 0 || height <= 0)
        throw InternalError("falseColorLegend", "size must be positive, got " + std::to_string(width) + "x" +
                                                    std::to_string(height));
    requireScale(scale);
    Image out(width, height, 3);
    for (int x = 0; x < width; ++x) {
        // Colours depend on t = error / scale alone; scale is validated so the caller's labels are.
        std::array<float, 3> rgb = divergingColor(-1.0 + 2.0 * (x + 0.5) / width);
        for (int y = 0; y < height; ++y)
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = rgb[c];
    }
    return out;
}

}  // namespace vct
