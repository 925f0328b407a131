#include "gl/program_cache.h"

#include "core/timing.h"
#include "gl/program_limits.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace vct {

std::string ProgramKey::name() const { return compute.empty() ? vertex + "+" + fragment : compute; }

std::string ProgramKey::id() const {
    std::string k = name();
    for (const auto& [d, v] : defines) k += "|" + d + "=" + v;
    return k;
}

ProgramKey computeProgramKey(const std::string& shader, ShaderDefines defines) {
    ProgramKey k;
    k.compute = shader;
    k.defines = std::move(defines);
    return k;
}

ProgramKey graphicsProgramKey(const std::string& vertex, const std::string& fragment, ShaderDefines defines) {
    ProgramKey k;
    k.vertex = vertex;
    k.fragment = fragment;
    k.defines = std::move(defines);
    return k;
}

namespace {

struct Cache {
    std::map<std::string, GlProgram> programs;
    std::map<std::string, int> compiles;
    std::mutex mutex;
};

// Function-local static: created after the shared GL context, so destroyed before it.
Cache& cache() {
    static Cache c;
    return c;
}

// One write(2) per line on an O_APPEND descriptor: lines from parallel test processes
// never interleave.
void logCompiled(const std::string& id) {
    const char* path = std::getenv(kProgramLogVariable);
    if (!path || !*path) return;
    const int fd = ::open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd < 0) return;
    const std::string line = id + "\n";
    const ssize_t written = ::write(fd, line.data(), line.size());
    (void)written;
    ::close(fd);
}

GlProgram build(const ProgramKey& key) {
    GlProgram p = key.compute.empty() ? buildGraphicsProgram(key.vertex, key.fragment, key.defines)
                                      : buildComputeProgram(key.compute, key.defines);
    static const GlLimits limits = deviceLimits();
    const std::vector<std::string> over = limitViolations(inspectProgram(p.id()), limits);
    if (!over.empty()) {
        std::string msg = "program '" + key.id() + "' exceeds this device's limits: " + over.front();
        for (size_t i = 1; i < over.size(); ++i) msg += "; " + over[i];
        throw std::runtime_error(msg);
    }
    return p;
}

}  // namespace

GLuint cachedProgram(const ProgramKey& key) {
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    const std::string id = key.id();
    auto it = c.programs.find(id);
    if (it != c.programs.end()) return it->second.id();
    c.compiles[id]++;
    logCompiled(id);
    const double start = nowMs();
    GlProgram program = build(key);
    addProgramBuildMs(nowMs() - start);
    return c.programs.emplace(id, std::move(program)).first->second.id();
}

const std::map<std::string, int>& programCompileCounts() { return cache().compiles; }

}  // namespace vct
