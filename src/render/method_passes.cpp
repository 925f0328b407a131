#include "render/method_passes.h"

#include "ao/screen_space_ao.h"
#include "gl/context.h"

#include <stdexcept>

namespace vct {

struct MethodCache::Impl {};

MethodOutputs runMethodPasses(const RenderPlan& plan, const RenderRequest& request, const Scene& scene,
                              const GpuScene& gpu, const GBuffer* gbuffer, const View& view, PassTimer& timer,
                              MethodCache& cache, std::map<std::string, int>& runCounts, nlohmann::json& extra) {
    (void)scene; (void)gpu; (void)cache; (void)runCounts; (void)extra;
    MethodOutputs out;
    GlContext& gl = GlContext::shared();
    if (plan.runs("ssao")) {
        out.ao = computeScreenSpaceAO(request.ao, *gbuffer, view, request.radius, request.params, request.seed, timer);
        gl.checkErrors("ssao");
    }
    for (const char* pass : {"voxelize", "cone_ao", "cone_gi", "reference_ao", "reference_gi"})
        if (plan.runs(pass))
            throw std::invalid_argument(std::string("pass '") + pass + "' is not implemented yet");
    return out;
}

}  // namespace vct
