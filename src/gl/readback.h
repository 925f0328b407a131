// Reads a 2D texture level back to the CPU as floats, flipped so row 0 is the top.
#pragma once

#include "image/image.h"

#include <epoxy/gl.h>

namespace vct {

// `channels` is 1 (GL_RED), 2 (GL_RG), 3 (GL_RGB) or 4 (GL_RGBA).
Image readTexture2D(GLuint texture, int width, int height, int channels, int level = 0);
// Uploads a top-row-first image into a new RGBA32F/R32F texture (flipping to GL order).
// Used by tests to build synthetic G-buffers.
void uploadTexture2D(GLuint texture, const Image& image);

}  // namespace vct
