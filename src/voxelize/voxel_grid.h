// The dense voxel grid shared by voxelization (src/voxelize), radiance injection and
// mip building (src/voxelize), and cone tracing (src/cone). This header is the contract
// between them.
//
// Conventions:
// - Cubic voxels of edge `voxelSize`; `resolution` voxels per axis; the grid's min corner
//   at `origin`. Voxel coordinates u = (world - origin) / voxelSize lie in [0, resolution];
//   texture coordinates are u / resolution (voxel centres at (i + 0.5) / resolution).
// - All 3D textures use GL_LINEAR filtering with a zero border (CLAMP_TO_BORDER), so
//   cones leaving the grid see empty space, i.e. the sky.
// - `opacity` and `radiance` are mipmapped (isotropic, levels = log2(maxres) + 1).
//   Radiance is PREMULTIPLIED by opacity (rgb = L * alpha, a = alpha), so cone tracing
//   composites front to back: C += (1 - A) * c; A += (1 - A) * a.
// - Radiance is the outgoing diffuse radiance of the voxel's surfaces (W/sr/m^2 per
//   channel): emission + albedo / pi * irradiance. It does not depend on voxel size.
// - Anisotropic mips (optional): six textures, one per axis direction (+X, -X, +Y, -Y,
//   +Z, -Z), whose level k holds level k + 1 of the pyramid (half the base resolution at
//   their level 0), each RGBA16F premultiplied radiance + alpha, composited front to back
//   along their axis as seen by a cone travelling in that direction (Crassin 2011).
#pragma once

#include "gl/handles.h"
#include "scene/scene.h"

#include <array>
#include <glm/glm.hpp>

namespace vct {

struct VoxelGrid {
    glm::ivec3 resolution{0};   // voxels per axis
    float voxelSize = 0.f;      // world units
    glm::vec3 origin{0.f};      // world position of the grid's min corner
    int levels = 1;             // mip levels in opacity/radiance
    glm::mat4 voxelFromWorld{1.f};   // world -> voxel units [0, res]
    glm::mat4 worldFromVoxel{1.f};

    GlTexture opacity;   // GL_R16F, 3D, mipmapped: covered fraction of the voxel in [0, 1]
    GlTexture albedo;    // GL_RGBA16F, level 0 only: average linear albedo (rgb), a = 1 where occupied
    // GL_RGBA16F, mipmapped like opacity (the mips once radiance is injected): level 0 the
    // average unit normal (xyz), a = 1 where occupied; injection turns a two-sided voxel's into
    // its facing normal (voxelize_shared.h). The cones' facing test reads every level.
    GlTexture normal;
    GlTexture emission;  // GL_RGBA16F, level 0 only: average emitted radiance (rgb)
    bool emissive = false;  // a material emits and the grid holds its emission (else zeros or none)
    // GL_RGBA16_SNORM, level 0 only, present when a material is doubleSided: the unit normal
    // (xyz, the winding side) and the doubleSided share of the voxel's weight (a).
    GlTexture twoSided;
    // GL_RGBA16F, level 0 only, present with vct.voxel.edges=sheet: the sheet texels (opacity,
    // lo, hi, axis) that the pixels' AO and GI cones read at the base level (vox_sheetTexel,
    // cone_sampleSheets).
    GlTexture sheets;
    // GL_R32UI, level 0 only, with sheets: each voxel's extent bits (vox_extentBits), where in it
    // along each axis its surfaces lie; cone_sampleSheets weighs a sheet or box across by them.
    GlTexture sheetExtents;
    GlTexture radiance;  // GL_RGBA16F, 3D, mipmapped, premultiplied; empty until injection
    bool anisotropic = false;
    std::array<GlTexture, 6> anisoRadiance;  // see above; empty unless anisotropic and lit
    // An AO grid's directional levels (no radiance to carry): GL_RGBA16F, levels as
    // anisoRadiance's, rgb = the directional opacity along X, Y, Z (a unused). Opacity alone
    // is the same both ways along an axis (a line's transmittance is the product of its
    // voxels', in either order; only radiance depends on which voxel is in front), so one
    // texture serves the six directions and a cone reads its three in one fetch.
    GlTexture anisoOpacity;
    // The directional textures hold optical depth (radiance * tau, tau), not (premultiplied
    // radiance, alpha): shaders/voxelize/opacity_depth.h, vct.opacity=depth.
    bool depthLevels = false;

    size_t memoryBytes = 0;  // GPU memory of all textures above
    size_t occupiedVoxels = 0;  // voxels with opacity > 0 at level 0 (filled by voxelize)
    // Dispatches injectRadiance split the lights over (injectLightsPerDispatch); 0 until injected.
    int injectDispatches = 0;
};

// Fits a grid with cubic voxels to `bounds` (padded by one voxel on each side so surfaces
// on the boundary stay inside): `maxResolution` voxels along the longest axis.
VoxelGrid makeGridLayout(const Bounds3& bounds, int maxResolution);

// An exact layout: min corner `origin`, cubic voxels of edge `voxelSize`, `resolution` voxels
// per axis (clipmap levels, whose origins and voxel sizes must nest exactly).
VoxelGrid makeGridLayout(const glm::vec3& origin, float voxelSize, const glm::ivec3& resolution);

}  // namespace vct
