// Further diffuse bounces between voxels (vct.bounces): after injection (src/voxelize) has
// put emission and direct light into grid.radiance, each bounce gathers the previous total
// at every occupied voxel with the pixel cones' march and cone set (shaders/cone/
// cone_bounce.glsl) and re-injects albedo times what it gathered. The direct term stays
// fixed, so N bounces carry a punctual light's light over N + 1 reflections inside the grid,
// and the pixel cones add one more: reference.bounces = N + 2 is the bounce-matched reference.
//
// Emitters (emissive surfaces, and the sky when the bounces see it) put their light into the
// voxels unreflected, so the same N gathers would carry it over one reflection fewer: N + 1
// with the pixel's, where the path tracer with N + 2 reflections finds more (the Cornell box's
// ceiling, lit by the panel only through a wall, would stay black without bounces). A scene
// with emitters therefore gathers once more first, from the emission alone: what the emitters
// throw on each voxel is their direct light, as injection computes a punctual light's. With
// L = emission + direct, G a gather and rho the albedo, the voxels leave
// L + rho G L + ... + (rho G)^N L + (rho G)^(N + 1) emission,
// every light's paths over at most N + 1 reflections in the grid.
//
// Keys, defaults, ranges and docs: bounceSettings() (vct.bounces, vct.bounce.sky,
// vct.bounce.emitters).
#pragma once

#include "cone/cone_settings.h"
#include "core/settings.h"
#include "core/timing.h"
#include "voxelize/voxel_grid.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vct {

// Default of vct.bounces. One extra bounce: the reference's paths carry several. Cornell box
// (64 px, 64^3): with direct light alone in the voxels the indirect light is 37% dark
// against 4 path-traced reflections; with one bounce it is within 10% of the bounce-matched
// reference. It costs one more cone gather per occupied voxel (timer scope "bounce").
constexpr int kDefaultVctBounces = 1;

// Entries of one list of gathering voxels (count + codes, 4 bytes each): the 128 MiB a
// shader storage buffer binding is guaranteed to hold. Larger grids list slab by slab.
constexpr size_t kMaxVoxelListEntries = (size_t(1) << 27) / sizeof(uint32_t);

// A slab of z slices [z0, z1) with its own list of gathering voxels, of room for `capacity`
// codes (at most the slab's voxels or the grid's occupied voxels, whichever is fewer).
struct VoxelListSlab {
    int z0 = 0, z1 = 0;
    size_t capacity = 0;
};
// The slabs of a grid of `resolution` (each list within kMaxVoxelListEntries, count included).
std::vector<VoxelListSlab> voxelListSlabs(const glm::ivec3& resolution, size_t occupiedVoxels);

struct BounceSettings {
    int bounces = kDefaultVctBounces;
    bool sky = true;       // bounce cones that escape see the sky radiance
    bool emitters = true;  // emitters' direct light: one gather more first (above)
};
const SettingsTable<BounceSettings>& bounceSettings();
int readVctBounces(const ParamMap& params);  // bounceSettings().read(params).bounces

// The gathers a grid's bounces take: settings.bounces, and one more first when
// settings.emitters and the grid holds emitters (`emissive` materials, or a `sky` > 0 the
// bounce cones see). Both backends.
int bounceGathers(const BounceSettings& settings, bool emissive, float sky);

// For volumes that hold direct light only (clipmaps): reads vct.bounces
// and, when the volume `injects`, refuses an explicit request for bounces with
// UsageError naming `where`. The default is not a request.
void refuseVctBounces(const ParamMap& params, bool injects, const std::string& where);

// Adds readVctBounces(params) bounces to grid.radiance (bounceGathers gathers; level 0; mips
// are rebuilt for each gather and left stale afterwards: call buildMips next). `cone` is the
// pixel passes' settings (cone set, aperture, step, offset, directional mips). Escaping cones
// see `sky` unless vct.bounce.sky = 0. Timer scope "bounce". No-op when there is nothing to
// gather.
void traceVoxelBounces(VoxelGrid& grid, float sky, const ConeSettings& cone, const ParamMap& params,
                       PassTimer& timer);

}  // namespace vct
