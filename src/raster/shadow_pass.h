// Shadow maps for the direct-lighting pass: one depth layer per directional or spot light
// (orthographic fit to the scene / perspective over the spot cone) and one distance cube
// per point light. Fills the shadow fields of the scene's light buffer.
#pragma once

#include "gl/handles.h"
#include "core/gpu_scene.h"
#include "core/timing.h"
#include "scene/scene.h"

namespace vct {

struct ShadowMaps {
    GlTexture maps;   // GL_TEXTURE_2D_ARRAY, DEPTH_COMPONENT32F with compare mode; >= 1 layer
    GlTexture cubes;  // GL_TEXTURE_CUBE_MAP_ARRAY, R32F distance; >= 1 cube
    int size = 0;
    int mapCount = 0;
    int cubeCount = 0;
};

// `size` texels per side. Without lights, returns 1x1 placeholder textures (so samplers
// are complete) and renders nothing.
ShadowMaps renderShadowMaps(const GpuScene& gpuScene, const Scene& scene, int size, PassTimer& timer);
// Empty placeholders for renders that skip the shadow pass.
ShadowMaps emptyShadowMaps();
void bindShadowMaps(const ShadowMaps& s);

}  // namespace vct
