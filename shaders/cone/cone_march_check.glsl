// The GPU half of tests/gpu/cone_march_shared_test.cpp: cone_checkEvaluate
// (cone_march_check.h) on each input of the buffer, one invocation each.
#include "cone/cone_march_check.h"

layout(local_size_x = CONE_CHECK_GROUP) in;
layout(std430, binding = CONE_CHECK_BINDING_INPUTS) readonly buffer CheckInputs { ConeCheckInput checkInputs[]; };
layout(std430, binding = CONE_CHECK_BINDING_OUTPUTS) writeonly buffer CheckOutputs { ConeCheckOutput checkOutputs[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(checkInputs.length())) return;
    checkOutputs[i] = cone_checkEvaluate(checkInputs[i]);
}
