// The scene buffers (layouts in common/scene_shared.h) and material lookups shared by the
// G-buffer, shadow and voxelization shaders. Variants: SCENE_NO_TEXTURES compiles the
// lookups without texture sampling, SCENE_NO_ALPHA_MASK without the alpha test,
// SCENE_NO_WRAP_MODES (fragment stages) without clamp and mirror (the pass planner and
// raster_programs.cpp pick them from the scene's features).
#include "common/scene_shared.h"

layout(std430, binding = SCENE_BINDING_VERTICES) readonly buffer SceneVertices { GpuVertex sceneVertices[]; };
layout(std430, binding = SCENE_BINDING_INDICES) readonly buffer SceneIndices { uint sceneIndices[]; };
layout(std430, binding = SCENE_BINDING_TRIMATERIAL) readonly buffer SceneTriMaterial { uint sceneTriMaterial[]; };
layout(std430, binding = SCENE_BINDING_MATERIALS) readonly buffer SceneMaterials { GpuMaterial sceneMaterials[]; };
layout(std430, binding = SCENE_BINDING_LIGHTS) readonly buffer SceneLights { GpuLight sceneLights[]; };
layout(std430, binding = SCENE_BINDING_TRINORMAL) readonly buffer SceneTriNormal { vec4 sceneTriNormal[]; };
layout(binding = SCENE_UNIT_TEXTURES) uniform sampler2DArray sceneTextures;

// One texture coordinate under wrap mode `mode` (TEXTURE_WRAP_*) for the array's REPEAT
// sampler: repeat is the sampler's own (c unchanged, to the bit); clamp-to-edge and mirrored
// repeat fold it into [0, 1] and hold it half a texel of the sampled level inside, so the
// filter does not reach across to the opposite edge (texture_sampler.cpp is the CPU's side
// of this). Selects, not branches: llvmpipe pays for an untaken branch's texture fetch in
// every lane (the voxelizer took 15% longer on Sponza with a branch per mode).
float scene_wrapCoordinate(float c, int mode, float halfTexel) {
    float mirrored = scene_mirrorCoordinate(c);
    float folded = mode == TEXTURE_WRAP_MIRRORED_REPEAT ? mirrored : c;
    return mode == TEXTURE_WRAP_REPEAT ? c : clamp(folded, halfTexel, 1.0 - halfTexel);
}

#ifdef SCENE_FRAGMENT_STAGE
// The screen derivatives of the texture coordinates, which the fragment stage sets at the top
// of main, in uniform control flow: taken after a branch (the wrap modes' below), they were
// wrong where a 2 x 2 pixel quad straddles two triangles (llvmpipe; the TextureWrap test).
vec2 scene_uvDx = vec2(0.0), scene_uvDy = vec2(0.0);
#endif

// True where glTF's alpha test cuts a texel of `material` with base-colour alpha `alpha` away
// (the G-buffer, the shadow maps and the voxelizer; the ray tracer's filter in
// src/reference/embree_scene.cpp).
bool scene_alphaCut(uint material, float alpha) {
    GpuMaterial m = sceneMaterials[material];
    return (m.flags & MATERIAL_ALPHA_MASK) != 0 && alpha < m.alphaCutoff;
}

// Layer `layer` at uv with the wrap modes at `shift` (MATERIAL_*_WRAP_SHIFT) of a material's
// flags. `lod` < 0: the level the hardware picks, which only a fragment stage has
// (SCENE_FRAGMENT_STAGE). Repeat on both axes samples as it always did.
vec4 scene_sampleLayer(int layer, vec2 uv, int flags, int shift, float lod) {
#if defined(SCENE_FRAGMENT_STAGE) && defined(SCENE_NO_WRAP_MODES)
    // Every texture repeats: the sampler's own. (The branch below cost the G-buffer with
    // materials 20% on Sponza under llvmpipe, taken or not.)
    return lod < 0.0 ? texture(sceneTextures, vec3(uv, float(layer)))
                     : textureLod(sceneTextures, vec3(uv, float(layer)), lod);
#else
    int modes = (flags >> shift) & 15;
#ifdef SCENE_FRAGMENT_STAGE
    if (modes == 0) return lod < 0.0 ? texture(sceneTextures, vec3(uv, float(layer)))
                                     : textureLod(sceneTextures, vec3(uv, float(layer)), lod);
    // The level of the unwrapped coordinates' footprint: a fold's derivatives would change it.
    if (lod < 0.0) {
        vec2 dx = scene_uvDx * float(SCENE_TEXTURE_SIZE), dy = scene_uvDy * float(SCENE_TEXTURE_SIZE);
        lod = max(0.0, 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-30)));
    }
#endif
    // Trilinear filtering reads the level above lod too: half of that level's texel.
    float halfTexel = 0.5 * exp2(ceil(max(lod, 0.0))) / float(SCENE_TEXTURE_SIZE);
    vec2 wrapped = vec2(scene_wrapCoordinate(uv.x, modes & 3, halfTexel), scene_wrapCoordinate(uv.y, modes >> 2, halfTexel));
    return textureLod(sceneTextures, vec3(wrapped, float(layer)), lod);
#endif
}

// Linear RGBA base colour (the array is sRGB, so sampling decodes). `lod` < 0 lets the
// hardware pick the mip level (fragment shaders); compute shaders pass an explicit level.
vec4 scene_baseColor(uint materialId, vec2 uv, float lod) {
    GpuMaterial m = sceneMaterials[materialId];
    vec4 c = m.baseColor;
#ifndef SCENE_NO_TEXTURES
    if (m.baseColorLayer >= 0) c *= scene_sampleLayer(m.baseColorLayer, uv, m.flags, MATERIAL_BASE_WRAP_SHIFT, lod);
#endif
    return c;
}

vec3 scene_emission(uint materialId, vec2 uv, float lod) {
    GpuMaterial m = sceneMaterials[materialId];
    vec3 e = m.emissive.rgb;
#ifndef SCENE_NO_TEXTURES
    if (m.emissiveLayer >= 0 && any(greaterThan(e, vec3(0.0))))
        e *= scene_sampleLayer(m.emissiveLayer, uv, m.flags, MATERIAL_EMISSIVE_WRAP_SHIFT, lod).rgb;
#endif
    return e;
}
