#include "ao/screen_space_ao.h"

#include "ao/alchemy.h"
#include "ao/ao_filters.h"
#include "ao/gtao.h"
#include "ao/hbao.h"
#include "ao/horizon_ao.h"
#include "ao/ssao.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {

std::vector<std::string> screenSpaceAoMethods() {
    return {"ssao-crytek", "ssao-hemisphere", "ssao-horizon", "alchemy", "hbao", "gtao"};
}

bool isScreenSpaceAoMethod(const std::string& method) {
    auto all = screenSpaceAoMethods();
    return std::find(all.begin(), all.end(), method) != all.end();
}

namespace {

bool hasNoiseTile(const std::string& method) { return method == "ssao-crytek" || method == "ssao-hemisphere"; }

bool readHalfRes(const ParamMap& params) {
    return params.getBool("ao.half-res", false,
                          "screen-space AO: evaluate at half resolution, then a depth-aware upsample");
}

GlTexture evaluate(const std::string& method, const AoPassContext& ctx, const ParamMap& params, bool filtered) {
    if (method == "ssao-crytek") return runSsao(ctx, gpu::SSAO_KERNEL_SPHERE, readSsaoSettings(params));
    if (method == "ssao-hemisphere") return runSsao(ctx, gpu::SSAO_KERNEL_HEMISPHERE, readSsaoSettings(params));
    if (method == "ssao-horizon") return runHorizonAo(ctx, readHorizonSettings(params));
    if (method == "alchemy") return runAlchemy(ctx, readAlchemySettings(params));
    if (method == "hbao") return runHbao(ctx, readHbaoSettings(params));
    if (method == "gtao") return runGtao(ctx, readGtaoSettings(params), filtered);
    throw std::invalid_argument("unknown screen-space AO method '" + method + "'");
}

}  // namespace

ScreenSpaceAoPasses planScreenSpaceAo(const std::string& method, const ParamMap& params) {
    if (!isScreenSpaceAoMethod(method))
        throw std::invalid_argument("unknown screen-space AO method '" + method + "'");
    ScreenSpaceAoPasses passes;
    passes.blur = readAoBlurSettings(params, hasNoiseTile(method)).enabled;
    passes.upsample = readHalfRes(params);
    return passes;
}

GlTexture computeScreenSpaceAO(const std::string& method, const GBuffer& gbuffer, const View& view, float radius,
                               const ParamMap& params, uint64_t seed, PassTimer& timer) {
    if (!isScreenSpaceAoMethod(method))
        throw std::invalid_argument("unknown screen-space AO method '" + method + "'");
    if (!std::isfinite(radius) || !(radius > 0.f))
        throw std::invalid_argument(method + ": AO radius must be finite and > 0, got " + std::to_string(radius));
    if (gbuffer.width <= 0 || gbuffer.height <= 0 || !gbuffer.position || !gbuffer.normal)
        throw std::invalid_argument(method + ": G-buffer has no position/normal attachments");
    if (view.width != gbuffer.width || view.height != gbuffer.height)
        throw std::invalid_argument(method + ": view is " + std::to_string(view.width) + "x" +
                                    std::to_string(view.height) + " but the G-buffer is " +
                                    std::to_string(gbuffer.width) + "x" + std::to_string(gbuffer.height));

    // Read every parameter before any GL work, so a bad value fails fast.
    AoBlurSettings blur = readAoBlurSettings(params, hasNoiseTile(method));
    bool halfRes = readHalfRes(params);
    AoPassContext ctx = makeAoPassContext(gbuffer, view, radius, halfRes ? 2 : 1, seed);

    GlTexture ao;
    {
        auto scope = timer.scope("ssao");
        ao = evaluate(method, ctx, params, blur.enabled || halfRes);
    }
    if (blur.enabled) {
        auto scope = timer.scope("blur");
        ao = blur.mode == AoBlurMode::Box ? runBoxBlur(ctx, ao) : runBilateralBlur(ctx, ao, blur, !halfRes);
    }
    if (halfRes) {
        auto scope = timer.scope("upsample");
        ao = runDepthAwareUpsample(ctx, ao, blur);
    }
    return ao;
}

}  // namespace vct
