// Turns the fixed-point sums of voxelize.glsl into the float textures of the VoxelGrid
// contract: opacity (1 where any triangle overlaps), weighted-average albedo, unit normal
// and emission, and (TWO_SIDED) the unit normal with the doubleSided share of the weight
// (voxelize_shared.h: two-sided voxels). Counts occupied voxels. OPACITY_ONLY (a grid for AO):
// opacity alone, from the weight accumulator. EDGE_COVERAGE: the opacity of an occupied voxel
// is vox_edgeOpacity of the coverage pass's sums instead of 1.
#include "voxelize/voxelize_shared.h"

layout(local_size_x = VOX_GRID_GROUP, local_size_y = VOX_GRID_GROUP, local_size_z = VOX_GRID_GROUP) in;

// The accumulators are read through texture units (texelFetch; up to 14 of the 16 guaranteed
// per stage), so the only images are the four or five outputs: GL guarantees 8 image units.
#ifndef OPACITY_ONLY
layout(binding = VOX_ACC_ALBEDO + 0) uniform usampler3D accAlbedoR;
layout(binding = VOX_ACC_ALBEDO + 1) uniform usampler3D accAlbedoG;
layout(binding = VOX_ACC_ALBEDO + 2) uniform usampler3D accAlbedoB;
layout(binding = VOX_ACC_NORMAL + 0) uniform usampler3D accNormalX;
layout(binding = VOX_ACC_NORMAL + 1) uniform usampler3D accNormalY;
layout(binding = VOX_ACC_NORMAL + 2) uniform usampler3D accNormalZ;
#endif
layout(binding = VOX_ACC_WEIGHT) uniform usampler3D accWeight;
#ifdef TWO_SIDED
layout(binding = VOX_ACC_TWO_SIDED) uniform usampler3D accTwoSided;
#endif
#ifdef EDGE_COVERAGE
layout(binding = VOX_ACC_COVERAGE) uniform usampler3D accCoverage;
layout(binding = VOX_ACC_AXES) uniform usampler3D accAxes;
#endif
#ifdef HAS_EMISSION
layout(binding = VOX_ACC_EMISSION + 0) uniform usampler3D accEmissionRLo;
layout(binding = VOX_ACC_EMISSION + 1) uniform usampler3D accEmissionRHi;
layout(binding = VOX_ACC_EMISSION + 2) uniform usampler3D accEmissionGLo;
layout(binding = VOX_ACC_EMISSION + 3) uniform usampler3D accEmissionGHi;
layout(binding = VOX_ACC_EMISSION + 4) uniform usampler3D accEmissionBLo;
layout(binding = VOX_ACC_EMISSION + 5) uniform usampler3D accEmissionBHi;
#endif

layout(r16f, binding = VOX_IMAGE_RESOLVE_OPACITY) uniform writeonly image3D outOpacity;
#ifndef OPACITY_ONLY
layout(rgba16f, binding = VOX_IMAGE_RESOLVE_ALBEDO) uniform writeonly image3D outAlbedo;
layout(rgba16f, binding = VOX_IMAGE_RESOLVE_NORMAL) uniform writeonly image3D outNormal;
layout(EMISSION_FORMAT, binding = VOX_IMAGE_RESOLVE_EMISSION) uniform writeonly image3D outEmission;
#endif
#ifdef TWO_SIDED
// xyz = the unit normal (the winding side, kept for every later injection), w = the share of
// the weight whose material is doubleSided.
layout(rgba16_snorm, binding = VOX_IMAGE_RESOLVE_TWO_SIDED) uniform writeonly image3D outTwoSided;
#endif

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
    uint w = texelFetch(accWeight, v, 0).r;
    if (w == 0u) {
        imageStore(outOpacity, v, vec4(0.0));
#ifndef OPACITY_ONLY
        imageStore(outAlbedo, v, vec4(0.0));
        imageStore(outNormal, v, vec4(0.0));
        imageStore(outEmission, v, vec4(0.0));
#endif
#ifdef TWO_SIDED
        imageStore(outTwoSided, v, vec4(0.0));
#endif
        return;
    }
    atomicAdd(bigHeader.w, 1u);
#ifdef EDGE_COVERAGE
    uint axes = texelFetch(accAxes, v, 0).r;
    ivec3 along = ivec3(0);
    if (axes != 0u) along[vox_singleAxis(axes)] = 1;
    ivec3 below = v - along, above = v + along;
    uint coverageBelow = all(greaterThanEqual(below, ivec3(0))) ? texelFetch(accCoverage, below, 0).r : 0u;
    uint coverageAbove = all(lessThan(above, uResolution)) ? texelFetch(accCoverage, above, 0).r : 0u;
    imageStore(outOpacity, v,
               vec4(vox_edgeOpacity(axes, coverageBelow, texelFetch(accCoverage, v, 0).r, coverageAbove)));
#else
    imageStore(outOpacity, v, vec4(1.0));
#endif
#ifndef OPACITY_ONLY
    float weight = float(w);
    vec3 albedo = vec3(texelFetch(accAlbedoR, v, 0).r, texelFetch(accAlbedoG, v, 0).r, texelFetch(accAlbedoB, v, 0).r) /
                  (weight * VOX_ALBEDO_SCALE);
    vec3 n = vec3(int(texelFetch(accNormalX, v, 0).r), int(texelFetch(accNormalY, v, 0).r),
                  int(texelFetch(accNormalZ, v, 0).r));
    float len = length(n);
    // Normals that cancel (both faces of a thin wall in one voxel) are stored as zero:
    // injection then treats the voxel as facing every light.
    n = len > 1e-3 * weight * VOX_NORMAL_SCALE ? n / len : vec3(0.0);
    vec3 e = vec3(0.0);
#ifdef HAS_EMISSION
    e = vec3(vox_emission(texelFetch(accEmissionRLo, v, 0).r, texelFetch(accEmissionRHi, v, 0).r, weight),
             vox_emission(texelFetch(accEmissionGLo, v, 0).r, texelFetch(accEmissionGHi, v, 0).r, weight),
             vox_emission(texelFetch(accEmissionBLo, v, 0).r, texelFetch(accEmissionBHi, v, 0).r, weight));
#endif
    imageStore(outAlbedo, v, vec4(albedo, 1.0));
    imageStore(outNormal, v, vec4(n, 1.0));
    imageStore(outEmission, v, vec4(e, 1.0));
#endif
#ifdef TWO_SIDED
    imageStore(outTwoSided, v, vec4(n, float(texelFetch(accTwoSided, v, 0).r) / weight));
#endif
}
