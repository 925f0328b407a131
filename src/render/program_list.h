// Every GL program the renderer (and its benchmarks) can build: the variants each pass's key
// function can return. The limits test links and inspects each; the test suite checks that
// every program its tests compiled is among them.
#pragma once

#include "gl/program_cache.h"

#include <vector>

namespace vct {

std::vector<ProgramKey> rendererProgramVariants();

}  // namespace vct
