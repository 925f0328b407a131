// The edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010; the
// spatial filter of SVGF, Schied et al. 2017): constants, the uniform block and the tap
// weights, shared by src/denoise/atrous.cpp and shaders/denoise/atrous.glsl so that the CPU
// tests weigh taps exactly as the shader does.
//
// A first pass estimates each pixel's variance from its 7x7 neighbourhood (SVGF's spatial
// estimate, for a single render has no history to take it from time). Iteration i then
// convolves with the 5x5 B3-spline kernel whose taps lie 2^i pixels apart (the "holes"), each
// tap weighted by how much its surface resembles the centre's (depth, normal, albedo from the
// G-buffer) and by how close its value is to the centre's in units of the centre's standard
// deviation, the weights normalized to sum to 1; the variance goes through the same weights
// squared. Noise is far larger than the signal's own steps at first, so early iterations
// average freely; as the variance falls, the luminance term keeps the signal's gradients (an
// AO falloff, a shadow edge) that the G-buffer knows nothing of. Three iterations cover
// 2 (1 + 2 + 4) = 14 pixels each way, five 62.
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define ATROUS_FN inline
#else
#define ATROUS_FN
#endif

VCT_BEGIN_NAMESPACE

#ifdef __cplusplus
using glm::exp; using glm::pow;
#endif

VCT_CONST int ATROUS_LOCAL_SIZE = 8;
VCT_CONST int ATROUS_MAX_ITERATIONS = 8;  // the last step is 128 pixels

// Texture units (the G-buffer's own, as core/gbuffer.h) and the image unit of the output.
VCT_CONST int ATROUS_UNIT_POSITION = 0;
VCT_CONST int ATROUS_UNIT_NORMAL = 1;
VCT_CONST int ATROUS_UNIT_ALBEDO = 3;
VCT_CONST int ATROUS_UNIT_INPUT = 6;
VCT_CONST int ATROUS_IMAGE_OUTPUT = 0;
VCT_CONST int ATROUS_BINDING_UNIFORMS = 1;

VCT_CONST int ATROUS_VARIANCE_RADIUS = 3;  // the variance estimate's 7x7 window (SVGF's)

// Defaults (src/denoise/atrous.cpp says how they were chosen).
VCT_CONST int ATROUS_DEFAULT_ITERATIONS = 3;
VCT_CONST float ATROUS_DEFAULT_SIGMA_DEPTH = 0.01;
VCT_CONST float ATROUS_DEFAULT_SIGMA_NORMAL = 64.0;
VCT_CONST float ATROUS_DEFAULT_SIGMA_ALBEDO = 0.1;
VCT_CONST float ATROUS_DEFAULT_SIGMA_LUMINANCE = 4.0;

struct AtrousUniforms {
    // x = step between taps (pixels); y = 1: the filter works on irradiance (the variance pass
    // divides the input by the albedo, the last iteration multiplies it back), so texture
    // detail is not blurred; z = 1: the last iteration (writes alpha 1 instead of the
    // variance); w unused
    ivec4 config;
    // x = sigma_depth (fraction of the centre's view depth), y = sigma_normal (exponent),
    // z = sigma_albedo, w = sigma_luminance (standard deviations; 0 = off)
    vec4 sigmas;
};

// B3-spline weights h(-2..2) = (1, 4, 6, 4, 1) / 16 at |offset| = 0, 1, 2; the 5x5 kernel
// h(x) h(y) sums to 1.
ATROUS_FN float atrous_kernel(int offset) { return offset == 0 ? 0.375f : (offset == 1 ? 0.25f : 0.0625f); }

// How much a tap's surface resembles the centre's, in [0, 1]:
// - depth: the tap's distance from the centre's tangent plane, relative to the centre's view
//   depth (zero along any plane, however steeply seen, so floors keep filtering; large across
//   a depth step), exp(-d^2 / (2 sigma^2));
// - normal: max(0, n . n_tap)^sigma_normal (SVGF's term);
// - albedo: exp(-|a - a_tap|^2 / (2 sigma^2)), keeping the edges of materials.
ATROUS_FN float atrous_edgeWeight(vec3 centre, vec3 normal, vec3 albedo, float depth, vec3 tap, vec3 tapNormal,
                                  vec3 tapAlbedo, vec4 sigmas) {
    float planeDistance = dot(normal, tap - centre) / max(sigmas.x * depth, 1e-30f);
    float wDepth = exp(-0.5f * planeDistance * planeDistance);
    float wNormal = sigmas.y > 0.0f ? pow(max(0.0f, dot(normal, tapNormal)), sigmas.y) : 1.0f;  // pow(0, 0) is undefined in GLSL
    vec3 da = albedo - tapAlbedo;
    float wAlbedo = exp(-0.5f * dot(da, da) / max(sigmas.z * sigmas.z, 1e-30f));
    return wDepth * wNormal * wAlbedo;
}

// SVGF's luminance term: exp(-|l - l_tap| / (sigma_luminance x standard deviation)). Equal
// values weigh 1 whatever the deviation, so a constant image stays constant.
ATROUS_FN float atrous_luminanceWeight(float luminance, float tapLuminance, float deviation, float sigmaLuminance) {
    if (!(sigmaLuminance > 0.0f)) return 1.0f;
    float d = luminance - tapLuminance;
    return exp(-(d < 0.0f ? -d : d) / max(sigmaLuminance * deviation, 1e-10f));
}

VCT_END_NAMESPACE
