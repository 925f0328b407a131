// Direct lighting and the final composite, both compute passes over the G-buffer.
#pragma once

#include "raster/shadow_pass.h"
#include "core/gbuffer.h"
#include "core/gpu_scene.h"
#include "core/timing.h"

namespace vct {

// RGBA32F direct radiance (Lambertian, shadowed) at every pixel. Timer scope "direct".
GlTexture computeDirectLighting(const GBuffer& g, const GpuScene& scene, const ShadowMaps& shadows,
                                PassTimer& timer);

struct CompositeInputs {
    const GlTexture* direct = nullptr;    // null: no direct light (no lights, or not requested)
    const GlTexture* ao = nullptr;        // null: AO = 1
    const GlTexture* indirect = nullptr;  // GI radiance; null: ambient = sky * albedo * AO
    float sky = 1.f;
};
struct CompositeOutputs {
    GlTexture beauty;    // RGBA32F
    GlTexture indirect;  // RGBA32F: the ambient/indirect term that went into beauty
};
// Timer scope "composite".
CompositeOutputs composite(const GBuffer& g, const CompositeInputs& in, PassTimer& timer);

}  // namespace vct
