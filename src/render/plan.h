// Pass planning: a render runs only the passes its scene and its requested outputs need
// (BRIEF section 7). Each pass declares the resources it reads and writes; the requested
// AOVs select resources; the passes that write a needed resource run, pulling in what
// they read; every other pass is left out with the reason. Pure logic, no GL: tested on
// the CPU and printed by `vct render --explain`.
#pragma once

#include "render/request.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace vct {

// What the scene contains that changes which passes and shader features are needed.
struct SceneFeatures {
    size_t triangles = 0;
    size_t materials = 0;
    size_t lights = 0;
    bool hasEmission = false;
    bool hasTextures = false;
    bool hasAlphaMask = false;
    bool hasOffscreenOccluders = false;
};
SceneFeatures analyzeScene(const Scene& scene);

struct PassDecl {
    std::string name;
    std::vector<std::string> reads;
    std::vector<std::string> writes;
    std::string why;  // why it exists in this request (filled when declared)
};

struct SkippedPass {
    std::string name;
    std::string reason;
};

struct RenderPlan {
    std::vector<PassDecl> run;        // in execution order, each with the reason it runs
    std::vector<SkippedPass> skipped; // every known pass that does not run, with the reason
    std::vector<std::string> notes;   // shader variants and other choices made from the scene
    bool runs(const std::string& pass) const;
    std::vector<std::string> runNames() const;
};

// Throws std::invalid_argument for requests that cannot be satisfied (e.g. --aov ao with
// --ao none), naming the option.
RenderPlan planRender(const SceneFeatures& scene, const RenderRequest& request);
std::string describePlan(const RenderPlan& plan);

// Every pass name the renderer knows, in execution order.
const std::vector<std::string>& allPassNames();

}  // namespace vct
