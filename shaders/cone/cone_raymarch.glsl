// Inspection view of the voxel grid: a ray from the camera through each pixel centre,
// compositing one channel front to back at a fixed mip level. rgb = composited colour,
// a = accumulated opacity. Defines: CONE_VIEW_RADIANCE or CONE_VIEW_ALBEDO (else opacity).
#include "cone/cone_shared.h"
#include "cone/cone_composite.h"

layout(local_size_x = CONE_LOCAL_SIZE, local_size_y = CONE_LOCAL_SIZE) in;
layout(rgba32f, binding = CONE_IMAGE_OUTPUT) uniform writeonly image2D cone_viewOut;
layout(std140, binding = CONE_UBO_BINDING) uniform ConeBlock { ConeUniforms u; };
layout(binding = CONE_UNIT_OPACITY) uniform sampler3D cone_opacity;  // opacity, or radiance
layout(binding = CONE_UNIT_COLOR) uniform sampler3D cone_color;      // albedo (CONE_VIEW_ALBEDO)

// (premultiplied colour, alpha) at texture coordinate tc.
vec4 cone_viewSample(vec3 tc, float lod) {
#if defined(CONE_VIEW_RADIANCE)
    return textureLod(cone_opacity, tc, lod);
#elif defined(CONE_VIEW_ALBEDO)
    float a = textureLod(cone_opacity, tc, lod).r;
    vec4 albedo = textureLod(cone_color, tc, 0.0);
    // Trilinear filtering blends in empty voxels (rgb 0, a 0): divide by the blended
    // occupancy to keep the surface's own colour at its edges.
    return vec4(albedo.rgb / max(albedo.a, 1e-4) * a, a);
#else
    float a = textureLod(cone_opacity, tc, lod).r;
    return vec4(a, a, a, a);
#endif
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (pix.x >= u.image.x || pix.y >= u.image.y) return;
    vec2 ndc = (vec2(pix) + 0.5) / vec2(u.image.xy) * 2.0 - 1.0;
    vec3 dirView = normalize(vec3(ndc.x * u.camera.x, ndc.y * u.camera.y, -1.0));
    vec3 eye = (u.voxelFromWorld * u.worldFromView * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    vec3 d = normalize((u.voxelFromWorld * u.worldFromView * vec4(dirView, 0.0)).xyz);

    // Slab test against the grid box [0, resolution].
    vec3 res = u.gridResolution.xyz;
    vec3 inv = 1.0 / d;  // +-inf on axis-parallel rays works with min/max below
    vec3 t0 = (vec3(0.0) - eye) * inv, t1 = (res - eye) * inv;
    vec3 tmin = min(t0, t1), tmax = max(t0, t1);
    float tNear = max(max(max(tmin.x, tmin.y), tmin.z), 0.0);
    float tFar = min(min(tmax.x, tmax.y), tmax.z);

    ConeResult acc;
    acc.radiance = vec3(0.0);
    acc.alpha = 0.0;
    float lod = float(u.config.z);
    float dt = u.camera.z;
    float texel = exp2(lod);
    if (tNear < tFar && !isnan(tNear) && !isnan(tFar)) {
        float t = tNear + 0.5 * dt;
        for (int i = 0; i < 4 * CONE_MAX_STEPS && t < tFar && acc.alpha < 0.999; ++i, t += dt)
            cone_composite(acc, cone_viewSample((eye + d * t) / res, lod), dt, texel, t, 0.0);  // no falloff
    }
    imageStore(cone_viewOut, pix, vec4(acc.radiance, acc.alpha));
}
