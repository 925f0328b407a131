// Shadow map fragment stage. Point lights store the distance to the light in an R32F
// cube face; directional and spot lights need only the depth attachment.
// SHADOW_ALPHA_TEST (a scene with alpha-masked materials; the vertex stage is then
// raster/gbuffer_vert.glsl): texels the alpha test cuts away cast no shadow, as they hide
// nothing in the G-buffer and stop no ray of the ray tracer.
#ifdef SHADOW_ALPHA_TEST
#include "raster/raster_surface.glsl"
#endif
in vec3 vWorldPos;
uniform vec3 lightPos;
uniform int storeDistance;
layout(location = 0) out float outDistance;
void main() {
#ifdef SHADOW_ALPHA_TEST
    raster_beginFragment();
    uint material = sceneTriMaterial[uint(gl_PrimitiveID)];
    if (scene_alphaCut(material, raster_baseColor(material).a)) discard;
#endif
    outDistance = storeDistance != 0 ? length(vWorldPos - lightPos) : 0.0;
}
