#include "gl/readback.h"

#include "core/errors.h"

#include <stdexcept>
#include <utility>

namespace vct {

namespace {
GLenum formatFor(int channels) {
    switch (channels) {
        case 1: return GL_RED;
        case 2: return GL_RG;
        case 3: return GL_RGB;
        case 4: return GL_RGBA;
        default: throw InternalError("readTexture2D", "channels must be 1..4");
    }
}
void flipRows(Image& img) {
    size_t row = size_t(img.width) * img.channels;
    for (int y = 0; y < img.height / 2; ++y)
        std::swap_ranges(img.pixels.begin() + y * row, img.pixels.begin() + (y + 1) * row,
                         img.pixels.begin() + (img.height - 1 - y) * row);
}
}  // namespace

Image readTexture2D(GLuint texture, int width, int height, int channels, int level) {
    Image img(width, height, channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture, level, formatFor(channels), GL_FLOAT,
                      static_cast<GLsizei>(img.pixels.size() * sizeof(float)), img.pixels.data());
    flipRows(img);
    return img;
}

void uploadTexture2D(GLuint texture, const Image& image) {
    Image flipped = image;
    flipRows(flipped);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture, 0, 0, 0, image.width, image.height, formatFor(image.channels), GL_FLOAT,
                        flipped.pixels.data());
}

}  // namespace vct
