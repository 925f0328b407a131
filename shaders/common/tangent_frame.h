// The orthonormal frame around a unit vector, shared by C++ and GLSL: the cone passes' cone
// sets (shaders/cone, src/vdb) and the reference's hemisphere samples (src/reference) turn
// tangent-space directions into world directions with it.
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define FRAME_FN inline
#else
#define FRAME_FN
#endif

VCT_BEGIN_NAMESPACE

// Columns (t, b, n) around unit n without a branch on the pole (Duff et al. 2017). The
// construction with sign s is orthonormal everywhere but at its pole n.z = -s, and s =
// sign(n.z) keeps it a hemisphere away from it. At n.z = +-0 the callers pick differently:
// the cone passes take n.z >= 0 (-0 counts as +1: frame_fromZ), the reference takes the sign
// bit (std::copysign). Each keeps its choice, since the two frames there differ by a half
// turn about n, which would rotate a cone set that is not symmetric under it.
FRAME_FN mat3 frame_fromZWithSign(vec3 n, float s) {
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

FRAME_FN mat3 frame_fromZ(vec3 n) { return frame_fromZWithSign(n, n.z >= 0.0f ? 1.0f : -1.0f); }

VCT_END_NAMESPACE
