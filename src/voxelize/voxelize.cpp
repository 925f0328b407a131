#include "voxelize/voxelize.h"

#include "common/scene_shared.h"
#include "core/errors.h"
#include "gl/context.h"
#include "gl/program_cache.h"
#include "gl/program_limits.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxel_programs.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <unistd.h>

namespace vct {

namespace {

// What the materials ask of the voxelizer: the largest emitted radiance (textures only scale
// it down), which decides whether emission accumulators are needed at all and which float
// precision the outputs need; and whether any is doubleSided (two-sided voxels).
struct MaterialNeeds {
    float maxEmission = 0.f;
    bool doubleSided = false;
};

MaterialNeeds materialNeeds(const GpuScene& scene) {
    std::vector<gpu::GpuMaterial> materials(std::max(1, scene.materialCount));
    glGetNamedBufferSubData(scene.materials.id(), 0, GLsizeiptr(materials.size() * sizeof(gpu::GpuMaterial)),
                            materials.data());
    MaterialNeeds needs;
    for (int i = 0; i < scene.materialCount; ++i) {
        const gpu::GpuMaterial& mat = materials[size_t(i)];
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(mat.emissive[c]))
                throw std::runtime_error("voxelize: material emission is not finite");
            needs.maxEmission = std::max(needs.maxEmission, mat.emissive[c]);
        }
        if ((mat.flags & gpu::MATERIAL_DOUBLE_SIDED) != 0) needs.doubleSided = true;
    }
    return needs;
}

// Half floats hold up to 65504; keep a margin for filtering and for the albedo/pi term.
constexpr float HALF_SAFE_MAX = 30000.f;

// One accumulation pass over every triangle: the small pass, then the big triangles it
// listed (one work group each). The images of the pass's accumulators are bound.
void accumulateTriangles(const GpuScene& scene, const VoxelGrid& grid, const GlBuffer& bigList, GLuint smallPass,
                         GLuint bigPass) {
    if (scene.triangleCount == 0) return;
    const GLuint listed = 0;
    glNamedBufferSubData(bigList.id(), 0, sizeof(listed), &listed);
    for (GLuint p : {smallPass, bigPass}) {
        setUniform(p, "uGridOrigin", grid.origin);
        setUniform(p, "uInvVoxelSize", 1.f / grid.voxelSize);
        setUniform(p, "uResolution", grid.resolution);
        glProgramUniform1ui(p, glGetUniformLocation(p, "uTriangleCount"), GLuint(scene.triangleCount));
    }
    glUseProgram(smallPass);
    glDispatchCompute(groupCount(scene.triangleCount, gpu::VOX_TRI_GROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    // The big-triangle count comes back to the CPU: llvmpipe was seen to run an indirect
    // dispatch with arguments read before the small pass finished (despite
    // GL_COMMAND_BARRIER_BIT), silently dropping every big triangle.
    uint32_t bigCount = 0;
    glGetNamedBufferSubData(bigList.id(), 0, sizeof(uint32_t), &bigCount);
    glUseProgram(bigPass);
    const uint32_t maxGroups = 65535;  // the GL minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT
    for (uint32_t base = 0; base < bigCount; base += maxGroups) {
        glProgramUniform1ui(bigPass, glGetUniformLocation(bigPass, "uBigBase"), base);
        glDispatchCompute(std::min(maxGroups, bigCount - base), 1, 1);
    }
    // Image writes before the next pass's atomics and the resolve's texel fetches.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
}

// The grid's name and the way out, as the estimate's refusal gives them.
std::string gridRefusal(const VoxelGrid& grid, const std::string& why) {
    return "voxel grid " + std::to_string(grid.resolution.x) + "x" + std::to_string(grid.resolution.y) + "x" +
           std::to_string(grid.resolution.z) + " " + why + ": lower --voxel-res or use vct.clipmap.levels";
}

// The estimate below passes a grid the machine's memory holds, but a GL may still refuse one of
// its textures (llvmpipe caps a single texture's size: a 1024x513x1024 accumulator of 2 GB):
// a refusal as clear as the estimate's, not a bare GL error at the pass's end.
void refuseUnallocatedGrid(const VoxelGrid& grid) {
    const std::vector<std::string> pending = GlContext::shared().pendingErrors();
    if (std::none_of(pending.begin(), pending.end(),
                     [](const std::string& e) { return e.find("GL_OUT_OF_MEMORY") != std::string::npos; }))
        return;
    try {
        GlContext::shared().checkErrors("voxelize");
    } catch (const std::exception& e) {
        throw std::runtime_error(gridRefusal(grid, std::string("could not be allocated (") + e.what() + ")"));
    }
}

}  // namespace

VoxelGrid voxelizeScene(const GpuScene& scene, const Bounds3& region, int voxelRes, const ParamMap& params,
                        PassTimer& timer, bool lit, bool attributes) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(region.min[a]) || !std::isfinite(region.max[a]))
            throw InternalError("voxelizeScene", "region bounds are not finite");
    return voxelizeGrid(scene, makeGridLayout(region, voxelRes), params, timer, "voxelize", lit, attributes);
}

