// Shader sources compiled into the binary (see cmake/EmbedShaders.cmake), keyed by their
// path relative to shaders/, e.g. "ao/gtao.glsl".
#pragma once
#include <map>
#include <string>

namespace vct {
const std::map<std::string, std::string>& embeddedShaders();
}
