#include "core/timing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>

namespace vct {

namespace {
thread_local double tProgramBuildMs = 0.0;
}

void addProgramBuildMs(double ms) { tProgramBuildMs += ms; }
double programBuildMsSoFar() { return tProgramBuildMs; }

double nowMs() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

PassTimer::Scope::Scope(PassTimer& timer, std::string name, bool gl, Reruns reruns)
    : mTimer(timer), mName(std::move(name)), mGl(gl), mReruns(timer.mViewDependent ? Reruns::EveryFrame : reruns) {
    if (mGl) {
        glFinish();
        if (mTimer.mGpuQueries) {
            glGenQueries(1, &mQuery);
            glBeginQuery(GL_TIME_ELAPSED, mQuery);
        }
    }
    mBuildAtStart = programBuildMsSoFar();
    mStart = nowMs();
}

PassTimer::Scope::~Scope() {
    PassTiming t;
    t.name = mName;
    t.reruns = mReruns;
    if (mGl) {
        if (mQuery) glEndQuery(GL_TIME_ELAPSED);
        glFinish();
    }
    // A program built inside the scope is the process's one-off cost, not the pass's.
    const double built = programBuildMsSoFar() - mBuildAtStart;
    t.wallMs = std::max(0.0, nowMs() - mStart - built);
    if (mQuery) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(mQuery, GL_QUERY_RESULT, &ns);
        glDeleteQueries(1, &mQuery);
        t.gpuMs = double(ns) * 1e-6;
    }
    mTimer.add(std::move(t));
}

double PassTimer::totalMs() const {
    double s = 0;
    for (const auto& t : mTimings) s += t.wallMs;
    return s;
}

std::optional<double> PassTimer::frameGpuMs() const {
    double s = 0;
    bool any = false;
    for (const auto& t : mTimings) {
        if (t.reruns != Reruns::EveryFrame) continue;
        if (!t.gpuMs) return std::nullopt;
        s += *t.gpuMs;
        any = true;
    }
    return any ? std::optional<double>(s) : std::nullopt;
}

double PassTimer::sceneStaticMs() const {
    double s = 0;
    for (const auto& t : mTimings)
        if (t.reruns == Reruns::WhenSceneChanges) s += t.wallMs;
    return s;
}

}  // namespace vct