VoxelGrid voxelizeGrid(const GpuScene& scene, VoxelGrid layout, const ParamMap& params, PassTimer& timer,
                       const std::string& scopeName, bool lit, bool attributes) {
    attributes = attributes || lit;  // injection reads them
    VoxelGrid grid = makeGridLayout(layout.origin, layout.voxelSize, layout.resolution);
    const MaterialNeeds needs = materialNeeds(scene);
    const bool twoSided = needs.doubleSided && lit;
    // Refuse a grid this machine cannot hold, before allocating: llvmpipe keeps textures in system
    // memory and an oversized one ends in the OOM killer, not GL_OUT_OF_MEMORY. ~66 bytes per
    // voxel at the peak (accumulators, albedo, normal, radiance, directional mips): 4.4 GB RSS
    // measured at 512x257x512 (stability suite); lit grids of scenes with doubleSided materials
    // add the doubleSided weight (4) and the two-sided texture (8); a grid of opacity alone
    // (no attributes) about 16 (the weight, opacity and directional levels); edge coverage adds
    // its two accumulators (8), sheets three more and their two textures (20).
    const VoxelSettings voxelOptions = voxelSettings().read(params);
    const bool edgeCoverage = voxelOptions.edges != VoxelEdges::Occupied;
    const bool sheets = voxelOptions.edges == VoxelEdges::Sheet;
    const double voxels = double(grid.resolution.x) * grid.resolution.y * grid.resolution.z;
    const double bytesPerVoxel =
        (!attributes ? 16.0 : twoSided ? 78.0 : 66.0) + (edgeCoverage ? 8.0 : 0.0) + (sheets ? 20.0 : 0.0);
    const double needBytes = bytesPerVoxel * voxels, haveBytes = double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
    if (haveBytes > 0.0 && needBytes > 0.5 * haveBytes)
        throw std::runtime_error(gridRefusal(grid, "needs about " + std::to_string(int(needBytes / 1e9)) +
                                                       " GB, more than half of this machine's " +
                                                       std::to_string(int(haveBytes / 1e9)) + " GB"));
    const VoxelPrecision precision = voxelOptions.precision;
    const float maxEmission = attributes ? needs.maxEmission : 0.f;
    const bool hasEmission = maxEmission > 0.f;
    const bool useFloat = precision == VoxelPrecision::Float ||
                          (precision == VoxelPrecision::Auto && maxEmission > HALF_SAFE_MAX);
    const GLenum emissionFormat = useFloat ? GL_RGBA32F : GL_RGBA16F;

    // Programs first, so a first-use compile is not timed as voxelization.
    const GLuint resolve =
        cachedProgram(resolveProgramKey(hasEmission, emissionFormat, twoSided, !attributes, edgeCoverage));
    // The passes this grid runs, each with the accumulators it binds as images [first, last).
    struct AccumulatePass {
        VoxelizePass pass;
        int first, last;
        GLuint program[2];  // [big pass]
    };
    std::vector<AccumulatePass> passes = {{VoxelizePass::Geometry, 0, gpu::VOX_ACC_EMISSION, {}}};
    if (hasEmission) passes.push_back({VoxelizePass::Emission, gpu::VOX_ACC_EMISSION, gpu::VOX_ACC_COVERAGE, {}});
    if (edgeCoverage)
        passes.push_back({VoxelizePass::Coverage, gpu::VOX_ACC_COVERAGE,
                          sheets ? gpu::VOX_ACC_COUNT : gpu::VOX_ACC_SHEET_LO, {}});
    for (AccumulatePass& p : passes)
        for (int big = 0; big < 2; ++big)
            p.program[big] = cachedProgram(voxelizeProgramKey(p.pass, big != 0, twoSided, !attributes, sheets));
    const GLuint sheetsProgram = sheets ? cachedProgram(sheetsProgramKey()) : 0;

    auto scope = timer.scope(scopeName, true, Reruns::WhenSceneChanges);
    const glm::ivec3 res = grid.resolution;

    // Accumulators, zeroed; nearest filtering, as integer textures must be for texelFetch. Those
    // the scene does not need (emission, the doubleSided weight) stay empty.
    std::vector<GlTexture> acc(size_t(gpu::VOX_ACC_COUNT));
    auto needed = [&](int i) {
        if (i >= gpu::VOX_ACC_SHEET_LO) return sheets;
        if (i >= gpu::VOX_ACC_COVERAGE) return edgeCoverage;
        if (!attributes) return i == gpu::VOX_ACC_WEIGHT;
        if (i == gpu::VOX_ACC_TWO_SIDED) return twoSided;
        return i < gpu::VOX_ACC_EMISSION || hasEmission;
    };
    for (int i = 0; i < gpu::VOX_ACC_COUNT; ++i) {
        if (!needed(i)) continue;
        acc[size_t(i)] = createTexture3D(GL_R32UI, res.x, res.y, res.z);
        glTextureParameteri(acc[size_t(i)].id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(acc[size_t(i)].id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        const GLuint zero = 0;
        glClearTexImage(acc[size_t(i)].id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    }
    refuseUnallocatedGrid(grid);
    // Big-triangle list: header {count, -, -, occupied voxels}, then triangle ids.
    std::vector<uint32_t> header = {0, 1, 1, 0};
    header.resize(4 + size_t(std::max(1, scene.triangleCount)), 0);
    checkStorageBufferSize(header.size() * sizeof(uint32_t), "voxelize: the big-triangle list of " +
                                                                 std::to_string(scene.triangleCount) + " triangles");
    GlBuffer bigList = createBuffer(header.size() * sizeof(uint32_t), header.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::VOX_BINDING_BIGLIST, bigList.id());
    bindSceneBuffers(scene);

    // The geometry pass, then (emission only) the emission pass and (edge coverage only) the
    // coverage pass: each binds its own accumulators as images (voxelize_shared.h).
    for (const AccumulatePass& p : passes) {
        for (int i = p.first; i < p.last; ++i)
            if (acc[size_t(i)]) bindImage3D(GLuint(i - p.first), acc[size_t(i)].id(), 0, GL_READ_WRITE, GL_R32UI);
        accumulateTriangles(scene, grid, bigList, p.program[0], p.program[1]);
        for (int i = p.first; i < p.last; ++i)
            glBindImageTexture(GLuint(i - p.first), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    }

    // Resolve into the contract's float textures.
    grid.opacity = createTexture3D(GL_R16F, res.x, res.y, res.z, grid.levels);
    if (attributes) {
        grid.albedo = createTexture3D(GL_RGBA16F, res.x, res.y, res.z);
        // Normals carry mips (filled with the radiance's: voxelize/mips.cpp) for the facing test.
        grid.normal = createTexture3D(GL_RGBA16F, res.x, res.y, res.z, grid.levels);
        grid.emission = createTexture3D(emissionFormat, res.x, res.y, res.z);
    }
    grid.emissive = hasEmission;
    if (twoSided) {
        grid.twoSided = createTexture3D(GL_RGBA16_SNORM, res.x, res.y, res.z);
        bindImage3D(gpu::VOX_IMAGE_RESOLVE_TWO_SIDED, grid.twoSided.id(), 0, GL_WRITE_ONLY, GL_RGBA16_SNORM);
    }
    refuseUnallocatedGrid(grid);
    for (int i = 0; i < gpu::VOX_ACC_COUNT; ++i)
        if (acc[size_t(i)]) glBindTextureUnit(GLuint(i), acc[size_t(i)].id());
    bindImage3D(gpu::VOX_IMAGE_RESOLVE_OPACITY, grid.opacity.id(), 0, GL_WRITE_ONLY, GL_R16F);
    if (attributes) {
        bindImage3D(gpu::VOX_IMAGE_RESOLVE_ALBEDO, grid.albedo.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
        bindImage3D(gpu::VOX_IMAGE_RESOLVE_NORMAL, grid.normal.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
        bindImage3D(gpu::VOX_IMAGE_RESOLVE_EMISSION, grid.emission.id(), 0, GL_WRITE_ONLY, emissionFormat);
    }
    setUniform(resolve, "uResolution", res);
    glUseProgram(resolve);
    const int g = gpu::VOX_GRID_GROUP;
    glDispatchCompute(groupCount(res.x, g), groupCount(res.y, g), groupCount(res.z, g));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    uint32_t occupied = 0;
    glGetNamedBufferSubData(bigList.id(), 3 * sizeof(uint32_t), sizeof(uint32_t), &occupied);
    grid.occupiedVoxels = occupied;

    if (sheets) {
        // Level 0's sheet texels from the resolved opacity and the coverage pass's sums.
        grid.sheets = createTexture3D(GL_RGBA16F, res.x, res.y, res.z);
        refuseUnallocatedGrid(grid);
        glBindTextureUnit(gpu::VOX_UNIT_SHEETS_OPACITY, grid.opacity.id());
        bindImage3D(gpu::VOX_IMAGE_SHEETS, grid.sheets.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
        setUniform(sheetsProgram, "uResolution", res);
        glUseProgram(sheetsProgram);
        glDispatchCompute(groupCount(res.x, g), groupCount(res.y, g), groupCount(res.z, g));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(gpu::VOX_UNIT_SHEETS_OPACITY, 0);
        // The extent bits are read as they were accumulated.
        grid.sheetExtents = std::move(acc[size_t(gpu::VOX_ACC_SHEET_EXTENT)]);
    }

    // Leave nothing bound to the (about to be freed) accumulators.
    for (int i = 0; i < gpu::VOX_ACC_COUNT; ++i) glBindTextureUnit(GLuint(i), 0);
    for (int i = gpu::VOX_IMAGE_RESOLVE_OPACITY; i <= gpu::VOX_IMAGE_RESOLVE_TWO_SIDED; ++i)
        glBindImageTexture(GLuint(i), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
    return grid;
}

}  // namespace vct
