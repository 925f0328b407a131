// What a cone pass did, in units that carry to another device: the volume samples its cones
// took (one filtered, possibly directional, lookup each) and the texture fetches those made
// (three per directional sample, one more below level 1 and, for GI, one for the facing
// normal; one per isotropic or clipmap sample), summed over the image. The dense GPU passes
// (cone/cone_trace.h) and the sparse CPU tracer (vdb/sparse_cone.h) count the same way.
#pragma once

#include "cone/cone_settings.h"

#include <nlohmann/json.hpp>

namespace vct {

struct ConeCost {
    double samples = 0.0;
    double fetches = 0.0;
    int pixels = 0;         // the image's
    int surfacePixels = 0;  // those with a surface (not sky): the per-pixel figures' divisor
    int tracedPixels = 0;   // those whose own cones were marched (fewer with vct.trace-scale > 1)
    // A GPU pass's dispatches per marching stage: the cone set split by the loop budget
    // (cone/cone_budget.h, vct.dispatch-cones), 1 where it fits one; 0 on the sparse CPU tracer,
    // which has none.
    int dispatches = 0;

    // One pixel's counts: `surface` when the G-buffer has a surface there, whether or not the
    // pixel's own cones were traced (zero samples: sky, or resolved from traced neighbours).
    void addPixel(double pixelSamples, double pixelFetches, bool surface) {
        ++pixels;
        samples += pixelSamples;
        fetches += pixelFetches;
        if (surface) ++surfacePixels;
        if (pixelSamples > 0.0) ++tracedPixels;
    }
};

// For a render's statistics: per surface pixel and in all, with the cones marched (the set
// times its lanes at `voxelRes`).
nlohmann::json coneCostJson(const ConeCost& c, const ConeSettings& s, int voxelRes);

}  // namespace vct
