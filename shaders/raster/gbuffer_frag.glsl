// G-buffer fragment stage: the surface at each pixel centre (layout in src/core/gbuffer.h).
// GBUFFER_SURFACE_ONLY: position and normals alone, for renders whose passes read no
// material (AO without GI or a lit image): no base-colour or emission fetch (about 40% of
// this pass on a textured scene under llvmpipe) and two attachments fewer.
// SCENE_NO_VERTEX_COLORS: the scene has none (every vertex white), so no colour is
// interpolated: one varying fewer, and the base colour is the material's to the bit.
#define SCENE_FRAGMENT_STAGE  // implicit texture levels (common/scene.glsl)
#include "common/scene.glsl"
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vUv;
#ifndef SCENE_NO_VERTEX_COLORS
in vec4 vColor;
#endif

// The material's base colour times the vertex colour (glTF: COLOR_0 multiplies both).
vec4 gbuffer_baseColor(uint material) {
    vec4 base = scene_baseColor(material, vUv, -1.0);
#ifndef SCENE_NO_VERTEX_COLORS
    base *= vColor;
#endif
    return base;
}
uniform vec3 eyeWorld;
uniform mat4 viewFromWorld;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outGeomNormal;
layout(location = 3) out vec4 outAlbedo;
layout(location = 4) out vec4 outEmission;

void main() {
    scene_uvDx = dFdx(vUv);
    scene_uvDy = dFdy(vUv);
    uint tri = uint(gl_PrimitiveID);
    uint material = sceneTriMaterial[tri];
#ifdef GBUFFER_SURFACE_ONLY
#ifndef SCENE_NO_ALPHA_MASK
    // The alpha test still decides which surface a pixel sees.
    GpuMaterial m = sceneMaterials[material];
    if ((m.flags & MATERIAL_ALPHA_MASK) != 0 && gbuffer_baseColor(material).a < m.alphaCutoff) discard;
#endif
#else
    vec4 base = gbuffer_baseColor(material);
    GpuMaterial m = sceneMaterials[material];
#ifndef SCENE_NO_ALPHA_MASK
    if ((m.flags & MATERIAL_ALPHA_MASK) != 0 && base.a < m.alphaCutoff) discard;
#endif
#endif

    // Geometric normal of the triangle itself (exact, unlike screen-space derivatives), one
    // load of the normals computed at upload: deriving it here from the three vertices took
    // seven loads per fragment, about 13% of this pass on Sponza at 512^2 under llvmpipe.
    vec3 ng = sceneTriNormal[tri].xyz;
    vec3 n = length(vNormal) > 0.0 ? normalize(vNormal) : ng;
    // Every surface is seen from its front: flip both normals toward the eye. Visibility
    // treats all triangles as two-sided, as the AO definition requires.
    vec3 toEye = eyeWorld - vWorldPos;
    if (dot(ng, toEye) < 0.0) ng = -ng;
    if (dot(n, ng) < 0.0) n = -n;

    float viewDepth = -(viewFromWorld * vec4(vWorldPos, 1.0)).z;
    outPosition = vec4(vWorldPos, max(viewDepth, 1e-30));
    outNormal = vec4(n, 1.0);
    outGeomNormal = vec4(ng, float(tri + 1u));
#ifndef GBUFFER_SURFACE_ONLY
    outAlbedo = vec4(base.rgb, 1.0);
    outEmission = vec4(scene_emission(material, vUv, -1.0), 1.0);
#endif
}
