// The edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010) as SVGF
// uses it for its spatial part (Schied et al. 2017): a variance pass, then one compute pass
// per iteration over an image of the G-buffer's size, guided by the G-buffer's depth, normals
// and albedo and by the signal's luminance relative to its estimated standard deviation
// (shaders/denoise/atrous_shared.h has the weights). Any estimator that leaves per-pixel
// noise on the G-buffer's pixels can use it: the low-spp ray tracers (src/denoised) and SSIL
// do. Deterministic: the same input, G-buffer and settings give the same bits.
//
// Defaults: see atrous.cpp, where the table documents each with the measurement behind it.
#pragma once

#include "core/gbuffer.h"
#include "core/settings.h"
#include "denoise/atrous_shared.h"
#include "gl/handles.h"
#include "gl/program_cache.h"

#include <vector>

namespace vct {

struct AtrousSettings {
    int iterations = gpu::ATROUS_DEFAULT_ITERATIONS;          // [0, ATROUS_MAX_ITERATIONS]; 0 = unfiltered
    float sigmaDepth = gpu::ATROUS_DEFAULT_SIGMA_DEPTH;       // fraction of the view depth
    float sigmaNormal = gpu::ATROUS_DEFAULT_SIGMA_NORMAL;     // exponent of max(0, n.n')
    float sigmaAlbedo = gpu::ATROUS_DEFAULT_SIGMA_ALBEDO;     // RGB distance
    float sigmaLuminance = gpu::ATROUS_DEFAULT_SIGMA_LUMINANCE;  // standard deviations; 0 = off
};
// The atrous.* keys, shared by every method that filters with it.
const SettingsTable<AtrousSettings>& atrousSettings();
// A filtering method's own setting docs followed by the filter's.
std::vector<SettingDoc> withAtrousDocs(std::vector<SettingDoc> docs);

// `channels` 1: `input` holds AO in its red channel (R32F); 3: RGB radiance (RGBA32F).
// `demodulate` (radiance only): filter input / albedo and multiply the result by the albedo,
// for light reflected by the surface, so textures stay sharp. Returns an RGBA32F texture of
// the same size (the value in r or rgb, alpha 1 on surfaces and 0 on sky); `input` must be
// gbuffer.width x gbuffer.height (GL bottom-left origin). Throws InternalError on a mismatch.
GlTexture runAtrousFilter(const GBuffer& gbuffer, const GlTexture& input, int channels,
                          const AtrousSettings& settings, bool demodulate);

std::vector<ProgramKey> atrousPrograms();  // every variant: both passes, 1 and 3 channels

}  // namespace vct
