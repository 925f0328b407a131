// rayMarchVoxels (declared in cone/cone_trace.h): the inspection view of the grid.
#include "cone/cone_gpu.h"
#include "cone/cone_programs.h"
#include "cone/cone_trace.h"
#include "core/errors.h"

#include <cmath>
#include <stdexcept>

namespace vct {

using namespace conedetail;

GlTexture rayMarchVoxels(const VoxelGrid& grid, const View& view, const std::string& what, int level,
                         PassTimer& timer) {
    checkGrid(grid, "rayMarchVoxels");
    if (view.width <= 0 || view.height <= 0) throw InternalError("rayMarchVoxels", "empty view");
    int channel = 0;
    if (what == "opacity") channel = gpu::CONE_CHANNEL_OPACITY;
    else if (what == "albedo") channel = gpu::CONE_CHANNEL_ALBEDO;
    else if (what == "radiance") channel = gpu::CONE_CHANNEL_RADIANCE;
    else throw InternalError("rayMarchVoxels", "channel '" + what + "' (expected albedo|radiance|opacity)");
    if (level < 0 || level >= grid.levels)
        throw InternalError("rayMarchVoxels", "level " + std::to_string(level) + " outside [0, " +
                                                  std::to_string(grid.levels - 1) + "]");
    if (channel == gpu::CONE_CHANNEL_ALBEDO && !grid.albedo)
        throw InternalError("rayMarchVoxels", "voxel grid has no albedo texture");
    if (channel == gpu::CONE_CHANNEL_RADIANCE && !grid.radiance)
        throw InternalError("rayMarchVoxels", "voxel grid has no radiance (inject first)");

    gpu::ConeUniforms u{};
    setGridUniforms(u, grid);
    u.worldFromView = view.worldFromView;
    float tanY = std::tan(0.5f * view.camera.yfov);
    // Half a texel of the level per step: no texel is skipped.
    u.camera = glm::vec4(tanY * view.aspect(), tanY, 0.5f * std::exp2(float(level)), 0.f);
    u.config = glm::ivec4(0, 0, level, channel);
    u.image = glm::ivec4(view.width, view.height, 0, 0);

    auto scope = timer.scope("cone_view");
    const GLuint program = cachedProgram(voxelViewProgramKey(channel));
    GlTexture out = createTexture2D(GL_RGBA32F, view.width, view.height);
    GlBuffer ubo = bindConeUniforms(u);
    glBindTextureUnit(gpu::CONE_UNIT_OPACITY,
                      channel == gpu::CONE_CHANNEL_RADIANCE ? grid.radiance.id() : grid.opacity.id());
    if (channel == gpu::CONE_CHANNEL_ALBEDO) glBindTextureUnit(gpu::CONE_UNIT_COLOR, grid.albedo.id());
    glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(program);
    glDispatchCompute(groupCount(view.width, gpu::CONE_LOCAL_SIZE), groupCount(view.height, gpu::CONE_LOCAL_SIZE),
                      1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    return out;
}

}  // namespace vct
