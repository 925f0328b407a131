#include "cone/cone_bounce.h"

#include "cone/cone_gpu.h"
#include "cone/cone_programs.h"
#include "core/errors.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxelize.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace vct {

using namespace conedetail;

const SettingsTable<BounceSettings>& bounceSettings() {
    static const auto table =
        SettingsTable<BounceSettings>()
            .integer("vct.bounces", &BounceSettings::bounces, 0, 8,
                     "extra diffuse bounces traced between voxels (dense and vdb grids; clipmaps inject direct "
                     "light only)")
            .flag("vct.bounce.sky", &BounceSettings::sky, "bounce cones that escape see the sky radiance")
            .flag("vct.bounce.emitters", &BounceSettings::emitters,
                  "emitters' direct light: a scene with emissive materials or a sky the bounces see gathers once "
                  "more first, from the emission alone, so emitters' light has as many reflections as the lights' "
                  "(0: emitters' light has one reflection fewer)");
    return table;
}

int readVctBounces(const ParamMap& params) { return bounceSettings().read(params).bounces; }

int bounceGathers(const BounceSettings& settings, bool emissive, float sky) {
    const bool emitters = settings.emitters && (emissive || (settings.sky && sky > 0.f));
    return std::max(settings.bounces, 0) + (emitters ? 1 : 0);
}

void refuseVctBounces(const ParamMap& params, bool injects, const std::string& where) {
    const int bounces = readVctBounces(params);
    if (injects && params.has("vct.bounces") && bounces > 0)
        throw UsageError(where + ": vct.bounces = " + std::to_string(bounces) +
                         " is not supported (direct light only; use vct.bounces=0)");
}

std::vector<VoxelListSlab> voxelListSlabs(const glm::ivec3& res, size_t occupiedVoxels) {
    // GL guarantees 128 MiB per storage buffer binding; a whole-grid list would hold 512 MB at
    // 512^3, and voxelization has counted the occupied voxels, which bound any list.
    const size_t sliceVoxels = size_t(std::max(res.x, 1)) * size_t(std::max(res.y, 1));
    const int slices = int(std::max<size_t>(1, (kMaxVoxelListEntries - 1) / sliceVoxels));
    std::vector<VoxelListSlab> slabs;
    for (int z0 = 0; z0 < res.z; z0 += slices) {
        VoxelListSlab s;
        s.z0 = z0;
        s.z1 = std::min(res.z, z0 + slices);
        s.capacity = std::min(occupiedVoxels, sliceVoxels * size_t(s.z1 - z0));
        slabs.push_back(s);
    }
    return slabs;
}

