#include "voxelize/voxel_programs.h"

#include "voxelize/voxel_gl.h"

namespace vct {

ProgramKey voxelizeProgramKey(VoxelizePass pass, bool bigPass, bool twoSided, bool opacityOnly, bool sheets) {
    ShaderDefines d;
    if (bigPass) d.push_back({"BIG_PASS", "1"});
    if (sheets && pass == VoxelizePass::Coverage) d.push_back({"EDGE_SHEETS", "1"});
    const bool geometry = pass == VoxelizePass::Geometry;
    if (twoSided && geometry && !opacityOnly) d.push_back({"TWO_SIDED", "1"});
    if (opacityOnly && geometry) d.push_back({"OPACITY_ONLY", "1"});
    // One source per pass, each declaring only the images it binds.
    const char* source = pass == VoxelizePass::Emission   ? "voxelize/voxelize_emission.glsl"
                         : pass == VoxelizePass::Coverage ? "voxelize/voxelize_coverage.glsl"
                                                          : "voxelize/voxelize.glsl";
    return computeProgramKey(source, d);
}

ProgramKey resolveProgramKey(bool hasEmission, GLenum emissionFormat, bool twoSided, bool opacityOnly,
                             bool edgeCoverage) {
    ShaderDefines d;
    if (edgeCoverage) d.push_back({"EDGE_COVERAGE", "1"});
    if (opacityOnly) {
        d.push_back({"OPACITY_ONLY", "1"});
        emissionFormat = GL_RGBA16F;  // no emission is written: one variant
    } else {
        if (hasEmission) d.push_back({"HAS_EMISSION", "1"});
        if (twoSided) d.push_back({"TWO_SIDED", "1"});
    }
    d.push_back({"EMISSION_FORMAT", glslImageFormat(emissionFormat)});
    d.push_back({"EMISSION_FORMAT_MAX", formatMaxLiteral(emissionFormat)});
    return computeProgramKey("voxelize/resolve.glsl", d);
}

ProgramKey sheetsProgramKey() { return computeProgramKey("voxelize/voxelize_sheets.glsl"); }

ProgramKey injectProgramKey(GLenum radianceFormat, int outerLevels, bool twoSided, bool lightBatches) {
    ShaderDefines d = {{"RADIANCE_FORMAT", glslImageFormat(radianceFormat)},
                       {"RADIANCE_FORMAT_MAX", formatMaxLiteral(radianceFormat)}};
    if (outerLevels > 0) d.push_back({"OUTER_LEVELS", std::to_string(outerLevels)});
    if (twoSided) d.push_back({"TWO_SIDED", "1"});
    if (lightBatches) d.push_back({"LIGHT_BATCHES", "1"});
    return computeProgramKey("voxelize/inject.glsl", d);
}

ProgramKey isotropicMipProgramKey(GLenum radianceFormat, bool normals) {
    ShaderDefines d;
    if (radianceFormat != 0) d = {{"HAS_RADIANCE", "1"}, {"RADIANCE_FORMAT", glslImageFormat(radianceFormat)}};
    if (normals) d.push_back({"HAS_NORMAL", "1"});
    return computeProgramKey("voxelize/mip_iso.glsl", d);
}

ProgramKey anisotropicMipProgramKey(GLenum srcFormat, GLenum dstFormat, bool packedOpacity) {
    ShaderDefines d = {{"SRC_FORMAT", glslImageFormat(srcFormat)}, {"DST_FORMAT", glslImageFormat(dstFormat)}};
    if (srcFormat == GL_R16F) d.push_back({"SOURCE_OPACITY", "1"});
    else if (packedOpacity) d.push_back({"SOURCE_PACKED", "1"});
    if (packedOpacity) d.push_back({"DEST_PACKED", "1"});
    return computeProgramKey("voxelize/mip_aniso.glsl", d);
}

ProgramKey clipmapNestProgramKey(GLenum dstFormat) {
    return computeProgramKey("voxelize/clipmap_nest.glsl", {{"DST_FORMAT", glslImageFormat(dstFormat)}});
}

std::vector<ProgramKey> voxelProgramVariants() {
    std::vector<ProgramKey> v;
    const GLenum radianceFormats[] = {GL_RGBA16F, GL_RGBA32F};
    for (bool big : {false, true}) {
        v.push_back(voxelizeProgramKey(VoxelizePass::Emission, big, false));
        for (bool sheets : {false, true}) v.push_back(voxelizeProgramKey(VoxelizePass::Coverage, big, false, false, sheets));
        for (bool twoSided : {false, true}) v.push_back(voxelizeProgramKey(VoxelizePass::Geometry, big, twoSided));
        v.push_back(voxelizeProgramKey(VoxelizePass::Geometry, big, false, true));
    }
    for (bool coverage : {false, true}) {
        v.push_back(resolveProgramKey(false, GL_RGBA16F, false, true, coverage));
        for (bool emission : {false, true})
            for (GLenum f : radianceFormats)
                for (bool twoSided : {false, true}) v.push_back(resolveProgramKey(emission, f, twoSided, false, coverage));
    }
    v.push_back(sheetsProgramKey());
    for (GLenum f : radianceFormats)
        for (int outer = 0; outer <= 7; ++outer)
            for (bool twoSided : {false, true})
                for (bool batches : {false, true}) v.push_back(injectProgramKey(f, outer, twoSided, batches));
    v.push_back(isotropicMipProgramKey(0, false));
    for (GLenum f : radianceFormats)
        for (bool normals : {false, true}) v.push_back(isotropicMipProgramKey(f, normals));
    v.push_back(anisotropicMipProgramKey(GL_R16F, GL_RGBA16F, true));
    v.push_back(anisotropicMipProgramKey(GL_RGBA16F, GL_RGBA16F, true));
    for (GLenum f : radianceFormats) v.push_back(anisotropicMipProgramKey(f, f, false));
    for (GLenum f : {GLenum(GL_R16F), GLenum(GL_RGBA16F), GLenum(GL_RGBA32F)}) v.push_back(clipmapNestProgramKey(f));
    return v;
}

}  // namespace vct
