// The gallery's stylesheet and script, compiled into the binary (gallery_css.cpp,
// gallery_js.cpp) so an installed `vct gallery` needs no source tree. Written to SITE/assets/.
#pragma once

namespace vct {

const char* galleryCss();
const char* galleryJs();

}  // namespace vct
