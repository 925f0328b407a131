#include "denoise/atrous.h"

#include "core/errors.h"
#include "gl/program.h"

#include <string>

namespace vct {

static_assert(gpu::ATROUS_UNIT_POSITION == kUnitPosition && gpu::ATROUS_UNIT_NORMAL == kUnitNormal &&
                  gpu::ATROUS_UNIT_ALBEDO == kUnitAlbedo,
              "the a-trous filter reads the G-buffer at the units of core/gbuffer.h");

namespace {

ProgramKey passKey(const char* shader, int channels) {
    return computeProgramKey(std::string("denoise/") + shader, {{"ATROUS_CHANNELS", std::to_string(channels)}});
}

void runPass(GLuint program, const gpu::AtrousUniforms& u, const GlTexture& in, const GlTexture& out, int w, int h) {
    glUseProgram(program);
    GlBuffer block = createBuffer(sizeof(u), &u, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::ATROUS_BINDING_UNIFORMS, block.id());
    glBindTextureUnit(gpu::ATROUS_UNIT_INPUT, in.id());
    glBindImageTexture(gpu::ATROUS_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groupCount(w, gpu::ATROUS_LOCAL_SIZE), groupCount(h, gpu::ATROUS_LOCAL_SIZE), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace

// Defaults, chosen by RMSE against the 256-spp reference (rtao-denoised and pt-denoised at 1
// and 4 spp, R = 0.5, 64 and 128 px) on the Cornell box, the default scene and offscreen_thin;
// tests/gpu/denoised_test.cpp prints the Cornell box's:
// - 3 iterations: best or tied everywhere (at 4 spp, 64 px, AO 0.077 / 0.055 / 0.037 against
//   0.080 / 0.064 / 0.038 for Dammertz et al.'s 5; at 128 px 0.051 / 0.038 / 0.022 against
//   0.053 / 0.044 / 0.023), GI within 0.5 % of the reference's mean either way. Without the
//   luminance term more iterations only blur: 5 of them double the AO error of 1.
// - sigma_luminance 4 (SVGF's): the luminance term cuts the Cornell box's AO error at 4 spp
//   from 0.121 to 0.077; 2 suits AO better (0.065) but leaves GI's noise (31 % against 17 %
//   RMSE), 8 keeps more bias in AO (0.091).
// - sigma_depth 0.01, sigma_normal 64 (halving at 8 degrees; SVGF: 128), sigma_albedo 0.1: on
//   these scenes of flat, hard-edged surfaces, 3x either way changes no error by more than
//   0.001; they matter at depth steps, creases and material edges, which
//   tests/gpu/atrous_test.cpp pins down.
const SettingsTable<AtrousSettings>& atrousSettings() {
    static const auto table =
        SettingsTable<AtrousSettings>()
            .integer("atrous.iterations", &AtrousSettings::iterations, 0, gpu::ATROUS_MAX_ITERATIONS,
                     "a-trous filter: iterations, taps 1, 2, 4, ... pixels apart (0 = unfiltered)")
            .real("atrous.sigma-depth", &AtrousSettings::sigmaDepth, 1e-4f, 1.f,
                  "a-trous filter: a tap's distance from the centre's tangent plane at which its weight falls "
                  "to 0.61, x the view depth")
            .real("atrous.sigma-normal", &AtrousSettings::sigmaNormal, 0.f, 1024.f,
                  "a-trous filter: exponent of max(0, n.n') (0 = normals ignored)")
            .real("atrous.sigma-albedo", &AtrousSettings::sigmaAlbedo, 1e-3f, 10.f,
                  "a-trous filter: RGB albedo difference at which a tap's weight falls to 0.61")
            .real("atrous.sigma-luminance", &AtrousSettings::sigmaLuminance, 0.f, 1e3f,
                  "a-trous filter: luminance difference at which a tap's weight falls to 1/e, in standard "
                  "deviations of the centre's estimate (SVGF's 4; 0 = off)");
    return table;
}

std::vector<SettingDoc> withAtrousDocs(std::vector<SettingDoc> docs) {
    for (const SettingDoc& d : atrousSettings().docs()) docs.push_back(d);
    return docs;
}

std::vector<ProgramKey> atrousPrograms() {
    return {passKey("atrous_variance.glsl", 1), passKey("atrous_variance.glsl", 3), passKey("atrous.glsl", 1),
            passKey("atrous.glsl", 3)};
}

GlTexture runAtrousFilter(const GBuffer& gbuffer, const GlTexture& input, int channels,
                          const AtrousSettings& settings, bool demodulate) {
    if (channels != 1 && channels != 3)
        throw InternalError("atrous", "channels must be 1 or 3, got " + std::to_string(channels));
    const int w = gbuffer.width, h = gbuffer.height;
    GLint inputWidth = 0, inputHeight = 0;
    glGetTextureLevelParameteriv(input.id(), 0, GL_TEXTURE_WIDTH, &inputWidth);
    glGetTextureLevelParameteriv(input.id(), 0, GL_TEXTURE_HEIGHT, &inputHeight);
    if (inputWidth != w || inputHeight != h)
        throw InternalError("atrous", "input is " + std::to_string(inputWidth) + "x" + std::to_string(inputHeight) +
                                          " but the G-buffer is " + std::to_string(w) + "x" + std::to_string(h));
    glBindTextureUnit(gpu::ATROUS_UNIT_POSITION, gbuffer.position.id());
    glBindTextureUnit(gpu::ATROUS_UNIT_NORMAL, gbuffer.normal.id());
    glBindTextureUnit(gpu::ATROUS_UNIT_ALBEDO, gbuffer.albedo.id());
    gpu::AtrousUniforms u{};
    u.sigmas = glm::vec4(settings.sigmaDepth, settings.sigmaNormal, settings.sigmaAlbedo, settings.sigmaLuminance);
    const int irradiance = demodulate && channels == 3 ? 1 : 0;
    u.config = glm::ivec4(1, irradiance, 0, 0);
    GlTexture current = createTexture2D(GL_RGBA32F, w, h);
    runPass(cachedProgram(passKey("atrous_variance.glsl", channels)), u, input, current, w, h);
    // No iteration: one pass with every tap on the centre, which returns it as it is.
    const int passes = settings.iterations > 0 ? settings.iterations : 1;
    const GLuint program = cachedProgram(passKey("atrous.glsl", channels));
    for (int i = 0; i < passes; ++i) {
        u.config = glm::ivec4(settings.iterations > 0 ? 1 << i : 0, irradiance, i + 1 == passes ? 1 : 0, 0);
        GlTexture out = createTexture2D(GL_RGBA32F, w, h);
        runPass(program, u, current, out, w, h);
        current = std::move(out);
    }
    glBindTextureUnit(gpu::ATROUS_UNIT_INPUT, 0);
    return current;
}

}  // namespace vct
