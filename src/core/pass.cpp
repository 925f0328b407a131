#include "core/pass.h"

#include <algorithm>

namespace vct {

bool RenderPlan::runs(PassId pass) const {
    return std::any_of(run.begin(), run.end(), [&](const PassDecl& p) { return p.id == pass; });
}

std::vector<std::string> RenderPlan::runNames() const {
    std::vector<std::string> out;
    for (const auto& p : run) out.emplace_back(p.id.name);
    return out;
}

}  // namespace vct
