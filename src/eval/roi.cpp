#include "eval/roi.h"

#include "core/errors.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "eval/validate.h"

namespace vct {

namespace {

void requireNonNegative(const Image& image, const std::string& what) {
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        if (image.pixels[i] >= 0.f) continue;
        size_t pixel = i / size_t(image.channels);
        std::ostringstream msg;
        msg << what << ": negative standard error " << image.pixels[i] << " at pixel ("
            << pixel % size_t(image.width) << ", " << pixel / size_t(image.width) << ")";
        throw InternalError("deriveRoiMask", msg.str());
    }
}

}  // namespace

Image deriveRoiMask(const Image& aoWith, const Image& aoWithout, const Image& stderrWith,
                    const Image& stderrWithout, double k) {
    requireFinite(aoWith, "aoWith");
    requireFinite(aoWithout, "aoWithout");
    requireFinite(stderrWith, "stderrWith");
    requireFinite(stderrWithout, "stderrWithout");
    requireSameShape(aoWith, "aoWith", aoWithout, "aoWithout");
    requireSameShape(aoWith, "aoWith", stderrWith, "stderrWith");
    requireSameShape(aoWith, "aoWith", stderrWithout, "stderrWithout");
    requireNonNegative(stderrWith, "stderrWith");
    requireNonNegative(stderrWithout, "stderrWithout");
    if (!(k >= 0.0) || !std::isfinite(k))
        throw InternalError("deriveRoiMask", "k must be finite and >= 0, got " + std::to_string(k));

    Image mask(aoWith.width, aoWith.height, 1, 0.f);
    for (int y = 0; y < aoWith.height; ++y)
        for (int x = 0; x < aoWith.width; ++x)
            for (int c = 0; c < aoWith.channels; ++c) {
                double diff = std::abs(double(aoWith.at(x, y, c)) - double(aoWithout.at(x, y, c)));
                double s1 = stderrWith.at(x, y, c), s2 = stderrWithout.at(x, y, c);
                // The two renders are independent, so the difference's variance is the sum.
                double threshold = k * std::sqrt(s1 * s1 + s2 * s2) + kRoiAbsoluteFloor;
                if (diff > threshold) {
                    mask.at(x, y) = 1.f;
                    break;
                }
            }
    return mask;
}

size_t countMask(const Image& mask) {
    requireNonEmpty(mask, "mask");
    size_t count = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) count += mask.at(x, y, 0) > 0.5f ? 1 : 0;
    return count;
}

}  // namespace vct
