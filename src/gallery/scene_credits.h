// Who made each scene and under which licence, for the "credits" line of every gallery page.
// The table mirrors shared/scenes/README.md (third-party scenes) and is compiled in, so an
// installed `vct gallery` credits scenes without the source tree.
#pragma once

#include <string>

namespace vct {

// Credit text (plain, not escaped) for a scene path as results.json stores it (matched by
// file name). The project's own scenes (a .gltf in a folder named scenes/) are credited to
// the project; an unknown file says that its credit is unknown.
std::string sceneCredit(const std::string& scenePath);

}  // namespace vct
