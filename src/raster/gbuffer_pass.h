// The G-buffer pass: rasterizes the scene once per view into the attachments of GBuffer.
#pragma once

#include "render/gbuffer.h"
#include "render/gpu_scene.h"
#include "render/timing.h"

namespace vct {

GBuffer renderGBuffer(const GpuScene& scene, const View& view, PassTimer& timer);

}  // namespace vct
