#include "raster/raster_programs.h"

namespace vct {

ProgramKey gbufferProgramKey(bool textures, bool alphaMask, bool materials, bool vertexColors) {
    ShaderDefines d;
    if (!vertexColors) d.push_back({"SCENE_NO_VERTEX_COLORS", "1"});
    if (!materials) d.push_back({"GBUFFER_SURFACE_ONLY", "1"});
    if (!textures) d.push_back({"SCENE_NO_TEXTURES", "1"});
    if (!alphaMask) d.push_back({"SCENE_NO_ALPHA_MASK", "1"});
    return graphicsProgramKey("raster/gbuffer_vert.glsl", "raster/gbuffer_frag.glsl", d);
}

ProgramKey shadowProgramKey(bool alphaMask, bool textures, bool vertexColors) {
    if (!alphaMask) return graphicsProgramKey("raster/shadow_vert.glsl", "raster/shadow_frag.glsl");
    // The alpha test needs the texture coordinates and colours: the G-buffer's vertex stage.
    ShaderDefines d = {{"SHADOW_ALPHA_TEST", "1"}};
    if (!textures) d.push_back({"SCENE_NO_TEXTURES", "1"});
    if (!vertexColors) d.push_back({"SCENE_NO_VERTEX_COLORS", "1"});
    return graphicsProgramKey("raster/gbuffer_vert.glsl", "raster/shadow_frag.glsl", d);
}
ProgramKey directLightProgramKey() { return computeProgramKey("raster/direct_comp.glsl"); }
ProgramKey compositeProgramKey() { return computeProgramKey("raster/composite_comp.glsl"); }

std::vector<ProgramKey> rasterProgramVariants() {
    std::vector<ProgramKey> v;
    for (bool textures : {false, true})
        for (bool alpha : {false, true})
            for (bool materials : {false, true})
                for (bool colors : {false, true}) v.push_back(gbufferProgramKey(textures, alpha, materials, colors));
    v.push_back(shadowProgramKey(false, false, false));
    for (bool textures : {false, true})
        for (bool colors : {false, true}) v.push_back(shadowProgramKey(true, textures, colors));
    v.push_back(directLightProgramKey());
    v.push_back(compositeProgramKey());
    return v;
}

}  // namespace vct
