// One further diffuse bounce between voxels, traced with the pixel cones' own march and cone
// set (cone_march.glsl: directional mips, facing test, plane limit, saturation): each
// occupied voxel with a normal gathers the previous bounce's radiance around its normal, so
// its outgoing radiance becomes L_direct + albedo * sum_c w_c (L_c + (1 - alpha_c) sky).
// When the scene has emitters (emissive materials, or a sky the bounces see), the first
// gather reads emission alone (BOUNCE_EMITTED writes it): what emitters throw on a voxel is
// their direct light, one reflection deep like a punctual light's (src/cone/cone_bounce.h).
// The weights integrate the cosine lobe and sum to 1, so with albedo < 1 each bounce adds
// less than the previous one. Voxels whose normals cancel (both faces of a thin wall) keep
// their direct light: they have no hemisphere to gather over. A two-sided voxel's facing normal
// (voxelize_shared.h) is shorter than one but never zero: it gathers on its brighter face, and
// its dimmer face shows the sum at the share it shows the direct light.
//
// Defines: CONE_GI = 1, CONE_ANISO (as the pixel cones), RADIANCE_FORMAT, RADIANCE_FORMAT_MAX;
// BOUNCE_LIST for the list of gathering voxels, BOUNCE_EMITTED for the emission alone; neither
// for the gather.
#include "cone/cone_march.glsl"

layout(std430, binding = CONE_BINDING_VOXEL_LIST) buffer VoxelList {
    uint listCount;
    uint listVoxels[];  // x | y << 10 | z << 20 (resolutions up to 1024)
};

layout(binding = CONE_UNIT_BOUNCE_DIRECT) uniform sampler3D bounce_direct;  // emission + direct, premultiplied
layout(binding = CONE_UNIT_BOUNCE_ALBEDO) uniform sampler3D bounce_albedo;

// A voxel gathers when it holds radiance and a normal (level 0 holds unit normals, zero where
// faces cancel, and two-sided voxels' facing normals).
bool bounce_gathers(ivec3 v) {
    vec3 n = texelFetch(cone_normalTexture, v, 0).xyz;
    return texelFetch(bounce_direct, v, 0).a > 0.0 && dot(n, n) > 0.0;
}

#ifdef BOUNCE_LIST
// Pass 1: the voxels that gather, in a list, so pass 2 runs one invocation per such voxel
// (on SIMD hardware a 4^3 block of the grid holds few surface voxels, and every lane of a
// block would wait for the longest march). Order is arbitrary; each voxel's result is not.
// One list per slab of z slices [uSlab.x, uSlab.y), so no list outgrows the 128 MiB of a
// storage buffer binding that GL guarantees.
layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

uniform ivec2 uSlab;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, uSlab.x);
    if (any(greaterThanEqual(v, ivec3(u.gridResolution.xy, uSlab.y))) || !bounce_gathers(v)) return;
    listVoxels[atomicAdd(listCount, 1u)] = uint(v.x) | (uint(v.y) << 10) | (uint(v.z) << 20);
}
#elif defined(BOUNCE_EMITTED)
// Before the first gather of a scene with emitters: the radiance the gather reads is the
// emission alone, premultiplied by the voxel's coverage as injection's radiance is.
layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;
layout(binding = CONE_UNIT_BOUNCE_EMISSION) uniform sampler3D bounce_emission;
layout(RADIANCE_FORMAT, binding = CONE_IMAGE_OUTPUT) uniform writeonly image3D bounce_out;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, ivec3(u.gridResolution.xyz)))) return;
    float a = texelFetch(bounce_direct, v, 0).a;
    imageStore(bounce_out, v, vec4(texelFetch(bounce_emission, v, 0).rgb * a, a));
}
#else
// Pass 2: voxels not in the list keep their direct light (the output starts as a copy of it).
layout(local_size_x = CONE_BOUNCE_GROUP) in;
layout(RADIANCE_FORMAT, binding = CONE_IMAGE_OUTPUT) uniform writeonly image3D bounce_out;

const float RADIANCE_MAX = RADIANCE_FORMAT_MAX;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= listCount) return;
    uint code = listVoxels[i];
    ivec3 v = ivec3(code & 1023u, (code >> 10) & 1023u, code >> 20);
    vec4 direct = texelFetch(bounce_direct, v, 0);
    vec3 n = normalize(texelFetch(cone_normalTexture, v, 0).xyz);
    // The voxel's surface lies up to half a voxel from its centre on either side: start the
    // cones the pixel offset beyond the farthest case, and measure the plane limit's height
    // from there, so a voxel never gathers its own surface.
    float offset = u.march.z;
    ConeGather g = cone_gatherVoxel(cone_gatherStart(i), vec3(v) + 0.5, n, n, offset + 0.5, offset, u.limits.x, 0.0,
                                    u.limits.y);
    cone_gatherCarry(i, g);
    vec3 albedo = texelFetch(bounce_albedo, v, 0).rgb;
    vec3 L = min(direct.rgb / direct.a + albedo * g.radiance, vec3(RADIANCE_MAX));
    imageStore(bounce_out, v, vec4(L * direct.a, direct.a));
}
#endif
