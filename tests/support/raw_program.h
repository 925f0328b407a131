// A compute program linked from raw GLSL source rather than the embedded shader table: for
// tests that probe what the GL itself accepts or does (its limits, its loop handling), which
// the renderer's programs cannot isolate.
#pragma once

#include "gl/handles.h"

#include <string>

namespace vcttest {

struct RawProgram {
    vct::GlProgram program;
    bool linked = false;  // false where the GL refused to compile or link it
};

RawProgram linkCompute(const std::string& source);

}  // namespace vcttest
