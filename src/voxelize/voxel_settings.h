// The voxel settings both backends read (the dense GPU grid and the sparse CPU one).
#pragma once

#include "core/settings.h"

namespace vct {

// Storage of emission, radiance and the directional mips: half is RGBA16F (the contract's,
// clamping at 65504), float RGBA32F; auto picks float when the scene's emission or lights
// could exceed the half range (e.g. emission 1e6).
enum class VoxelPrecision { Auto, Half, Float };

// Level 0's opacity: 1 on every voxel a triangle overlaps (occupied), or the share of the
// voxel's column its sheets cover where they are of one dominant axis (coverage;
// vox_edgeOpacity in shaders/voxelize/voxelize_shared.h); or that, and where in its voxel each
// sheet lies, which the AO cones read at the base level of directional grids (sheet;
// vox_sheetTexel, cone_sampleSheets in shaders/cone/cone_march_shared.h).
enum class VoxelEdges { Occupied, Coverage, Sheet };

struct VoxelSettings {
    VoxelPrecision precision = VoxelPrecision::Auto;
    float injectOffset = 2.f;  // voxels along the normal where injection's shadow rays start
    int dispatchLights = 0;    // at most this many lights per injection dispatch; 0 = the loop budget's
    VoxelEdges edges = VoxelEdges::Occupied;
};
const SettingsTable<VoxelSettings>& voxelSettings();

// vct.preset: a named set of VCT settings across the voxels', the cones' and the region's
// tables. Each of those tables puts the preset's values in before it reads its own keys, so a
// key given on its own overrides the preset; the VCT method's table (vct/vct_settings.cpp)
// documents the key and checks what the preset cannot serve. Declared here, the lowest layer
// whose settings a preset sets.
enum class VctPreset {
    Default,   // every key's own default
    Converge,  // the march whose voxel error falls with the voxels (docs/convergence.md)
};
inline constexpr const char* kVctPresetKey = "vct.preset";
// The preset `params` names (Default when none); a name outside the list is a UsageError.
VctPreset readVctPreset(const ParamMap& params);

}  // namespace vct
