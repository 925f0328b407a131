// Turns the fixed-point sums of voxelize.glsl into the float textures of the VoxelGrid
// contract: opacity (1 where any triangle overlaps), weighted-average albedo, unit normal
// and emission. Counts occupied voxels.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

layout(r32ui, binding = VOX_UNIT_ALBEDO + 0) uniform readonly uimage3D accAlbedoR;
layout(r32ui, binding = VOX_UNIT_ALBEDO + 1) uniform readonly uimage3D accAlbedoG;
layout(r32ui, binding = VOX_UNIT_ALBEDO + 2) uniform readonly uimage3D accAlbedoB;
layout(r32ui, binding = VOX_UNIT_NORMAL + 0) uniform readonly uimage3D accNormalX;
layout(r32ui, binding = VOX_UNIT_NORMAL + 1) uniform readonly uimage3D accNormalY;
layout(r32ui, binding = VOX_UNIT_NORMAL + 2) uniform readonly uimage3D accNormalZ;
layout(r32ui, binding = VOX_UNIT_WEIGHT) uniform readonly uimage3D accWeight;
#ifdef HAS_EMISSION
layout(r32ui, binding = VOX_UNIT_EMISSION + 0) uniform readonly uimage3D accEmissionRLo;
layout(r32ui, binding = VOX_UNIT_EMISSION + 1) uniform readonly uimage3D accEmissionRHi;
layout(r32ui, binding = VOX_UNIT_EMISSION + 2) uniform readonly uimage3D accEmissionGLo;
layout(r32ui, binding = VOX_UNIT_EMISSION + 3) uniform readonly uimage3D accEmissionGHi;
layout(r32ui, binding = VOX_UNIT_EMISSION + 4) uniform readonly uimage3D accEmissionBLo;
layout(r32ui, binding = VOX_UNIT_EMISSION + 5) uniform readonly uimage3D accEmissionBHi;
#endif

// Output units 13..16 (after the accumulators).
layout(r16f, binding = 13) uniform writeonly image3D outOpacity;
layout(rgba16f, binding = 14) uniform writeonly image3D outAlbedo;
layout(rgba16f, binding = 15) uniform writeonly image3D outNormal;
layout(EMISSION_FORMAT, binding = 16) uniform writeonly image3D outEmission;

layout(std430, binding = VOX_BINDING_BIGLIST) buffer BigList {
    uvec4 bigHeader;  // w = occupied voxels
    uint bigTriangles[];
};

uniform ivec3 uResolution;

// Largest finite value of the output format, so emission up to 1e6 never becomes Inf.
const float EMISSION_STORE_MAX = EMISSION_FORMAT_MAX;

#ifdef HAS_EMISSION
float vox_emission(uint lo, uint hi, float weight) {
    // hi * 2^32 + lo in float: relative rounding ~6e-8, far below the 2^-12 quantum scale.
    float sum = float(hi) * 4294967296.0 + float(lo);
    return min(sum / (weight * VOX_EMISSION_SCALE), EMISSION_STORE_MAX);
}
#endif

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, uResolution))) return;
    uint w = imageLoad(accWeight, v).r;
    if (w == 0u) {
        imageStore(outOpacity, v, vec4(0.0));
        imageStore(outAlbedo, v, vec4(0.0));
        imageStore(outNormal, v, vec4(0.0));
        imageStore(outEmission, v, vec4(0.0));
        return;
    }
    atomicAdd(bigHeader.w, 1u);
    float weight = float(w);
    vec3 albedo = vec3(imageLoad(accAlbedoR, v).r, imageLoad(accAlbedoG, v).r, imageLoad(accAlbedoB, v).r) /
                  (weight * VOX_ALBEDO_SCALE);
    vec3 n = vec3(int(imageLoad(accNormalX, v).r), int(imageLoad(accNormalY, v).r),
                  int(imageLoad(accNormalZ, v).r));
    float len = length(n);
    // Normals that cancel (both faces of a thin wall in one voxel) are stored as zero:
    // injection then treats the voxel as facing every light.
    n = len > 1e-3 * weight * VOX_NORMAL_SCALE ? n / len : vec3(0.0);
    vec3 e = vec3(0.0);
#ifdef HAS_EMISSION
    e = vec3(vox_emission(imageLoad(accEmissionRLo, v).r, imageLoad(accEmissionRHi, v).r, weight),
             vox_emission(imageLoad(accEmissionGLo, v).r, imageLoad(accEmissionGHi, v).r, weight),
             vox_emission(imageLoad(accEmissionBLo, v).r, imageLoad(accEmissionBHi, v).r, weight));
#endif
    imageStore(outOpacity, v, vec4(1.0));
    imageStore(outAlbedo, v, vec4(albedo, 1.0));
    imageStore(outNormal, v, vec4(n, 1.0));
    imageStore(outEmission, v, vec4(e, 1.0));
}
