// Pass planning: a render runs only the passes its scene and its requested outputs need.
// The renderer's own passes (G-buffer, shadows, direct light, composite) and the passes its
// methods declare (core/method.h) each name the resources they read and write; the
// requested AOVs select resources; the passes that write a needed resource run, pulling in
// what they read; every other pass is left out with the reason. Pure logic, no GL: tested on
// the CPU and printed by `vct render --explain`.
#pragma once

#include "core/method.h"
#include "core/pass.h"
#include "core/request.h"
#include "core/scene_features.h"

#include <string>
#include <vector>

namespace vct {

// The methods a request names (null for none); a UsageError for a name the registry lacks.
struct ActiveMethods {
    const Method* ao = nullptr;
    const Method* gi = nullptr;
    // AO first: the order their passes are declared and run.
    std::vector<const Method*> list() const;
};
ActiveMethods activeMethods(const RenderRequest& request);

// Throws UsageError for requests that cannot be satisfied (e.g. --aov ao with --ao none),
// naming the option.
RenderPlan planRender(const SceneFeatures& scene, const RenderRequest& request);
std::string describePlan(const RenderPlan& plan);

// Every pass the renderer knows: its own and every registered method's, in a fixed order.
std::vector<PassId> allPassIds();

// Every AOV a render can write: the renderer's and the registered methods'.
std::vector<AovInfo> knownAovs();
const AovInfo* findAov(const std::string& name);

}  // namespace vct
