// G-buffer fragment stage: the surface at each pixel centre (layout in src/core/gbuffer.h).
// GBUFFER_SURFACE_ONLY: position and normals alone, for renders whose passes read no
// material (AO without GI or a lit image): no base-colour or emission fetch (about 40% of
// this pass on a textured scene under llvmpipe) and two attachments fewer.
// Vertex colours and the alpha test: raster/raster_surface.glsl.
#include "raster/raster_surface.glsl"
in vec3 vWorldPos;
in vec3 vNormal;
uniform vec3 eyeWorld;
uniform mat4 viewFromWorld;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outGeomNormal;
layout(location = 3) out vec4 outAlbedo;
layout(location = 4) out vec4 outEmission;

void main() {
    raster_beginFragment();
    uint tri = uint(gl_PrimitiveID);
    uint material = sceneTriMaterial[tri];
#ifdef GBUFFER_SURFACE_ONLY
#ifndef SCENE_NO_ALPHA_MASK
    // The alpha test still decides which surface a pixel sees.
    if (scene_alphaCut(material, raster_baseColor(material).a)) discard;
#endif
#else
    vec4 base = raster_baseColor(material);
#ifndef SCENE_NO_ALPHA_MASK
    if (scene_alphaCut(material, base.a)) discard;
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
    outGeomNormal = vec4(ng, 1.0);
#ifndef GBUFFER_SURFACE_ONLY
    outAlbedo = vec4(base.rgb, 1.0);
    outEmission = vec4(scene_emission(material, vUv, -1.0), 1.0);
#endif
}
