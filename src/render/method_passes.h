// Runs the AO and GI estimator passes of a plan (screen space, cone tracing, reference)
// and hands their outputs to the composite. Kept apart from renderer.cpp so that the
// core's control flow stays readable as methods are added.
#pragma once

#include "gl/handles.h"
#include "image/image.h"
#include "render/gbuffer.h"
#include "render/gpu_scene.h"
#include "render/plan.h"
#include "render/request.h"
#include "render/timing.h"

#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

namespace vct {

struct MethodOutputs {
    GlTexture ao;        // R32F (GPU methods)
    GlTexture indirect;  // RGBA32F GI radiance (cone_gi)
    Image aoImage;       // CPU methods (reference), top row first
    Image aoStderr;
    Image indirectImage, indirectStderr, ptDirect, ptBeauty;  // path tracer
    std::map<std::string, Image> voxelViews;                   // voxel_* AOVs
};

// Shared state across renders of one session (voxel grids keyed by their settings).
struct MethodCache {
    struct Impl;
    std::shared_ptr<Impl> impl;
};

MethodOutputs runMethodPasses(const RenderPlan& plan, const RenderRequest& request, const Scene& scene,
                              const GpuScene& gpu, const GBuffer* gbuffer, const View& view, PassTimer& timer,
                              MethodCache& cache, std::map<std::string, int>& runCounts, nlohmann::json& extra);

}  // namespace vct
