#include "eval/validate.h"

#include "core/errors.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vct {

void requireNonEmpty(const Image& image, const std::string& what) {
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0)
        throw InternalError("requireNonEmpty", what + ": empty image (" + std::to_string(image.width) + "x" +
                                                   std::to_string(image.height) + "x" +
                                                   std::to_string(image.channels) + ")");
    if (image.pixels.size() != size_t(image.width) * size_t(image.height) * size_t(image.channels))
        throw InternalError("requireNonEmpty", what + ": pixel buffer holds " + std::to_string(image.pixels.size()) +
                                                   " floats, expected width*height*channels");
}

void requireFinite(const Image& image, const std::string& what) {
    requireNonEmpty(image, what);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        float v = image.pixels[i];
        if (std::isfinite(v)) continue;
        size_t pixel = i / size_t(image.channels);
        std::ostringstream msg;
        msg << what << ": non-finite value " << v << " at pixel (" << pixel % size_t(image.width) << ", "
            << pixel / size_t(image.width) << ") channel " << i % size_t(image.channels);
        throw InternalError("requireFinite", msg.str());
    }
}

void requireSameShape(const Image& a, const std::string& aName, const Image& b, const std::string& bName) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        std::ostringstream msg;
        msg << aName << " is " << a.width << "x" << a.height << "x" << a.channels << " but " << bName
            << " is " << b.width << "x" << b.height << "x" << b.channels;
        throw InternalError("requireSameShape", msg.str());
    }
}

void requireMaskFits(const Image* mask, const Image& image, const std::string& imageName) {
    if (!mask) return;
    requireFinite(*mask, "mask");
    if (mask->width != image.width || mask->height != image.height) {
        std::ostringstream msg;
        msg << "mask is " << mask->width << "x" << mask->height << " but " << imageName << " is "
            << image.width << "x" << image.height;
        throw InternalError("requireMaskFits", msg.str());
    }
}

}  // namespace vct