void traceVoxelBounces(VoxelGrid& grid, float sky, const ConeSettings& cone, const ParamMap& params,
                       PassTimer& timer) {
    const BounceSettings settings = bounceSettings().read(params);
    const bool bounceSky = settings.sky;
    const int gathers = bounceGathers(settings, grid.emissive, sky);
    if (gathers == 0) return;
    if (!grid.radiance || !grid.albedo || !grid.normal)
        throw InternalError("traceVoxelBounces", "the grid has no injected radiance");
    if (!(sky >= 0.f) || !std::isfinite(sky))
        throw InternalError("traceVoxelBounces", "sky radiance must be finite and >= 0");
    cone.validate();
    if (grid.occupiedVoxels == 0) return;  // nothing gathers

    const glm::ivec3 res = grid.resolution;
    const GLenum format = textureInternalFormat(grid.radiance.id());
    const float diagonal = glm::length(glm::vec3(res)) * grid.voxelSize;
    PassTimer mipsTimer;  // the mips rebuilt inside the bounce count towards "bounce"
    auto scope = timer.scope("bounce", true, Reruns::WhenSceneChanges);
    // The direct term stays fixed; each bounce re-gathers from the previous total.
    GlTexture direct = createTexture3D(format, res.x, res.y, res.z);
    GlTexture next = createTexture3D(format, res.x, res.y, res.z);
    glCopyImageSubData(grid.radiance.id(), GL_TEXTURE_3D, 0, 0, 0, 0, direct.id(), GL_TEXTURE_3D, 0, 0, 0, 0, res.x,
                       res.y, res.z);
    GlBuffer ubo;  // bound after each bounce's mips: the uniforms say how the levels encode opacity
    // The gathering voxels, one list per slab of z slices (voxelListSlabs).
    struct Slab {
        VoxelListSlab range;
        GlBuffer list;
        uint32_t listed = 0;
    };
    std::vector<Slab> slabs;
    for (const VoxelListSlab& range : voxelListSlabs(res, grid.occupiedVoxels)) {
        Slab slab;
        slab.range = range;
        slab.list = createBuffer(sizeof(uint32_t) * (1 + range.capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
        const uint32_t zero = 0;
        glNamedBufferSubData(slab.list.id(), 0, sizeof(zero), &zero);
        slabs.push_back(std::move(slab));
    }
    if (gathers > settings.bounces) {
        // Emitters: the first gather reads the emission alone (cone_bounce.glsl, BOUNCE_EMITTED).
        ubo = bindConeUniforms(coneUniforms(true, grid, 2.f * diagonal, bounceSky ? sky : 0.f, cone));
        glBindTextureUnit(gpu::CONE_UNIT_BOUNCE_DIRECT, direct.id());
        glBindTextureUnit(gpu::CONE_UNIT_BOUNCE_EMISSION, grid.emission.id());
        bindImage3D(gpu::CONE_IMAGE_OUTPUT, grid.radiance.id(), 0, GL_WRITE_ONLY, format);
        glUseProgram(cachedProgram(coneBounceProgramKey(cone.anisotropic, format, BouncePass::Emitted, false, false)));
        const int g = gpu::VOX_GRID_GROUP;
        glDispatchCompute(groupCount(res.x, g), groupCount(res.y, g), groupCount(res.z, g));
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        glBindTextureUnit(gpu::CONE_UNIT_BOUNCE_EMISSION, 0);
    }
    for (int i = 0; i < gathers; ++i) {
        // The mips (and the directional textures, rebuilt anew) of the previous total.
        buildMips(grid, cone.anisotropic, mipsTimer, "bounce_mips", wantsDepthLevels(cone));
        const gpu::ConeUniforms uniforms = coneUniforms(true, grid, 2.f * diagonal, bounceSky ? sky : 0.f, cone);
        ubo = bindConeUniforms(uniforms);
        const ConeDirectional directional = bindGridTextures(true, grid, cone);
        const bool aniso = directional != ConeDirectional::None, depth = readsDepthLevels(grid, directional);
        const bool sharpen = readsSharpened(cone, directional);
        glBindTextureUnit(gpu::CONE_UNIT_BOUNCE_DIRECT, direct.id());
        glBindTextureUnit(gpu::CONE_UNIT_BOUNCE_ALBEDO, grid.albedo.id());
        if (i == 0) {
            // Listed once: direct light and normals do not change.
            const GLuint listPass = cachedProgram(coneBounceProgramKey(aniso, format, BouncePass::List, depth, sharpen));
            glUseProgram(listPass);
            const int g = gpu::VOX_GRID_GROUP;
            for (Slab& slab : slabs) {
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_VOXEL_LIST, slab.list.id());
                glProgramUniform2i(listPass, glGetUniformLocation(listPass, "uSlab"), slab.range.z0, slab.range.z1);
                glDispatchCompute(groupCount(res.x, g), groupCount(res.y, g), groupCount(slab.range.z1 - slab.range.z0, g));
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
                glGetNamedBufferSubData(slab.list.id(), 0, sizeof(slab.listed), &slab.listed);
            }
        }
        // Voxels that do not gather keep their direct light.
        glCopyImageSubData(direct.id(), GL_TEXTURE_3D, 0, 0, 0, 0, next.id(), GL_TEXTURE_3D, 0, 0, 0, 0, res.x, res.y,
                           res.z);
        bindImage3D(gpu::CONE_IMAGE_OUTPUT, next.id(), 0, GL_WRITE_ONLY, format);
        glUseProgram(cachedProgram(coneBounceProgramKey(aniso, format, BouncePass::Gather, depth, sharpen)));
        // The cone set over the loop budget's dispatches (coneSlices), the sums of a slab's
        // listed voxels carried between them.
        const ConeSlices coneSet = coneSlices(uniforms, cone, denseLoopsPerStep(cone));
        uint32_t mostListed = 0;
        for (const Slab& slab : slabs) mostListed = std::max(mostListed, slab.listed);
        GlBuffer carry = bindConeCarry(coneSet, mostListed);
        for (const Slab& slab : slabs) {
            if (slab.listed == 0) continue;
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_VOXEL_LIST, slab.list.id());
            for (int k = 0; k < coneSet.count(); ++k) {
                loadConeSlice(ubo.id(), coneSet, k);
                glDispatchCompute(groupCount(int(slab.listed), gpu::CONE_BOUNCE_GROUP), 1, 1);
                if (k + 1 < coneSet.count()) glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            }
        }
        if (carry) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_CARRY, 0);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        glCopyImageSubData(next.id(), GL_TEXTURE_3D, 0, 0, 0, 0, grid.radiance.id(), GL_TEXTURE_3D, 0, 0, 0, 0, res.x,
                           res.y, res.z);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_VOXEL_LIST, 0);
    glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
}

}  // namespace vct
