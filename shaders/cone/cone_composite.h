// Front-to-back compositing of a cone's (or a view ray's) samples, shared by C++ and GLSL:
// the march (cone_march_shared.h) and the voxel views (cone_raymarch.glsl) composite with it.
// Literals carry `f` and the operations keep their order, as in cone_march_shared.h.
#pragma once
#include "cone/cone_shared.h"

#ifdef __cplusplus
#define CONE_INOUT(T) T&
#else
#define CONE_INOUT(T) inout T
#endif

VCT_BEGIN_NAMESPACE

struct ConeResult {
    vec3 radiance;  // premultiplied radiance gathered front to back
    float alpha;    // accumulated opacity; 1 = the cone saw no sky
    float samples;  // volume samples the march took (a device-independent cost)
};

// Composites one sample s (premultiplied radiance, alpha) over a step dt through texels of
// edge `texel`, at distance tMid: opacity corrected for the step length, alpha' = 1 - (1 -
// alpha)^(dt / texel), and (AO) the falloff weight 1 / (1 + lambda t).
CONE_FN void cone_composite(CONE_INOUT(ConeResult) r, vec4 s, float dt, float texel, float tMid, float falloff) {
    float a = clamp(s.a, 0.0f, 1.0f);
    float k = dt / texel;
    float aStep = 1.0f - exp2(k * log2(max(1.0f - a, 1e-7f)));
    // Premultiplied radiance scales with the corrected opacity (its ratio to alpha is the
    // radiance itself); a transparent sample with radiance would be emission of a medium.
    vec3 c = a > 1e-6f ? vec3(s) * (aStep / a) : vec3(s) * k;
    float w = falloff > 0.0f ? 1.0f / (1.0f + falloff * tMid) : 1.0f;
    r.radiance += (1.0f - r.alpha) * c;
    r.alpha += (1.0f - r.alpha) * aStep * w;
}

// A saturated cone counts as closed: renormalize what it saw rather than letting the last
// 1 - maxAlpha see the sky (that would leak sky light into closed rooms).
CONE_FN void cone_close(CONE_INOUT(ConeResult) r, float maxAlpha) {
    if (r.alpha >= maxAlpha) {
        r.radiance /= r.alpha;
        r.alpha = 1.0f;
    }
}

VCT_END_NAMESPACE
