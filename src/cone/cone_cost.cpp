#include "cone/cone_cost.h"

#include "cone/cone_set.h"

#include <algorithm>

namespace vct {

nlohmann::json coneCostJson(const ConeCost& c, const ConeSettings& s, int voxelRes) {
    const double n = std::max(1, c.surfacePixels);
    return {{"samples_per_pixel", c.samples / n},
            {"fetches_per_pixel", c.fetches / n},
            {"samples", c.samples},
            {"fetches", c.fetches},
            {"surface_pixels", c.surfacePixels},
            {"traced_pixels", c.tracedPixels},
            {"trace_scale", s.traceScale},
            {"dispatches", c.dispatches},
            {"cones_marched", s.coneCount * resolveConeLanes(s.lanes, s.coneCount, voxelRes, s.lanesBase)}};
}

}  // namespace vct
