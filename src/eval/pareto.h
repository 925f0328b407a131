// Pareto fronts of time against error over result records: the variants worth their cost.
#pragma once

#include <nlohmann/json.hpp>

namespace vct {

// Sets "pareto" (on the time_ms / rmse front) and "pareto_roi" (time_ms / roi_rmse; null
// without an ROI) on each record, within groups of equal (case, kind). A record is on the
// front when no other record of its group is at most as slow and at most as wrong, and
// strictly better in one of the two.
void markParetoFronts(nlohmann::json& records);

}  // namespace vct
