// The scene uploaded once to the GPU, shared by every pass of a render (and of a
// comparison): vertex/index/material/light buffers at the bindings of
// shaders/common/scene_shared.h, and all textures in one sRGB 2D array.
#pragma once

#include "gl/handles.h"
#include "scene/scene.h"

namespace vct {

struct GpuScene {
    GlBuffer vertices;          // GpuVertex[]
    GlBuffer indices;           // uint[3 * triangleCount], also the element buffer
    GlBuffer triangleMaterial;  // uint[triangleCount]
    GlBuffer triangleNormal;    // vec4[triangleCount]: unit geometric normal ((0, 1, 0) if degenerate)
    GlBuffer materials;         // GpuMaterial[]
    GlBuffer lights;            // GpuLight[] (shadow fields filled by the shadow pass)
    GlTexture textures;         // GL_TEXTURE_2D_ARRAY, SCENE_TEXTURE_SIZE^2, at least one layer
    GlVertexArray vao;          // positions at attribute 0, normals 1, uvs 2, vertex colours 3
    int vertexCount = 0;
    int triangleCount = 0;
    int materialCount = 0;
    int lightCount = 0;
    bool hasTextures = false;   // any texture referenced: else shaders compile without sampling
    bool hasAlphaMask = false;  // any alpha-masked material: else no alpha test
    bool hasVertexColors = false;  // Scene::colors given: else the G-buffer reads none
    bool hasWrapModes = false;     // a texture that clamps or mirrors: else the raster compiles them out
    Bounds3 bounds;
};

GpuScene uploadScene(const Scene& scene);
// Rewrites the light buffer from the scene's lights (the same lights, moved): a sequence whose
// lights move calls it between frames. The shadow pass must then run again.
void uploadLights(GpuScene& gpuScene, const Scene& scene);
// Binds the scene's storage buffers and texture array at their conventional points.
void bindSceneBuffers(const GpuScene& s);

}  // namespace vct
