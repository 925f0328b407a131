// The G-buffer pass: rasterizes the scene once per view into the attachments of GBuffer.
#pragma once

#include "core/gbuffer.h"
#include "core/gpu_scene.h"
#include "core/timing.h"

namespace vct {

// materials = false: position and normals only (GBuffer::materials), for renders that read
// no albedo or emission.
GBuffer renderGBuffer(const GpuScene& scene, const View& view, PassTimer& timer, bool materials = true);

}  // namespace vct
