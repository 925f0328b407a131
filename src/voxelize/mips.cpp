#include "voxelize/voxelize.h"

#include "core/errors.h"
#include "gl/program_cache.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxel_programs.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace vct {

namespace {

glm::ivec3 levelSize(const glm::ivec3& base, int level) { return glm::max(base >> level, glm::ivec3(1)); }

// GI grids filter their normals too: the facing test (vox_facingWeight) reads them at every
// level the cones sample.
bool filtersNormals(const VoxelGrid& grid) {
    return grid.radiance && grid.normal && textureLevelCount(grid.normal) >= grid.levels;
}

GLuint isotropicMipProgram(const VoxelGrid& grid) {
    return cachedProgram(
        isotropicMipProgramKey(grid.radiance ? textureInternalFormat(grid.radiance.id()) : 0, filtersNormals(grid)));
}

void buildIsotropicMips(VoxelGrid& grid, GLuint program) {
    const bool hasRadiance = bool(grid.radiance);
    const GLenum radianceFormat = hasRadiance ? textureInternalFormat(grid.radiance.id()) : GL_RGBA16F;
    const bool hasNormal = filtersNormals(grid);
    glUseProgram(program);
    for (int level = 1; level < grid.levels; ++level) {
        glm::ivec3 src = levelSize(grid.resolution, level - 1), dst = levelSize(grid.resolution, level);
        setUniform(program, "uSrcSize", src);
        setUniform(program, "uDstSize", dst);
        bindImage3D(0, grid.opacity.id(), level - 1, GL_READ_ONLY, GL_R16F);
        bindImage3D(1, grid.opacity.id(), level, GL_WRITE_ONLY, GL_R16F);
        if (hasRadiance) {
            bindImage3D(2, grid.radiance.id(), level - 1, GL_READ_ONLY, radianceFormat);
            bindImage3D(3, grid.radiance.id(), level, GL_WRITE_ONLY, radianceFormat);
        }
        if (hasNormal) {
            bindImage3D(4, grid.normal.id(), level - 1, GL_READ_ONLY, GL_RGBA16F);
            bindImage3D(5, grid.normal.id(), level, GL_WRITE_ONLY, GL_RGBA16F);
        }
        dispatchGrid(dst);
    }
    glUseProgram(0);
}

struct AnisoPrograms {
    GLuint first = 0;  // pyramid level 1 from the base texture
    GLuint rest = 0;   // from the directional texture's previous level
};

// A lit grid's directional levels carry radiance; an AO grid's hold opacity alone, the three
// axes in one texture (VoxelGrid::anisoOpacity).
bool packsOpacity(const VoxelGrid& grid) { return !grid.radiance; }

GLenum anisoBaseFormat(const VoxelGrid& grid) {
    return grid.radiance ? textureInternalFormat(grid.radiance.id()) : GL_R16F;
}

// RGBA16F per the contract, RGBA32F when the radiance itself needed float precision (the
// packed opacity levels: RGBA16F).
GLenum anisoFormatFor(GLenum baseFormat) { return baseFormat == GL_RGBA32F ? GL_RGBA32F : GL_RGBA16F; }

AnisoPrograms buildAnisoPrograms(const VoxelGrid& grid) {
    const GLenum baseFormat = anisoBaseFormat(grid), anisoFormat = anisoFormatFor(baseFormat);
    const bool packed = packsOpacity(grid);
    return {cachedProgram(anisotropicMipProgramKey(baseFormat, anisoFormat, packed)),
            cachedProgram(anisotropicMipProgramKey(anisoFormat, anisoFormat, packed))};
}

void buildAnisotropicMips(VoxelGrid& grid, const AnisoPrograms& programs, bool depthLevels) {
    const int anisoLevels = grid.levels - 1;
    if (anisoLevels < 1) throw InternalError("buildAnisotropicMips", "voxel grid too small for anisotropic mips");
    const bool packed = packsOpacity(grid);
    const GLenum baseFormat = anisoBaseFormat(grid), anisoFormat = anisoFormatFor(baseFormat);

    const glm::ivec3 base = levelSize(grid.resolution, 1);
    // Lit: one texture per direction (+X, -X, +Y, -Y, +Z, -Z); packed: one for the three axes.
    std::array<GlTexture, 6>& lit = grid.anisoRadiance;
    for (GlTexture& t : lit) t.reset();
    grid.anisoOpacity.reset();
    const int textures = packed ? 1 : 6;
    auto target = [&](int d) -> GlTexture& { return packed ? grid.anisoOpacity : lit[size_t(d)]; };
    for (int d = 0; d < textures; ++d) target(d) = createTexture3D(anisoFormat, base.x, base.y, base.z, anisoLevels);
    const GLuint baseTexture = packed ? grid.opacity.id() : grid.radiance.id();
    for (int level = 0; level < anisoLevels; ++level) {
        const GLuint p = level == 0 ? programs.first : programs.rest;
        glUseProgram(p);
        // Pyramid level level + 1 from pyramid level `level`.
        glm::ivec3 src = levelSize(grid.resolution, level), dst = levelSize(grid.resolution, level + 1);
        setUniform(p, "uSrcSize", src);
        setUniform(p, "uDstSize", dst);
        for (int d = 0; d < textures; ++d) {
            const GlTexture& out = target(d);
            setUniform(p, "uAxis", packed ? 0 : d / 2);
            setUniform(p, "uSign", d % 2 == 0 ? 1 : -1);
            setUniform(p, "uDepthIn", depthLevels && level > 0 ? 1 : 0);
            setUniform(p, "uDepthOut", depthLevels ? 1 : 0);
            if (level == 0) bindImage3D(0, baseTexture, 0, GL_READ_ONLY, baseFormat);
            else bindImage3D(0, out.id(), level - 1, GL_READ_ONLY, anisoFormat);
            bindImage3D(1, out.id(), level, GL_WRITE_ONLY, anisoFormat);
            dispatchGrid(dst);
        }
    }
    grid.anisotropic = true;
    grid.depthLevels = depthLevels;
    glUseProgram(0);
}

}  // namespace

void buildMips(VoxelGrid& grid, bool anisotropic, PassTimer& timer, const std::string& scopeName, bool depthLevels) {
    if (!grid.opacity) throw InternalError("buildMips", "the grid has no opacity (voxelize first)");
    const GLuint iso = isotropicMipProgram(grid);
    AnisoPrograms aniso;
    if (anisotropic) aniso = buildAnisoPrograms(grid);
    auto scope = timer.scope(scopeName, true, Reruns::WhenSceneChanges);
    buildIsotropicMips(grid, iso);
    if (anisotropic) buildAnisotropicMips(grid, aniso, depthLevels);
    else {
        for (GlTexture& t : grid.anisoRadiance) t.reset();
        grid.anisoOpacity.reset();
        grid.anisotropic = false;
        grid.depthLevels = false;
    }
    for (GLuint u = 0; u < 6; ++u) glBindImageTexture(u, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
}

}  // namespace vct
