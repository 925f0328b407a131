#include "cone/cone_programs.h"

#include "cone/cone_shared.h"
#include "voxelize/voxel_gl.h"

namespace vct {

namespace {
ShaderDefines coneDefines(bool gi, bool aniso) { return {{"CONE_GI", gi ? "1" : "0"}, {"CONE_ANISO", aniso ? "1" : "0"}}; }
ShaderDefines coneDefines(bool gi, ConeDirectional directional, bool depthLevels, bool sharpen, bool sheets = false) {
    ShaderDefines d = coneDefines(gi, directional != ConeDirectional::None);
    if (sheets && directional != ConeDirectional::None) d.push_back({"CONE_SHEETS", "1"});
    if (directional == ConeDirectional::Packed) d.push_back({"CONE_ANISO_PACKED", "1"});
    if (depthLevels && directional != ConeDirectional::None) d.push_back({"CONE_DEPTH_LEVELS", "1"});
    if (sharpen && directional != ConeDirectional::None) d.push_back({"CONE_SHARPEN", "1"});
    return d;
}
}  // namespace

ProgramKey conePassProgramKey(bool gi, ConeDirectional directional, bool depthLevels, bool sharpen, bool sheets) {
    return computeProgramKey(gi ? "cone/cone_gi.glsl" : "cone/cone_ao.glsl",
                             coneDefines(gi, directional, depthLevels, sharpen, sheets));
}

ProgramKey clipmapConePassProgramKey(bool gi) {
    return computeProgramKey(gi ? "cone/cone_gi.glsl" : "cone/cone_ao.glsl",
                             {{"CONE_GI", gi ? "1" : "0"}, {"CONE_CLIPMAP", "1"}});
}

ProgramKey coneResolveProgramKey(bool gi) {
    ShaderDefines d = coneDefines(gi, false);
    d.push_back({"CONE_RESOLVE_STAGE", "1"});
    return computeProgramKey(gi ? "cone/cone_gi.glsl" : "cone/cone_ao.glsl", d);
}

ProgramKey coneBounceProgramKey(bool aniso, GLenum radianceFormat, BouncePass pass, bool depthLevels, bool sharpen) {
    // The list and emission passes march no cones: one variant whatever the levels hold.
    const bool gathers = pass == BouncePass::Gather;
    ShaderDefines d = coneDefines(true, aniso ? ConeDirectional::Six : ConeDirectional::None, depthLevels && gathers,
                                  sharpen && gathers);
    d.push_back({"RADIANCE_FORMAT", glslImageFormat(radianceFormat)});
    d.push_back({"RADIANCE_FORMAT_MAX", formatMaxLiteral(radianceFormat)});
    if (pass == BouncePass::List) d.push_back({"BOUNCE_LIST", "1"});
    if (pass == BouncePass::Emitted) d.push_back({"BOUNCE_EMITTED", "1"});
    return computeProgramKey("cone/cone_bounce.glsl", d);
}

ProgramKey voxelViewProgramKey(int channel) {
    // The channel is a preprocessor switch: GLSL `const int`s are not visible to #if.
    ShaderDefines d;
    if (channel == gpu::CONE_CHANNEL_RADIANCE) d = {{"CONE_VIEW_RADIANCE", "1"}};
    if (channel == gpu::CONE_CHANNEL_ALBEDO) d = {{"CONE_VIEW_ALBEDO", "1"}};
    return computeProgramKey("cone/cone_raymarch.glsl", d);
}

ProgramKey coneCountProgramKey(bool gi, ConeDirectional directional, bool depthLevels, bool sharpen, bool sheets) {
    return computeProgramKey("bench/cone_count.glsl", coneDefines(gi, directional, depthLevels, sharpen, sheets));
}

ProgramKey fetchBenchProgramKey() { return computeProgramKey("bench/fetch.glsl"); }

ProgramKey coneMarchCheckProgramKey() { return computeProgramKey("cone/cone_march_check.glsl"); }

std::vector<ProgramKey> coneProgramVariants() {
    std::vector<ProgramKey> v;
    for (bool gi : {false, true}) {
        for (ConeDirectional d : {ConeDirectional::None, ConeDirectional::Six, ConeDirectional::Packed}) {
            if (gi && d == ConeDirectional::Packed) continue;  // a lit grid has its six
            for (bool depth : {false, true})
                for (bool sharpen : {false, true}) {
                    // Depth and the sharpened filter live in directional levels.
                    if ((depth || sharpen) && d == ConeDirectional::None) continue;
                    for (bool sheets : {false, true}) {
                        v.push_back(conePassProgramKey(gi, d, depth, sharpen, sheets));
                        v.push_back(coneCountProgramKey(gi, d, depth, sharpen, sheets));
                    }
                }
        }
        v.push_back(clipmapConePassProgramKey(gi));
        v.push_back(coneResolveProgramKey(gi));
    }
    for (bool aniso : {false, true})
        for (GLenum f : {GLenum(GL_RGBA16F), GLenum(GL_RGBA32F)})
            for (BouncePass pass : {BouncePass::List, BouncePass::Emitted, BouncePass::Gather})
                for (bool depth : {false, true})  // the key ignores depth and sharpen but for gathers with aniso
                    for (bool sharpen : {false, true})
                        if (!((depth || sharpen) && (pass != BouncePass::Gather || !aniso)))
                            v.push_back(coneBounceProgramKey(aniso, f, pass, depth, sharpen));
    for (int c : {gpu::CONE_CHANNEL_OPACITY, gpu::CONE_CHANNEL_ALBEDO, gpu::CONE_CHANNEL_RADIANCE})
        v.push_back(voxelViewProgramKey(c));
    v.push_back(fetchBenchProgramKey());
    v.push_back(coneMarchCheckProgramKey());
    return v;
}

}  // namespace vct
