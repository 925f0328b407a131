// The Embree ground truth as two methods of the registry: --ao reference (ray-traced AO at the
// G-buffer's points) and --gi reference (the path tracer, which lights the image itself).
// Both always report their per-pixel standard error, and compare scores every other method
// against them.
#pragma once

#include "core/method.h"
#include "reference/embree_scene.h"

namespace vct {

inline constexpr PassId kPassReferenceAo{"reference_ao"};
inline constexpr PassId kPassReferenceGi{"reference_gi"};
inline constexpr ResourceId kAoStderr{"ao_stderr"};
inline constexpr ResourceId kIndirectStderr{"indirect_stderr"};

// The Embree BVH of the render's scene, built on first use and kept for the session: shared
// by every method that traces rays (the reference and the low-spp ray tracers).
const EmbreeScene& sessionEmbreeScene(MethodContext& ctx);

const Method& referenceAoMethod();
const Method& referenceGiMethod();

}  // namespace vct
