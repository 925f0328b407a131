#include "ao/ssao/ssao.h"

#include "ao/ao_random.h"

#include <cmath>

namespace vct {

const SettingsTable<SsaoSettings>& ssaoSettings() {
    static const auto table =
        SettingsTable<SsaoSettings>()
            .integer("ssao.samples", &SsaoSettings::samples, 1, gpu::SSAO_MAX_SAMPLES,
                     "ssao-crytek/ssao-hemisphere: kernel points per pixel (LearnOpenGL: 64)")
            .real("ssao.bias", &SsaoSettings::bias, 0.f, 1.f,
                  "ssao-*: depth bias as a fraction of R (LearnOpenGL: 0.025 at R = 0.5)")
            .flag("ssao.range-check", &SsaoSettings::rangeCheck,
                  "ssao-*: fade occluders by smoothstep(0, 1, R / |d_p - d_scene|)");
    return table;
}

namespace {
glm::vec3 pointInUnitBall(SplitMix64& rng) {
    for (;;) {
        glm::vec3 u(rng.uniform(-1.f, 1.f), rng.uniform(-1.f, 1.f), rng.uniform(-1.f, 1.f));
        float r2 = glm::dot(u, u);
        if (r2 <= 1.f && r2 > 1e-6f) return u;
    }
}
}  // namespace

std::vector<glm::vec4> makeSsaoKernel(int kind, int samples, uint64_t seed) {
    SplitMix64 rng(seed ^ 0x55A0CE4Eull);
    std::vector<glm::vec4> kernel;
    kernel.reserve(size_t(samples));
    for (int i = 0; i < samples; ++i) {
        glm::vec3 u = pointInUnitBall(rng);
        if (kind == gpu::SSAO_KERNEL_HEMISPHERE) {
            glm::vec3 dir = glm::normalize(glm::vec3(u.x, u.y, std::abs(u.z)));
            float t = float(i) / float(samples);
            float scale = 0.1f + 0.9f * t * t;  // more points near p, where occluders matter most
            u = dir * rng.uniform(0.f, 1.f) * scale;
        }
        kernel.emplace_back(u, 0.f);
    }
    return kernel;
}

std::array<glm::vec4, 16> makeSsaoNoise(int kind, uint64_t seed) {
    SplitMix64 rng(seed ^ 0x4E015Eull);
    std::array<glm::vec4, 16> tile;
    for (auto& v : tile) {
        if (kind == gpu::SSAO_KERNEL_HEMISPHERE) {
            v = glm::vec4(rng.uniform(-1.f, 1.f), rng.uniform(-1.f, 1.f), 0.f, 0.f);
        } else {
            v = glm::vec4(glm::normalize(pointInUnitBall(rng)), 0.f);
        }
    }
    return tile;
}

GlTexture runSsao(const AoPassContext& ctx, int kind, const SsaoSettings& settings) {
    gpu::SsaoUniforms u{};
    u.config = glm::ivec4(kind, settings.samples, settings.rangeCheck ? 1 : 0, 0);
    u.bias = glm::vec4(settings.bias * ctx.radius, 0.f, 0.f, 0.f);
    auto noise = makeSsaoNoise(kind, ctx.seed);
    for (int i = 0; i < 16; ++i) u.noise[i] = noise[size_t(i)];
    std::vector<glm::vec4> kernel = makeSsaoKernel(kind, settings.samples, ctx.seed);

    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    GlBuffer kernelBuffer = createBuffer(kernel.size() * sizeof(glm::vec4), kernel.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::AO_BINDING_KERNEL, kernelBuffer.id());
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/ssao.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}

namespace {

ScreenSpaceAo ssaoEstimator(const std::string& name, int kind, const std::string& summary) {
    ScreenSpaceAo e;
    e.name = name;
    e.summary = summary;
    e.noiseTile = true;
    e.settings = [] { return ssaoSettings().docs(); };
    e.evaluate = [kind](const AoPassContext& ctx, const ParamMap& params, bool) {
        return runSsao(ctx, kind, ssaoSettings().read(params));
    };
    e.programs = {computeProgramKey("ao/ssao.glsl")};
    return e;
}

}  // namespace

const ScreenSpaceAo& ssaoCrytekEstimator() {
    static const ScreenSpaceAo e = ssaoEstimator("ssao-crytek", gpu::SSAO_KERNEL_SPHERE,
                                                 "Crysis' SSAO: kernel points in a sphere around p");
    return e;
}

const ScreenSpaceAo& ssaoHemisphereEstimator() {
    static const ScreenSpaceAo e = ssaoEstimator("ssao-hemisphere", gpu::SSAO_KERNEL_HEMISPHERE,
                                                 "normal-oriented hemisphere SSAO (LearnOpenGL)");
    return e;
}

const Method& ssaoCrytekMethod() {
    static const Method m = screenSpaceMethod(ssaoCrytekEstimator());
    return m;
}

const Method& ssaoHemisphereMethod() {
    static const Method m = screenSpaceMethod(ssaoHemisphereEstimator());
    return m;
}

}  // namespace vct
