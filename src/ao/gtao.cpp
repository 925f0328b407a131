#include "ao/gtao.h"

#include <stdexcept>

namespace vct {

void gtaoPresetCounts(const std::string& preset, int& slices, int& steps) {
    if (preset == "low") { slices = gpu::GTAO_PRESET_LOW_SLICES; steps = gpu::GTAO_PRESET_LOW_STEPS; }
    else if (preset == "medium") { slices = gpu::GTAO_PRESET_MEDIUM_SLICES; steps = gpu::GTAO_PRESET_MEDIUM_STEPS; }
    else if (preset == "high") { slices = gpu::GTAO_PRESET_HIGH_SLICES; steps = gpu::GTAO_PRESET_HIGH_STEPS; }
    else if (preset == "ultra") { slices = gpu::GTAO_PRESET_ULTRA_SLICES; steps = gpu::GTAO_PRESET_ULTRA_STEPS; }
    else throw std::invalid_argument("gtao preset '" + preset + "': expected low|medium|high|ultra");
}

GtaoSettings readGtaoSettings(const ParamMap& params) {
    GtaoSettings s;
    s.preset = params.getChoice("gtao.preset", s.preset, {"low", "medium", "high", "ultra"},
                                "gtao: XeGTAO quality preset, slices x steps 1x2, 2x2, 3x3, 9x3");
    gtaoPresetCounts(s.preset, s.slices, s.steps);
    s.slices = params.getInt("gtao.slices", s.slices, 1, gpu::GTAO_MAX_SLICES,
                             "gtao: slices per pixel (overrides gtao.preset)");
    s.steps = params.getInt("gtao.steps", s.steps, 1, gpu::GTAO_MAX_STEPS,
                            "gtao: horizon samples per side of a slice (overrides gtao.preset)");
    s.radiusMultiplier = params.getFloat("gtao.radius-multiplier", s.radiusMultiplier, 0.1f, 10.f,
                                         "gtao: sampling radius / R (XeGTAO: 1.457, centring the falloff on R)");
    s.falloffRange = params.getFloat("gtao.falloff-range", s.falloffRange, 0.01f, 1.f,
                                     "gtao: fraction of the sampling radius over which samples fade out");
    s.samplePower = params.getFloat("gtao.sample-power", s.samplePower, 1.f, 4.f,
                                    "gtao: step distribution exponent (samples crowd near p)");
    s.thinOccluder = params.getFloat("gtao.thin-occluder", s.thinOccluder, 0.f, 0.7f,
                                     "gtao: thin-occluder compensation (XeGTAO's thickness heuristic)");
    s.finalPower = params.getFloat("gtao.final-power", s.finalPower, 0.25f, 5.f,
                                   "gtao: exponent applied to the visibility (XeGTAO: 2.2)");
    s.multiBounce = params.getBool("gtao.multibounce", s.multiBounce,
                                   "gtao: multi-bounce fit from the G-buffer albedo (Jimenez et al. 2016)");
    return s;
}

GlTexture runGtao(const AoPassContext& ctx, const GtaoSettings& settings, bool filtered) {
    float effectRadius = ctx.radius * settings.radiusMultiplier;
    float falloffRange = settings.falloffRange * effectRadius;
    float falloffFrom = effectRadius * (1.f - settings.falloffRange);
    gpu::GtaoUniforms u{};
    u.config = glm::ivec4(settings.slices, settings.steps, settings.multiBounce ? 1 : 0, 0);
    // weight = saturate(dist * mul + add): 1 up to falloffFrom, 0 from effectRadius on.
    u.falloff = glm::vec4(effectRadius, -1.f / falloffRange, falloffFrom / falloffRange + 1.f, settings.samplePower);
    u.shaping = glm::vec4(settings.thinOccluder, settings.finalPower, filtered ? gpu::AO_WORKING_MAX : 1.f, 0.f);
    GlBuffer block = uploadUniformBlock(u, gpu::AO_BINDING_TECHNIQUE);
    bindAoPassInputs(ctx);
    GlTexture out = createAoTexture(ctx.evalWidth, ctx.evalHeight);
    dispatchAoPass(cachedProgram(computeProgramKey("ao/gtao.glsl")), out, ctx.evalWidth, ctx.evalHeight);
    return out;
}

}  // namespace vct
