#include "raster/raster_programs.h"

namespace vct {

RasterSceneFeatures rasterFeaturesOf(const GpuScene& s) {
    return {s.hasTextures, s.hasAlphaMask, s.hasVertexColors, s.hasWrapModes};
}

namespace {

// The SCENE_NO_* defines of what the scene lacks.
ShaderDefines sceneDefines(const RasterSceneFeatures& f) {
    ShaderDefines d;
    if (!f.vertexColors) d.push_back({"SCENE_NO_VERTEX_COLORS", "1"});
    if (!f.textures) d.push_back({"SCENE_NO_TEXTURES", "1"});
    if (!f.alphaMask) d.push_back({"SCENE_NO_ALPHA_MASK", "1"});
    if (!f.wrapModes) d.push_back({"SCENE_NO_WRAP_MODES", "1"});
    return d;
}

}  // namespace

ProgramKey gbufferProgramKey(const RasterSceneFeatures& f, bool materials) {
    ShaderDefines d = sceneDefines(f);
    if (!materials) d.push_back({"GBUFFER_SURFACE_ONLY", "1"});
    return graphicsProgramKey("raster/gbuffer_vert.glsl", "raster/gbuffer_frag.glsl", d);
}

ProgramKey shadowProgramKey(const RasterSceneFeatures& f) {
    if (!f.alphaMask) return graphicsProgramKey("raster/shadow_vert.glsl", "raster/shadow_frag.glsl");
    // The alpha test needs the texture coordinates and colours: the G-buffer's vertex stage.
    ShaderDefines d = sceneDefines(f);
    d.push_back({"SHADOW_ALPHA_TEST", "1"});
    return graphicsProgramKey("raster/gbuffer_vert.glsl", "raster/shadow_frag.glsl", d);
}

ProgramKey directLightProgramKey() { return computeProgramKey("raster/direct_comp.glsl"); }
ProgramKey compositeProgramKey() { return computeProgramKey("raster/composite_comp.glsl"); }

std::vector<ProgramKey> rasterProgramVariants() {
    std::vector<ProgramKey> v;
    for (bool textures : {false, true})
        for (bool alpha : {false, true})
            for (bool colors : {false, true})
                for (bool wrap : {false, true}) {
                    if (wrap && !textures) continue;  // wrap modes need a texture
                    const RasterSceneFeatures f{textures, alpha, colors, wrap};
                    for (bool materials : {false, true}) v.push_back(gbufferProgramKey(f, materials));
                    if (alpha) v.push_back(shadowProgramKey(f));  // without masks: one program, below
                }
    v.push_back(shadowProgramKey(RasterSceneFeatures{false, false, false, false}));
    v.push_back(directLightProgramKey());
    v.push_back(compositeProgramKey());
    return v;
}

}  // namespace vct
