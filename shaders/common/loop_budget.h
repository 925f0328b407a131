// How many loop iterations one shader invocation may run, shared by C++ (which splits work
// over dispatches to stay within it) and the shaders.
//
// llvmpipe counts every loop iteration of an invocation, all its loops together, and leaves
// every loop once the count reaches 65535 (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS): silently,
// with whatever the sums hold then. A pass whose invocations could loop longer (a cone gather
// of many lanes, an injection with many lights) splits its work over dispatches that each stay
// within this budget and carries its sums from one to the next, in the same order, so the
// result is the one a single dispatch would give. 5535 below the limit for the few loops a
// pass does not count.
#pragma once
#include "common/shared_types.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int SHADER_LOOP_BUDGET = 60000;

VCT_END_NAMESPACE
