// Helpers for tests that run the `vct` binary as a user would.
#pragma once

#include <string>

namespace vcttest {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs `vct ARGS` (the built binary) from the source directory; captures the output.
CommandResult runVct(const std::string& args);
// A fresh empty directory under the system temp dir, removed at process exit.
std::string freshTempDir(const std::string& name);
std::string sourceDir();
// Where third-party scenes live: $VCT_SHARED_SCENES, else <source>/../shared/scenes.
std::string sharedScenesDir();

}  // namespace vcttest
