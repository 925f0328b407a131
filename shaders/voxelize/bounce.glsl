// One further diffuse bounce between voxels: each occupied voxel gathers the radiance of
// the previous bounce with 6 cones of 60 degrees around its normal (one along it, five at
// 60 degrees; weights pi/4 and 3pi/20 of the cosine lobe, normalized to sum to 1; Villegas
// 2016 / Rauwendaal "Deferred voxel shading"), so E / pi = sum_i w_i L_i and the voxel's
// outgoing radiance becomes L_direct + albedo * sum_i w_i L_i. With albedo <= 1 and
// weights summing to 1 each bounce adds less than the previous one.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(binding = 0) uniform sampler3D uRadiance;  // previous bounce, premultiplied, mipmapped
layout(binding = 1) uniform sampler3D uDirect;    // emission + direct, premultiplied, level 0
layout(binding = 2) uniform sampler3D uAlbedo;
layout(binding = 3) uniform sampler3D uNormal;
layout(RADIANCE_FORMAT, binding = 0) uniform writeonly image3D outRadiance;

uniform ivec3 uResolution;
uniform float uSky;         // radiance of the uniform sky seen by escaping cones
uniform float uMaxLevel;    // highest mip level

const float RADIANCE_MAX = RADIANCE_FORMAT_MAX;
const float TAN_HALF_APERTURE = 0.57735027;  // tan(30 degrees)

vec3 bounce_cone(vec3 origin, vec3 dir) {
    vec3 invRes = 1.0 / vec3(uResolution);
    vec3 color = vec3(0.0);
    float alpha = 0.0;
    float t = 1.0;  // voxels: starts one voxel out (plus the origin offset) against self-occlusion
    float maxT = length(vec3(uResolution));
    while (t < maxT && alpha < 0.99) {
        float diameter = max(1.0, 2.0 * t * TAN_HALF_APERTURE);
        float level = min(log2(diameter), uMaxLevel);
        vec3 p = origin + dir * t;
        if (any(lessThan(p, vec3(-diameter))) || any(greaterThan(p, vec3(uResolution) + diameter))) break;
        vec4 s = textureLod(uRadiance, p * invRes, level);
        // Radiance leaves the front of a surface (vox_facingWeight), as in the pixel cones.
        vec4 n = textureLod(uNormal, p * invRes, level);  // coverage-weighted mean normal
        s.rgb *= vox_facingWeight(n.xyz / max(n.w, 1e-4), dir);
        float step = 0.5 * diameter;
        // Opacity corrected for the step length relative to the sample's footprint.
        float a = 1.0 - pow(max(1.0 - s.a, 0.0), step / diameter);
        vec3 c = s.a > 1e-6 ? s.rgb * (a / s.a) : vec3(0.0);
        color += (1.0 - alpha) * c;
        alpha += (1.0 - alpha) * a;
        t += step;
    }
    return color + (1.0 - alpha) * vec3(uSky);
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uResolution))) return;
    vec4 direct = texelFetch(uDirect, v, 0);
    float opacity = direct.a;
    vec3 n = texelFetch(uNormal, v, 0).xyz;
    if (opacity <= 0.0 || dot(n, n) < 0.5) {
        imageStore(outRadiance, v, direct);
        return;
    }
    vec3 albedo = texelFetch(uAlbedo, v, 0).rgb;
    vec3 tangent = normalize(abs(n.x) > 0.5 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    vec3 bitangent = cross(n, tangent);
    vec3 origin = vec3(v) + 0.5 + n;
    vec3 gathered = 0.25 * bounce_cone(origin, n);
    for (int i = 0; i < 5; ++i) {
        float phi = float(i) * (2.0 * 3.14159265 / 5.0);
        vec3 dir = 0.5 * n + 0.8660254 * (cos(phi) * tangent + sin(phi) * bitangent);
        gathered += 0.15 * bounce_cone(origin, dir);
    }
    vec3 L = min(direct.rgb / opacity + albedo * gathered, vec3(RADIANCE_MAX));
    imageStore(outRadiance, v, vec4(L * opacity, opacity));
}
