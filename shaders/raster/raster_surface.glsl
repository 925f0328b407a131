// What a rasterized fragment of the scene sees of its material, shared by the G-buffer and
// the shadow maps so both cut glTF's alpha-masked texels alike (scene_alphaCut, common/scene.glsl,
// with this base colour): the base colour times the vertex colour. Reads the inputs raster/gbuffer_vert.glsl writes. Defines as common/scene.glsl,
// and SCENE_NO_VERTEX_COLORS where the scene has none (no colour interpolated: the base
// colour is the material's to the bit).
#define SCENE_FRAGMENT_STAGE  // implicit texture levels (common/scene.glsl)
#include "common/scene.glsl"
in vec2 vUv;
#ifndef SCENE_NO_VERTEX_COLORS
in vec4 vColor;
#endif

// Call first in main, in uniform control flow: the texture lookups' derivatives.
void raster_beginFragment() {
    scene_uvDx = dFdx(vUv);
    scene_uvDy = dFdy(vUv);
}

// The material's base colour times the vertex colour (glTF: COLOR_0 multiplies both).
vec4 raster_baseColor(uint material) {
    vec4 base = scene_baseColor(material, vUv, -1.0);
#ifndef SCENE_NO_VERTEX_COLORS
    base *= vColor;
#endif
    return base;
}
