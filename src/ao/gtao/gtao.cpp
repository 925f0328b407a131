#include "ao/gtao/gtao.h"

#include <stdexcept>

namespace vct {

void gtaoPresetCounts(const std::string& preset, int& slices, int& steps) {
    if (preset == "low") { slices = gpu::GTAO_PRESET_LOW_SLICES; steps = gpu::GTAO_PRESET_LOW_STEPS; }
    else if (preset == "medium") { slices = gpu::GTAO_PRESET_MEDIUM_SLICES; steps = gpu::GTAO_PRESET_MEDIUM_STEPS; }
    else if (preset == "high") { slices = gpu::GTAO_PRESET_HIGH_SLICES; steps = gpu::GTAO_PRESET_HIGH_STEPS; }
    else if (preset == "ultra") { slices = gpu::GTAO_PRESET_ULTRA_SLICES; steps = gpu::GTAO_PRESET_ULTRA_STEPS; }
    else throw InternalError("gtaoPresetCounts", "unknown preset '" + preset + "'");
}

const SettingsTable<GtaoSettings>& gtaoSettings() {
    auto presetSlices = [](const GtaoSettings& s) {
        int slices = 0, steps = 0;
        gtaoPresetCounts(s.preset, slices, steps);
        return slices;
    };
    auto presetSteps = [](const GtaoSettings& s) {
        int slices = 0, steps = 0;
        gtaoPresetCounts(s.preset, slices, steps);
        return steps;
    };
    static const auto table =
        SettingsTable<GtaoSettings>()
            .choice("gtao.preset", &GtaoSettings::preset,
                    {{"low", "low"}, {"medium", "medium"}, {"high", "high"}, {"ultra", "ultra"}},
                    "gtao: XeGTAO quality preset, slices x steps 1x2, 2x2, 3x3, 9x3")
            .integer("gtao.slices", &GtaoSettings::slices, presetSlices, "the preset's", 1, gpu::GTAO_MAX_SLICES,
                     "gtao: slices per pixel (overrides gtao.preset)")
            .integer("gtao.steps", &GtaoSettings::steps, presetSteps, "the preset's", 1, gpu::GTAO_MAX_STEPS,
                     "gtao: horizon samples per side of a slice (overrides gtao.preset)")
            .real("gtao.radius-multiplier", &GtaoSettings::radiusMultiplier, 0.1f, 10.f,
                  "gtao: sampling radius / R (XeGTAO: 1.457, centring the falloff on R)")
            .real("gtao.falloff-range", &GtaoSettings::falloffRange, 0.01f, 1.f,
                  "gtao: fraction of the sampling radius over which samples fade out")
            .real("gtao.sample-power", &GtaoSettings::samplePower, 1.f, 4.f,
                  "gtao: step distribution exponent (samples crowd near p)")
            .real("gtao.thin-occluder", &GtaoSettings::thinOccluder, 0.f, 0.7f,
                  "gtao: thin-occluder compensation (XeGTAO's thickness heuristic)")
            .real("gtao.final-power", &GtaoSettings::finalPower, 0.25f, 5.f,
                  "gtao: exponent applied to the visibility (XeGTAO: 2.2)")
            .flag("gtao.multibounce", &GtaoSettings::multiBounce,
                  "gtao: multi-bounce fit from the G-buffer albedo (Jimenez et al. 2016)");
    return table;
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

const ScreenSpaceAo& gtaoEstimator() {
    static const ScreenSpaceAo e = [] {
        ScreenSpaceAo s;
        s.name = "gtao";
        s.summary = "ground-truth-based AO (Jimenez et al. 2016, after XeGTAO)";
        s.settings = [] { return gtaoSettings().docs(); };
        s.presetValues = [](const ParamMap& params) {
            const GtaoSettings g = gtaoSettings().read(params);
            return std::map<std::string, std::string>{{"gtao.slices", std::to_string(g.slices)},
                                                      {"gtao.steps", std::to_string(g.steps)}};
        };
        s.readsAlbedo = [](const ParamMap& params) { return gtaoSettings().read(params).multiBounce; };
        s.evaluate = [](const AoPassContext& ctx, const ParamMap& params, bool filtered) {
            return runGtao(ctx, gtaoSettings().read(params), filtered);
        };
        s.programs = {computeProgramKey("ao/gtao.glsl")};
        return s;
    }();
    return e;
}

const Method& gtaoMethod() {
    static const Method m = screenSpaceMethod(gtaoEstimator());
    return m;
}

}  // namespace vct
