// hbao: horizon-based AO (Bavoil and Sainz 2008; NVIDIA gl_ssao).
#pragma once

#include "ao/ao_pass.h"
#include "ao/hbao_shared.h"
#include "render/params.h"

namespace vct {

struct HbaoSettings {
    int directions = gpu::HBAO_DEFAULT_DIRECTIONS;  // [1, 32]
    int steps = gpu::HBAO_DEFAULT_STEPS;            // per direction, [1, 64]
    float angleBias = gpu::HBAO_DEFAULT_ANGLE_BIAS; // radians added to the tangent angle, [0, 1]
};

HbaoSettings readHbaoSettings(const ParamMap& params);
GlTexture runHbao(const AoPassContext& ctx, const HbaoSettings& settings);

}  // namespace vct
