// The scene buffers (layouts in common/scene_shared.h) and material lookups shared by the
// G-buffer, shadow and voxelization shaders. Variants: SCENE_NO_TEXTURES compiles the
// lookups without texture sampling, SCENE_NO_ALPHA_MASK without the alpha test (the pass
// planner picks them from the scene's features).
#include "common/scene_shared.h"

layout(std430, binding = SCENE_BINDING_VERTICES) readonly buffer SceneVertices { GpuVertex sceneVertices[]; };
layout(std430, binding = SCENE_BINDING_INDICES) readonly buffer SceneIndices { uint sceneIndices[]; };
layout(std430, binding = SCENE_BINDING_TRIMATERIAL) readonly buffer SceneTriMaterial { uint sceneTriMaterial[]; };
layout(std430, binding = SCENE_BINDING_MATERIALS) readonly buffer SceneMaterials { GpuMaterial sceneMaterials[]; };
layout(std430, binding = SCENE_BINDING_LIGHTS) readonly buffer SceneLights { GpuLight sceneLights[]; };
layout(std430, binding = SCENE_BINDING_TRINORMAL) readonly buffer SceneTriNormal { vec4 sceneTriNormal[]; };
layout(binding = SCENE_UNIT_TEXTURES) uniform sampler2DArray sceneTextures;

// Linear RGBA base colour (the array is sRGB, so sampling decodes). `lod` < 0 lets the
// hardware pick the mip level (fragment shaders); compute shaders pass an explicit level.
vec4 scene_baseColor(uint materialId, vec2 uv, float lod) {
    GpuMaterial m = sceneMaterials[materialId];
    vec4 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorLayer >= 0) {
        vec3 tc = vec3(uv, float(m.baseColorLayer));
        c *= lod < 0.0 ? texture(sceneTextures, tc) : textureLod(sceneTextures, tc, lod);
    }
#endif
    return c;
}

vec3 scene_emission(uint materialId, vec2 uv, float lod) {
    GpuMaterial m = sceneMaterials[materialId];
    vec3 e = m.emissive.rgb;
#ifndef SCENE_NO_TEXTURES
    if (m.emissiveLayer >= 0 && any(greaterThan(e, vec3(0.0)))) {
        vec3 tc = vec3(uv, float(m.emissiveLayer));
        e *= (lod < 0.0 ? texture(sceneTextures, tc) : textureLod(sceneTextures, tc, lod)).rgb;
    }
#endif
    return e;
}
