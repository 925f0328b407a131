// Per-pass timing: wall clock after glFinish (llvmpipe's timer queries read 0), and GPU
// time from GL_TIME_ELAPSED queries only where the driver's queries are meaningful.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace vct {

struct PassTiming {
    std::string name;
    double wallMs = 0.0;
    std::optional<double> gpuMs;  // empty where the driver's timer queries read 0
};

class PassTimer {
public:
    explicit PassTimer(bool gpuQueries = false) : mGpuQueries(gpuQueries) {}
    // Times `name` from construction to destruction of the returned scope.
    class Scope {
    public:
        Scope(PassTimer& timer, std::string name, bool gl);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
    private:
        PassTimer& mTimer;
        std::string mName;
        bool mGl;
        unsigned mQuery = 0;
        double mStart = 0.0;
    };
    // gl = true: glFinish before reading the clock at both ends (GPU work is synchronous to it).
    Scope scope(const std::string& name, bool gl = true) { return Scope(*this, name, gl); }
    void add(PassTiming t) { mTimings.push_back(std::move(t)); }
    const std::vector<PassTiming>& timings() const { return mTimings; }
    double totalMs() const;

private:
    bool mGpuQueries;
    std::vector<PassTiming> mTimings;
};

double nowMs();  // steady clock in milliseconds

}  // namespace vct
