// `vct sweep` (a grid of comparisons, resumable and shardable) and `vct merge` (their
// results in one table). The research command dispatcher calls these two.
#pragma once

#include <CLI/CLI.hpp>

namespace vct {

void registerSweepCommands(CLI::App& app);
// Runs `sweep` or `merge` if one of them was parsed and returns its exit code; -1 otherwise.
int runSweepCommand(CLI::App& app);

}  // namespace vct
