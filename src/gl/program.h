// GLSL programs built from the embedded shader table. `#include "path"` lines are
// expanded by the loader (core GLSL has none) so one header can be shared by C++ and
// GLSL; defines are injected after the #version line. Compile errors throw with the
// shader's name and the driver's log.
#pragma once

#include "gl/handles.h"

#include <string>
#include <utility>
#include <vector>

namespace vct {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

// Returns the fully expanded source of an embedded shader (includes resolved).
std::string expandShaderSource(const std::string& name, const ShaderDefines& defines = {});

GlProgram buildComputeProgram(const std::string& name, const ShaderDefines& defines = {});
GlProgram buildGraphicsProgram(const std::string& vertex, const std::string& fragment,
                               const ShaderDefines& defines = {},
                               const std::string& geometry = "");

// Number of work groups to cover `n` items with groups of `groupSize`.
inline GLuint groupCount(int n, int groupSize) { return static_cast<GLuint>((n + groupSize - 1) / groupSize); }

}  // namespace vct
