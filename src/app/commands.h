// The research subcommands beside render/info (compare, sweep, merge, pareto, gallery,
// voxelize) and the --help-params text.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace vct {

void registerResearchCommands(CLI::App& app);
// Runs whichever registered research subcommand was parsed; returns the exit code.
int runResearchCommand(CLI::App& app);
// Every documented --param key with its default, range and meaning.
std::string paramsHelpText();

}  // namespace vct
