// Directional levels that hold optical depth instead of opacity (vct.opacity=depth), shared by
// the mip builders (mip_aniso.glsl, src/vdb/sparse_levels.cpp) and the samplers that read them
// (cone_march.glsl, src/vdb/sparse_cone.cpp).
//
// Why. A cone's march filters the levels trilinearly and composites the samples front to
// back. Opacity does not interpolate linearly along a ray: a one-texel opaque sheet between
// empty texels is a tent of alpha, and a march through it collects an optical depth of
// integral -ln(1 - alpha(x)) dx = 2 texels of e-folds in the continuous limit, so it passes
// exp(-2) = 13.5% of the light whatever the resolution (a closed room leaks ~20% of its cones
// at every grid size). Optical depth does: its tent integrates to the texel's own depth, so
// crossing a texel of transmittance T passes exactly T, and texels in series multiply.
// Across the ray the same interpolation widens an opaque texel's shadow by up to a texel,
// which shrinks with the texels.
//
// Encoding. Depth counts halvings of transmittance, tau = -log2(1 - alpha), capped at
// VOX_DEPTH_MAX; premultiplied radiance is carried premultiplied by tau (radiance * tau), so
// the filtered ratio is the depth-weighted mean radiance. The base level stays opacity: it
// holds 0 or 1 (a voxel that any triangle overlaps is opaque), whose trilinear filter in
// depth is VOX_DEPTH_MAX times the filtered opacity (vox_depthFromCoverage).
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define VOX_DEPTH_FN inline
#else
#define VOX_DEPTH_FN
#endif

VCT_BEGIN_NAMESPACE

// 8 halvings: crossing one opaque texel passes 1/256 of the light (below the cones' 0.99
// closing threshold after one wall), while a larger cap only widens opaque texels' shadows
// across the ray (depth tau * f at a texel's trilinear weight f).
VCT_CONST float VOX_DEPTH_MAX = 8.0f;

// (premultiplied radiance, alpha) -> (radiance * tau, tau).
VOX_DEPTH_FN vec4 vox_depthFromAlpha(vec4 s) {
    float a = clamp(s.w, 0.0f, 1.0f);
    float tau = min(-log2(max(1.0f - a, exp2(-VOX_DEPTH_MAX))), VOX_DEPTH_MAX);
    float scale = a > 1.0e-6f ? tau / a : 1.4426950408889634f;  // d tau / d alpha at 0: 1 / ln 2
    return vec4(vec3(s) * scale, tau);
}

// (radiance * tau, tau) -> (premultiplied radiance, alpha).
VOX_DEPTH_FN vec4 vox_alphaFromDepth(vec4 s) {
    float tau = max(s.w, 0.0f);
    float a = 1.0f - exp2(-tau);
    float scale = tau > 1.0e-6f ? a / tau : 0.6931471805599453f;  // d alpha / d tau at 0: ln 2
    return vec4(vec3(s) * scale, a);
}

// The base level's (premultiplied radiance, opacity) filtered from voxels that are 0 or 1,
// as depth: the same filter weights times VOX_DEPTH_MAX.
VOX_DEPTH_FN vec4 vox_depthFromCoverage(vec4 s) { return s * VOX_DEPTH_MAX; }

VCT_END_NAMESPACE
