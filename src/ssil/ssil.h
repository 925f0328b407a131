// ssil: screen-space indirect lighting with visibility bitmasks (Therrien, Levesque and Gilet
// 2023, their main contribution): one bounce of diffuse light gathered from the lit G-buffer
// (direct light and emission) through VBAO's slices and masks, plus the sky through the
// sectors left clear; denoised by the a-trous filter (src/denoise) as irradiance.
#pragma once

#include "core/method.h"
#include "ssil/ssil_shared.h"

namespace vct {

inline constexpr PassId kPassSsil{"ssil"};
inline constexpr PassId kPassSsilFilter{"ssil_atrous"};
inline constexpr ResourceId kSsilRaw{"ssil_raw"};

struct SsilSettings {
    int slices = gpu::SSIL_DEFAULT_SLICES;
    int steps = gpu::SSIL_DEFAULT_STEPS;  // per side of a slice
    float extent = gpu::SSIL_DEFAULT_EXTENT;  // x the image's longer side
    float thickness = gpu::SSIL_DEFAULT_THICKNESS;  // x the view depth
    float samplePower = gpu::SSIL_DEFAULT_SAMPLE_POWER;
    bool filter = true;  // the a-trous filter after the gather
};
const SettingsTable<SsilSettings>& ssilSettings();

// The unfiltered gather: RGBA32F of the G-buffer's size, rgb = indirect radiance. `direct`:
// the renderer's direct light (null: the scene has no punctual lights).
GlTexture runSsil(const GBuffer& gbuffer, const View& view, const GlTexture* direct, float sky,
                  const SsilSettings& settings, uint64_t seed);

const Method& ssilMethod();

}  // namespace vct
