#include "voxelize/voxelize.h"

#include "common/scene_shared.h"
#include "gl/program.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <unistd.h>

namespace vct {

namespace {

// Largest emitted radiance of any material (textures only scale it down): decides whether
// emission accumulators are needed at all and which float precision the outputs need.
float maxMaterialEmission(const GpuScene& scene) {
    std::vector<gpu::GpuMaterial> materials(std::max(1, scene.materialCount));
    glGetNamedBufferSubData(scene.materials.id(), 0, GLsizeiptr(materials.size() * sizeof(gpu::GpuMaterial)),
                            materials.data());
    float m = 0.f;
    for (const gpu::GpuMaterial& mat : materials) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(mat.emissive[c]))
                throw std::invalid_argument("voxelize: material emission is not finite");
            m = std::max(m, mat.emissive[c]);
        }
    }
    return m;
}

// Half floats hold up to 65504; keep a margin for filtering and for the albedo/pi term.
constexpr float HALF_SAFE_MAX = 30000.f;

}  // namespace

VoxelGrid voxelizeScene(const GpuScene& scene, const Bounds3& region, int voxelRes, const ParamMap& params,
                        PassTimer& timer) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(region.min[a]) || !std::isfinite(region.max[a]))
            throw std::invalid_argument("voxelize: region bounds are not finite");
    return voxelizeGrid(scene, makeGridLayout(region, voxelRes), params, timer);
}

