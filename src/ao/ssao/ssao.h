// ssao-crytek (Mittring 2007, Crysis) and ssao-hemisphere (Chapman; LearnOpenGL "SSAO"):
// kernel points around p tested against the depth buffer. Both read `ssao.*` keys.
#pragma once

#include "ao/screen_space.h"
#include "ao/ssao_shared.h"
#include "core/settings.h"

#include <array>
#include <vector>

namespace vct {

struct SsaoSettings {
    int samples = gpu::SSAO_DEFAULT_SAMPLES;  // kernel points
    float bias = gpu::SSAO_DEFAULT_BIAS;      // depth bias as a fraction of R
    bool rangeCheck = true;                   // LearnOpenGL's smoothstep(0, 1, R / |d_p - d_scene|)
};
const SettingsTable<SsaoSettings>& ssaoSettings();

// Unit-radius kernel offsets (xyz, w = 0), deterministic in `seed`.
// SSAO_KERNEL_SPHERE: uniform in the unit ball (rejection sampling), as Crysis.
// SSAO_KERNEL_HEMISPHERE: uniform directions with z > 0 (rejection sampling in the ball, then
// normalized), length uniform in [0, 1) times lerp(0.1, 1, (i / N)^2), as LearnOpenGL.
std::vector<glm::vec4> makeSsaoKernel(int kind, int samples, uint64_t seed);
// The 4x4 rotation tile: random tangent-plane vectors (hemisphere) or unit vectors (sphere).
std::array<glm::vec4, 16> makeSsaoNoise(int kind, uint64_t seed);

GlTexture runSsao(const AoPassContext& ctx, int kind, const SsaoSettings& settings);

const ScreenSpaceAo& ssaoCrytekEstimator();
const ScreenSpaceAo& ssaoHemisphereEstimator();
const Method& ssaoCrytekMethod();
const Method& ssaoHemisphereMethod();

}  // namespace vct
