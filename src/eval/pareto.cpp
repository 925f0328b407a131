// Pareto fronts of time against error, per group of records that compete with each other.
#include "eval/pareto.h"

#include <map>
#include <string>
#include <vector>

namespace vct {

using nlohmann::json;

namespace {

// `a` dominates `b`: at most as slow and at most as wrong, strictly better in one.
bool dominates(const json& a, const json& b, const char* metric) {
    return a["time_ms"].get<double>() <= b["time_ms"].get<double>() && a[metric].get<double>() <= b[metric].get<double>() &&
           (a["time_ms"].get<double>() < b["time_ms"].get<double>() || a[metric].get<double>() < b[metric].get<double>());
}

}  // namespace

void markParetoFronts(json& records) {
    std::map<std::string, std::vector<size_t>> groups;
    for (size_t i = 0; i < records.size(); ++i)
        groups[records[i].value("case", std::string()) + "\n" + records[i].value("kind", std::string())].push_back(i);
    for (const char* metric : {"rmse", "roi_rmse"}) {
        const std::string flag = std::string(metric) == "rmse" ? "pareto" : "pareto_roi";
        for (const auto& [key, members] : groups)
            for (size_t i : members) {
                json& r = records[i];
                if (!r.contains(metric) || !r[metric].is_number() || !r["time_ms"].is_number()) {
                    r[flag] = nullptr;
                    continue;
                }
                bool dominated = false;
                for (size_t j : members)
                    if (j != i && records[j].contains(metric) && records[j][metric].is_number() &&
                        dominates(records[j], r, metric)) {
                        dominated = true;
                        break;
                    }
                r[flag] = !dominated;
            }
    }
}

}  // namespace vct