VoxelGrid voxelizeGrid(const GpuScene& scene, VoxelGrid layout, const ParamMap& params, PassTimer& timer,
                       const std::string& scopeName) {
    VoxelGrid grid = makeGridLayout(layout.origin, layout.voxelSize, layout.resolution);
    // Refuse a grid this machine cannot hold, before allocating: llvmpipe keeps textures in system
    // memory and an oversized one ends in the OOM killer, not GL_OUT_OF_MEMORY. ~66 bytes per
    // voxel at the peak (accumulators, albedo, normal, radiance, directional mips): 4.4 GB RSS
    // measured at 512x257x512 (stability suite).
    const double voxels = double(grid.resolution.x) * grid.resolution.y * grid.resolution.z;
    const double needBytes = 66.0 * voxels, haveBytes = double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
    if (haveBytes > 0.0 && needBytes > 0.5 * haveBytes)
        throw std::invalid_argument("voxel grid " + std::to_string(grid.resolution.x) + "x" +
                                    std::to_string(grid.resolution.y) + "x" + std::to_string(grid.resolution.z) +
                                    " needs about " + std::to_string(int(needBytes / 1e9)) + " GB, more than half of "
                                    "this machine's " + std::to_string(int(haveBytes / 1e9)) +
                                    " GB: lower --voxel-res or use vct.clipmap.levels");
    const std::string precision =
        params.getChoice("vct.voxel.precision", "auto", {"auto", "half", "float"},
                         "storage of emission/radiance: half (RGBA16F, clamps at 65504), float (RGBA32F), "
                         "auto = float when emission or lights exceed the half range");
    const float maxEmission = maxMaterialEmission(scene);
    const bool hasEmission = maxEmission > 0.f;
    const bool useFloat = precision == "float" || (precision == "auto" && maxEmission > HALF_SAFE_MAX);
    const GLenum emissionFormat = useFloat ? GL_RGBA32F : GL_RGBA16F;

    ShaderDefines defines;
    if (hasEmission) defines.push_back({"HAS_EMISSION", "1"});
    ShaderDefines bigDefines = defines;
    bigDefines.push_back({"BIG_PASS", "1"});
    ShaderDefines resolveDefines = defines;
    resolveDefines.push_back({"EMISSION_FORMAT", glslImageFormat(emissionFormat)});
    resolveDefines.push_back({"EMISSION_FORMAT_MAX", formatMaxLiteral(emissionFormat)});
    GlProgram smallPass = buildComputeProgram("voxelize/voxelize.glsl", defines);
    GlProgram bigPass = buildComputeProgram("voxelize/voxelize.glsl", bigDefines);
    GlProgram resolve = buildComputeProgram("voxelize/resolve.glsl", resolveDefines);

    auto scope = timer.scope(scopeName);
    const glm::ivec3 res = grid.resolution;

    // Accumulators, zeroed.
    const int accumulatorCount = hasEmission ? gpu::VOX_UNIT_EMISSION + 6 : gpu::VOX_UNIT_EMISSION;
    std::vector<GlTexture> acc;
    for (int i = 0; i < accumulatorCount; ++i) {
        acc.push_back(createTexture3D(GL_R32UI, res.x, res.y, res.z));
        const GLuint zero = 0;
        glClearTexImage(acc.back().id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        bindImage3D(GLuint(i), acc.back().id(), 0, GL_READ_WRITE, GL_R32UI);
    }
    // Big-triangle list: header {count, -, -, occupied voxels}, then triangle ids.
    std::vector<uint32_t> header = {0, 1, 1, 0};
    header.resize(4 + size_t(std::max(1, scene.triangleCount)), 0);
    GlBuffer bigList = createBuffer(header.size() * sizeof(uint32_t), header.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::VOX_BINDING_BIGLIST, bigList.id());

    bindSceneBuffers(scene);
    for (GLuint p : {smallPass.id(), bigPass.id()}) {
        setUniform(p, "uGridOrigin", grid.origin);
        setUniform(p, "uInvVoxelSize", 1.f / grid.voxelSize);
        setUniform(p, "uResolution", res);
        glProgramUniform1ui(p, glGetUniformLocation(p, "uTriangleCount"), GLuint(scene.triangleCount));
    }
    if (scene.triangleCount > 0) {
        glUseProgram(smallPass.id());
        glDispatchCompute(groupCount(scene.triangleCount, gpu::VOX_TRI_GROUP), 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        // The big-triangle count comes back to the CPU: llvmpipe was seen to run an indirect
        // dispatch with arguments read before the small pass finished (despite
        // GL_COMMAND_BARRIER_BIT), silently dropping every big triangle.
        uint32_t bigCount = 0;
        glGetNamedBufferSubData(bigList.id(), 0, sizeof(uint32_t), &bigCount);
        glUseProgram(bigPass.id());
        const uint32_t maxGroups = 65535;  // the GL minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT
        for (uint32_t base = 0; base < bigCount; base += maxGroups) {
            glProgramUniform1ui(bigPass.id(), glGetUniformLocation(bigPass.id(), "uBigBase"), base);
            glDispatchCompute(std::min(maxGroups, bigCount - base), 1, 1);
        }
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // Resolve into the contract's float textures.
    grid.opacity = createTexture3D(GL_R16F, res.x, res.y, res.z, grid.levels);
    grid.albedo = createTexture3D(GL_RGBA16F, res.x, res.y, res.z);
    // Normals carry mips (filled with the radiance's: voxelize/mips.cpp) for the facing test.
    grid.normal = createTexture3D(GL_RGBA16F, res.x, res.y, res.z, grid.levels);
    grid.emission = createTexture3D(emissionFormat, res.x, res.y, res.z);
    for (int i = 0; i < accumulatorCount; ++i) bindImage3D(GLuint(i), acc[size_t(i)].id(), 0, GL_READ_ONLY, GL_R32UI);
    bindImage3D(13, grid.opacity.id(), 0, GL_WRITE_ONLY, GL_R16F);
    bindImage3D(14, grid.albedo.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
    bindImage3D(15, grid.normal.id(), 0, GL_WRITE_ONLY, GL_RGBA16F);
    bindImage3D(16, grid.emission.id(), 0, GL_WRITE_ONLY, emissionFormat);
    setUniform(resolve.id(), "uResolution", res);
    glUseProgram(resolve.id());
    const int g = gpu::VOX_GRID_GROUP;
    glDispatchCompute(groupCount(res.x, g), groupCount(res.y, g), groupCount(res.z, g));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    uint32_t occupied = 0;
    glGetNamedBufferSubData(bigList.id(), 3 * sizeof(uint32_t), sizeof(uint32_t), &occupied);
    grid.occupiedVoxels = occupied;

    // Leave no image bound to the (about to be freed) accumulators.
    for (int i = 0; i <= 16; ++i) glBindImageTexture(GLuint(i), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
    grid.memoryBytes = voxelGridMemoryBytes(grid);
    return grid;
}

}  // namespace vct
