// The merged sweep records as one CSV table, for spreadsheets and plotting scripts.
#include "eval/sweep.h"

#include <algorithm>
#include <sstream>

namespace vct {

using nlohmann::json;

std::string mergedCsv(const json& merged) {
    static const std::vector<std::string> stillColumns = {
        "case",  "scene",       "camera", "radius",   "width",     "height",     "kind",   "method",   "label",
        "params", "time_ms",    "frame_ms", "rmse",   "mae",      "bias",      "max_abs",    "psnr",   "ssim",     "roi_rmse",
        "nonroi_rmse", "ref_spp", "ref_stderr", "pareto", "pareto_roi", "samples_per_pixel",
        "fetches_per_pixel", "rays_per_pixel", "voxel_bytes", "gl_renderer"};
    // A sequence's own columns come after the still ones, and only where a record has them:
    // a sweep without camera paths keeps its table as it was.
    static const std::vector<std::string> sequenceColumns = {"frames", "rmse_worst", "instability", "camera_path",
                                                             "frame_seeds"};
    std::vector<std::string> columns = stillColumns;
    const json& records = merged["records"];
    if (std::any_of(records.begin(), records.end(), [](const json& r) { return r.contains("frames"); }))
        columns.insert(columns.end(), sequenceColumns.begin(), sequenceColumns.end());
    auto quote = [](const std::string& s) {
        if (s.find_first_of(",\"\n") == std::string::npos) return s;
        std::string q = "\"";
        for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    std::ostringstream out;
    for (size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
    for (const json& r : merged["records"]) {
        for (size_t i = 0; i < columns.size(); ++i) {
            const std::string& col = columns[i];
            std::string cell;
            if (col == "params") {
                if (r.contains("params"))
                    for (auto it = r["params"].begin(); it != r["params"].end(); ++it)
                        cell += (cell.empty() ? "" : ";") + it.key() + "=" + it.value().get<std::string>();
            } else if (!r.contains(col) && r.contains("cost") && r["cost"].contains(col)) {
                // The record's device-independent cost (eval/comparison.h), flattened.
                if (!r["cost"][col].is_null()) cell = r["cost"][col].dump();
            } else if (r.contains(col) && !r[col].is_null()) {
                cell = r[col].is_string() ? r[col].get<std::string>() : r[col].dump();
            }
            out << (i ? "," : "") << quote(cell);
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace vct
