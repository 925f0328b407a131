// Screen-space AO estimators over the G-buffer (BRIEF section 2): ssao-crytek,
// ssao-hemisphere, ssao-horizon, alchemy, hbao, gtao. Every method takes the reference's
// world radius R and returns A in [0, 1] (1 = open) at the G-buffer's resolution; sky is 1.
#pragma once

#include "gl/handles.h"
#include "render/gbuffer.h"
#include "render/params.h"
#include "render/timing.h"
#include "render/view.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

bool isScreenSpaceAoMethod(const std::string& method);
std::vector<std::string> screenSpaceAoMethods();

// The passes a method will run with these parameters (reads `blur`, `ao.half-res`).
struct ScreenSpaceAoPasses {
    bool evaluate = true;   // timer scope "ssao"
    bool blur = true;       // timer scope "blur" (bilateral or box)
    bool upsample = false;  // timer scope "upsample" (ao.half-res=1)
};
ScreenSpaceAoPasses planScreenSpaceAo(const std::string& method, const ParamMap& params);

// Runs `method` and returns an R32F texture of gbuffer.width x gbuffer.height (GL bottom-left
// origin, as the G-buffer). `view` must be the camera the G-buffer was rendered with;
// `seed` fixes kernels and per-pixel noise. Throws std::invalid_argument for an unknown
// method, a radius that is not finite and > 0, a view/G-buffer size mismatch or a bad param.
GlTexture computeScreenSpaceAO(const std::string& method, const GBuffer& gbuffer, const View& view, float radius,
                               const ParamMap& params, uint64_t seed, PassTimer& timer);

}  // namespace vct
