#include "support/run_vct.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace vcttest {

std::string sourceDir() { return VCT_SOURCE_DIR; }

std::string sharedScenesDir() {
    if (const char* env = std::getenv("VCT_SHARED_SCENES")) return env;
    return sourceDir() + "/../shared/scenes";
}

CommandResult runVct(const std::string& args) {
    std::string cmd = "cd '" + sourceDir() + "' && '" + std::string(VCT_BINARY) + "' " + args + " 2>&1";
    CommandResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string freshTempDir(const std::string& name) {
    namespace fs = std::filesystem;
    fs::path p = fs::temp_directory_path() / ("vct_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

}  // namespace vcttest
