// The scene as uploaded to the GPU (src/render/gpu_scene.cpp) and read by every shader
// that touches triangles: the G-buffer, the shadow maps and the voxelizer.
#pragma once
#include "common/shared_types.h"

#ifdef __cplusplus
#define SCENE_FN inline
#else
#define SCENE_FN
#endif

VCT_BEGIN_NAMESPACE

// Shader storage binding points of the scene buffers.
VCT_CONST int SCENE_BINDING_VERTICES = 0;   // GpuVertex[vertexCount]
VCT_CONST int SCENE_BINDING_INDICES = 1;    // uint[3 * triangleCount]
VCT_CONST int SCENE_BINDING_TRIMATERIAL = 2;  // uint[triangleCount]
VCT_CONST int SCENE_BINDING_MATERIALS = 3;  // GpuMaterial[materialCount]
VCT_CONST int SCENE_BINDING_LIGHTS = 4;     // GpuLight[lightCount]
VCT_CONST int SCENE_BINDING_TRINORMAL = 5;  // vec4[triangleCount]: unit geometric normal, w = 0
// Texture unit of the scene's texture array (sRGB RGBA8, one layer per glTF image).
VCT_CONST int SCENE_UNIT_TEXTURES = 8;
// Every scene texture is resampled to this square size in the array (mipmapped).
VCT_CONST int SCENE_TEXTURE_SIZE = 512;

struct GpuVertex {
    vec4 position;  // xyz world, w = 1
    vec4 normal;    // xyz world unit normal, w = 0
    vec4 uv;        // xy texcoord 0
    vec4 color;     // linear RGBA vertex colour (glTF COLOR_0), (1, 1, 1, 1) without one
};

VCT_CONST int MATERIAL_DOUBLE_SIDED = 1;
VCT_CONST int MATERIAL_ALPHA_MASK = 2;
// The wrap modes of a material's textures, two bits an axis in GpuMaterial::flags from these
// shifts (S, then T two bits up): the texture array has one sampler, REPEAT, for every layer.
VCT_CONST int MATERIAL_BASE_WRAP_SHIFT = 2;
VCT_CONST int MATERIAL_EMISSIVE_WRAP_SHIFT = 6;
VCT_CONST int TEXTURE_WRAP_REPEAT = 0;  // TextureWrap's order (scene/scene.h)
VCT_CONST int TEXTURE_WRAP_CLAMP_TO_EDGE = 1;
VCT_CONST int TEXTURE_WRAP_MIRRORED_REPEAT = 2;

// Mirrored repeat of one texture coordinate into [0, 1]: period 2, forwards, then backwards.
// The CPU sampler (src/scene/texture_sampler.cpp) and the shaders (common/scene.glsl) fold alike.
SCENE_FN float scene_mirrorCoordinate(float c) {
    float m = c - 2.0f * floor(0.5f * c);  // [0, 2)
    return m <= 1.0f ? m : 2.0f - m;
}

// The vertex colour at barycentric weights b of a triangle whose corners have colours c0, c1,
// c2, for the CPU readers (texture_sampler.cpp) and the GPU voxelizer alike. A triangle of one
// colour keeps it exactly: weights summing to 1 within rounding would move it by an ulp, and
// the voxelizers' fixed-point sums with it, so a scene without vertex colours voxelizes as it
// did before they existed.
SCENE_FN vec4 scene_vertexColor(vec4 c0, vec4 c1, vec4 c2, vec3 b) {
    if (c0 == c1 && c1 == c2) return c0;
    return b.x * c0 + b.y * c1 + b.z * c2;
}

struct GpuMaterial {
    vec4 baseColor;       // linear RGBA factor
    vec4 emissive;        // linear RGB factor x emissive_strength, w unused
    int baseColorLayer;   // layer in the texture array, -1 for none
    int emissiveLayer;    // layer in the texture array, -1 for none
    int flags;            // MATERIAL_* bits
    float alphaCutoff;
};

VCT_CONST int LIGHT_DIRECTIONAL = 0;
VCT_CONST int LIGHT_POINT = 1;
VCT_CONST int LIGHT_SPOT = 2;

struct GpuLight {
    vec4 color;          // rgb = colour x intensity (lux for directional, candela otherwise); w = type
    vec4 position;       // xyz world (point, spot)
    vec4 direction;      // xyz world unit direction of travel (directional, spot)
    vec4 spot;           // x = cos(outer), y = cos(inner), z = shadow layer (-1 none), w = normal bias (world)
    mat4 shadowClipFromWorld;  // directional and spot: into the shadow map's clip space
};

VCT_END_NAMESPACE
