// The rasterization and lighting passes' programs, each built by one key function
// (gl/program_cache.h) so the passes and the list of every variant agree.
#pragma once

#include "core/gpu_scene.h"
#include "gl/program_cache.h"

#include <vector>

namespace vct {

// What of the scene the raster shaders compile in: each feature a scene lacks is compiled out
// (SCENE_NO_* in common/scene.glsl and raster/raster_surface.glsl), so a scene without it
// draws as fast as before the feature existed (llvmpipe runs untaken branches' fetches).
struct RasterSceneFeatures {
    bool textures = true;
    bool alphaMask = true;
    bool vertexColors = true;
    bool wrapModes = true;  // a texture that clamps or mirrors
};
RasterSceneFeatures rasterFeaturesOf(const GpuScene& s);

// The G-buffer; albedo and emission compiled out where the render reads no material
// (GBuffer::materials).
ProgramKey gbufferProgramKey(const RasterSceneFeatures& f, bool materials);
// The shadow maps: the alpha test where the scene has alpha-masked materials.
ProgramKey shadowProgramKey(const RasterSceneFeatures& f);
ProgramKey directLightProgramKey();
ProgramKey compositeProgramKey();

std::vector<ProgramKey> rasterProgramVariants();

}  // namespace vct
