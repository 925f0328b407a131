// Denoised low-spp ray tracing, what real-time ray tracers ship: the reference's estimators
// (src/reference) at 1 to 4 samples per pixel, then the edge-avoiding a-trous filter
// (src/denoise) guided by the G-buffer. --ao rtao-denoised traces AO rays from the G-buffer's
// points; --gi pt-denoised path-traces the indirect light and filters it as irradiance (the
// albedo divided out and multiplied back), so the renderer's direct pass and composite light
// the image as for every other GI method. Each adds its unfiltered estimate as an AOV.
#pragma once

#include "core/method.h"

namespace vct {

inline constexpr PassId kPassRtao{"rtao"};
inline constexpr PassId kPassRtaoFilter{"rtao_atrous"};
inline constexpr PassId kPassPt{"pt"};
inline constexpr PassId kPassPtFilter{"pt_atrous"};
inline constexpr ResourceId kRtaoNoisy{"rtao_noisy"};
inline constexpr ResourceId kPtNoisy{"pt_noisy"};

// 4 samples per pixel, the top of what real-time ray tracers spend: at 1 spp the spatial
// variance the filter steers by is mostly noise itself, and the filtered error is about 1.6x
// that at 4 spp (Cornell box, 128 px: AO 0.083 against 0.051, GI RMSE 25 % against 16 % of
// the mean), at a quarter of the rays.
struct RtaoDenoisedSettings {
    int spp = 4;  // [1, 64]
};

struct PtDenoisedSettings {
    int spp = 4;      // [1, 64]
    int bounces = 4;  // [1, 1024], the reference's default path length, so both estimate the same light
};

const SettingsTable<RtaoDenoisedSettings>& rtaoDenoisedSettings();
const SettingsTable<PtDenoisedSettings>& ptDenoisedSettings();

const Method& rtaoDenoisedMethod();
const Method& ptDenoisedMethod();

}  // namespace vct
