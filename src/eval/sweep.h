// Sweeps: a grid of scenes x cameras x radii x method parameter values, run as one
// comparison per "case" (scene, camera, radius) so every variant of a case shares one
// G-buffer, one reference and one voxelization; resumable and shardable. `vct merge`
// folds the cases' results.json into one table with a Pareto-front column.
// The spec format is documented in docs/sweeps.md.
//
// This is the header callers include: the spec and its cases are in sweep_spec.h, the
// Pareto fronts in pareto.h.
#pragma once

#include "eval/pareto.h"
#include "eval/sweep_spec.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace vct {

struct Shard {
    int index = 0;  // 0-based
    int count = 1;
};
Shard parseShard(const std::string& text);  // "I/N" with 0 <= I < N
std::vector<SweepCase> casesOfShard(const std::vector<SweepCase>& cases, const Shard& shard);

struct SweepRunOptions {
    std::string outDir;
    Shard shard;
    bool writeImages = true;
    std::function<void(const std::string&)> log;       // one line per case (always)
    std::function<void(const std::string&)> progress;  // steps inside a case (may be empty)
};

struct SweepSummary {
    int ran = 0, skippedDone = 0, skippedMissing = 0;
};

// Runs the shard's cases into outDir/cases/<id>/, each with runComparison, or with
// runSequenceComparison where its camera is a path: a case whose results.json exists is
// skipped (both write it last, by rename), as is one whose scene file is absent.
// Needs a GL context (GlContext::shared()).
SweepSummary runSweep(const SweepSpec& spec, const SweepRunOptions& options);

// Reads every case under each directory (a sweep dir's cases/*/, or a comparison dir with
// results.json) and returns {"cases": [...], "records": [...]}: records flattened with
// case, scene, camera, radius, width, height, gl_renderer, ref_spp, ref_stderr columns and
// the Pareto flags. A sequence comparison's records (a path case) also get rmse (their
// rmse_mean, so they share the still records' columns and fronts), frames, camera_path (the
// path's source) and frame_seeds. Cases are ordered by (case index, id); a case id seen twice keeps the
// first. `warn` receives a line for each duplicate or incomplete case.
nlohmann::json mergeSweepResults(const std::vector<std::string>& dirs,
                                 const std::function<void(const std::string&)>& warn = {});

// The merged records as CSV (header first, RFC 4180 quoting).
std::string mergedCsv(const nlohmann::json& merged);

// Writes OUT/results.json and OUT/results.csv (temp name + rename).
void writeMerged(const nlohmann::json& merged, const std::string& outDir);

}  // namespace vct
