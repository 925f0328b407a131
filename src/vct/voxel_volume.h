// The voxels of one VCT render on the GPU: a dense grid over the chosen region, or a
// clipmap around the camera (vct.clipmap.levels > 0), voxelized, injected (GI) and filtered
// as the plan says, or taken from the session's cache of grids keyed by everything that
// shapes them.
#pragma once

#include "clipmap/clipmap.h"
#include "cone/cone_settings.h"
#include "core/method.h"
#include "voxelize/voxel_grid.h"

#include <nlohmann/json.hpp>

#include <deque>
#include <map>
#include <memory>
#include <string>

namespace vct {

struct VoxelVolume {
    std::shared_ptr<VoxelGrid> grid;   // dense path; the clipmap's coarsest level otherwise
    std::shared_ptr<Clipmap> clipmap;  // null on the dense path
    nlohmann::json stats;              // extra["voxels"]
};

// The grids a session keeps (the key: resolution, injection, bounces, region, clipmap).
// At most kMaxCachedVolumes, the oldest dropped first.
constexpr size_t kMaxCachedVolumes = 6;
struct VoxelVolumeCache {
    std::map<std::string, std::shared_ptr<VoxelGrid>> grids;
    std::map<std::string, std::shared_ptr<Clipmap>> clipmaps;
    std::deque<std::string> order;  // keys of both maps, oldest first
    std::map<std::string, std::string> litBy;  // grid key -> lightsKey of the radiance it holds
};

// The scene's lights as a key (type, position, direction, colour, exactly): radiance injected
// under one key is stale under another.
std::string lightsKey(const Scene& scene);

// Whether this render's grid keeps albedo, normal and emission: injection, the GI cones or a
// voxel view read them, AO alone reads opacity (voxelize.h). Both backends.
bool voxelAttributesNeeded(const MethodContext& ctx);

// A key of everything a grid depends on: two requests with the same key share one grid.
// `attributes`: the grid keeps them (voxelAttributesNeeded).
std::string voxelGridKey(const RenderRequest& request, bool inject, bool aniso, bool attributes);
// The part of a grid's key that names its world box.
std::string boundsKey(const Bounds3& bounds);

// Builds (or reuses, unless request.reuseSceneData is false) the volume of this render.
VoxelVolume voxelVolumeFor(MethodContext& ctx, const ConeSettings& cone, VoxelVolumeCache& cache);

}  // namespace vct
