// Per-pass timing: wall clock after glFinish (llvmpipe's timer queries read 0), and GPU
// time from GL_TIME_ELAPSED queries only where the driver's queries are meaningful.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace vct {

// When a pass must run again: every frame (it reads the view: the G-buffer, the cones, the
// reference's rays), or only when the scene or its lights change (voxelization, injection,
// bounces, mips, shadow maps, the reference's BVH). A render's frame cost is its wall clock
// less the second kind: what the next frame of the same static scene costs.
enum class Reruns { EveryFrame, WhenSceneChanges };

struct PassTiming {
    std::string name;
    double wallMs = 0.0;
    std::optional<double> gpuMs;  // empty where the driver's timer queries read 0
    Reruns reruns = Reruns::EveryFrame;
};

// Program builds (compile, link, the limits check: gl/program_cache.h) happen the first time
// a pass uses a program, a one-off cost of the process rather than of the pass or of the next
// frame. The cache adds each build's wall time here (per thread: a pass and the builds it
// triggers run on one); a timed scope leaves out what was built inside it, and a render
// reports the builds between its start and end (RenderResult::programBuildMs). GPU times are
// left as measured: the GPU may wait idle inside them while a program is built. What a
// driver compiles at a program's first draw or dispatch (llvmpipe's JIT) is not seen here
// and stays in that pass.
void addProgramBuildMs(double ms);
double programBuildMsSoFar();  // this thread's total

class PassTimer {
public:
    explicit PassTimer(bool gpuQueries = false) : mGpuQueries(gpuQueries) {}
    // Times `name` from construction to destruction of the returned scope.
    class Scope {
    public:
        Scope(PassTimer& timer, std::string name, bool gl, Reruns reruns);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
    private:
        PassTimer& mTimer;
        std::string mName;
        bool mGl;
        Reruns mReruns;
        unsigned mQuery = 0;
        double mStart = 0.0;
        double mBuildAtStart = 0.0;  // programBuildMsSoFar() when the scope began
    };
    // gl = true: glFinish before reading the clock at both ends (GPU work is synchronous to it).
    Scope scope(const std::string& name, bool gl = true, Reruns reruns = Reruns::EveryFrame) {
        return Scope(*this, name, gl, reruns);
    }
    // While one is alive, passes that would rerun only when the scene changes count as per-frame:
    // their inputs include the view after all (a voxel region fitted to the visible points is
    // built anew whenever the camera moves).
    class ViewDependent {
    public:
        ViewDependent(PassTimer& timer, bool dependent) : mTimer(timer), mWas(timer.mViewDependent) {
            mTimer.mViewDependent = mWas || dependent;
        }
        ~ViewDependent() { mTimer.mViewDependent = mWas; }
        ViewDependent(const ViewDependent&) = delete;
        ViewDependent& operator=(const ViewDependent&) = delete;
    private:
        PassTimer& mTimer;
        bool mWas;
    };
    void add(PassTiming t) { mTimings.push_back(std::move(t)); }
    const std::vector<PassTiming>& timings() const { return mTimings; }
    double totalMs() const;
    double sceneStaticMs() const;  // the passes that rerun only when the scene changes
    // The GPU's own time for the passes that rerun every frame (timer queries, no glFinish
    // stalls or CPU submission in it): what the frame costs a GPU that is kept busy. Empty
    // where any such pass has no GPU time: the driver's queries read 0 (llvmpipe), or the
    // pass ran on the CPU (the reference's rays), whose cost frame_ms alone holds.
    std::optional<double> frameGpuMs() const;

private:
    bool mGpuQueries;
    bool mViewDependent = false;
    std::vector<PassTiming> mTimings;
};

double nowMs();  // steady clock in milliseconds

}  // namespace vct
