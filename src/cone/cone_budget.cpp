#include "cone/cone_budget.h"

#include "cone/cone_shared.h"

#include <algorithm>
#include <cmath>

namespace vct {

long long coneLoopBound(float maxDistVoxels, float stepFactor, int loopsPerStep) {
    long long steps = gpu::CONE_MAX_STEPS;
    if (std::isfinite(maxDistVoxels) && maxDistVoxels >= 0.f && stepFactor > 0.f) {
        const double byDistance = std::floor(double(maxDistVoxels) / double(stepFactor)) + 2.0;
        if (byDistance < double(steps)) steps = (long long)byDistance;
    }
    return steps * std::max(1, loopsPerStep) + 1;
}

int conesPerDispatch(float maxDistVoxels, float stepFactor, int loopsPerStep, int requested) {
    const long long fit = gpu::CONE_LOOP_BUDGET / coneLoopBound(maxDistVoxels, stepFactor, loopsPerStep);
    int cones = int(std::clamp<long long>(fit, 1, gpu::CONE_BLOCK_CONES));
    if (requested > 0) cones = std::min(cones, requested);
    return cones;
}

}  // namespace vct
