// How many cones one dispatch of a cone pass marches. Drivers may end a long-running
// invocation's loops (llvmpipe after 65535 iterations of all its loops together: see
// CONE_LOOP_BUDGET in shaders/cone/cone_shared.h), so a pass bounds what one cone's march can
// iterate and marches as many cones per dispatch as the budget holds; the gathers carry their
// sums from one dispatch to the next (cone_common.glsl).
#pragma once

namespace vct {

// Loop iterations one cone of a gather may run: at most CONE_MAX_STEPS steps, and fewer where
// the distance limit bounds them: every step but the last advances at least beta voxels (a
// footprint is never below one voxel), so floor(maxDist / beta) + 1 steps, and one more for
// the sliver a float sum of steps can leave before the limit. Each step runs
// `loopsPerStep` iterations (the march's own; the plane limit's level search, at most one:
// a texel of level c is shorter than 2^(c + 1) voxels, cone_texelExtent; a clipmap's level
// search, twice per step), and the gather's loop over the cones adds one.
long long coneLoopBound(float maxDistVoxels, float stepFactor, int loopsPerStep);

// Cones per dispatch: as many as CONE_LOOP_BUDGET holds cones of coneLoopBound, at least 1
// and at most CONE_BLOCK_CONES (the uniform block's slice); `requested` > 0 (vct.dispatch-cones)
// lowers it further.
int conesPerDispatch(float maxDistVoxels, float stepFactor, int loopsPerStep, int requested);

}  // namespace vct
