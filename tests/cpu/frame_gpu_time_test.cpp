// PassTimer::frameGpuMs: the GPU time of the passes a static scene's next frame reruns,
// defined only where every such pass has one; and program builds left out of the passes.
#include "core/timing.h"

#include <gtest/gtest.h>

using namespace vct;

namespace {

PassTiming pass(const char* name, double wall, std::optional<double> gpu, Reruns reruns) {
    PassTiming t;
    t.name = name;
    t.wallMs = wall;
    t.gpuMs = gpu;
    t.reruns = reruns;
    return t;
}

}  // namespace

TEST(FrameGpuTime, SumsThePerFramePassesAlone) {
    PassTimer timer;
    timer.add(pass("gbuffer", 5.0, 1.25, Reruns::EveryFrame));
    timer.add(pass("voxelize", 40.0, 30.0, Reruns::WhenSceneChanges));
    timer.add(pass("cone_ao", 9.0, 2.5, Reruns::EveryFrame));
    ASSERT_TRUE(timer.frameGpuMs().has_value());
    EXPECT_DOUBLE_EQ(*timer.frameGpuMs(), 3.75);
    EXPECT_DOUBLE_EQ(timer.sceneStaticMs(), 40.0);
}

TEST(FrameGpuTime, EmptyWhereAPerFramePassHasNoGpuTime) {
    PassTimer cpuRays;  // the reference: its rays run on the CPU
    cpuRays.add(pass("gbuffer", 5.0, 1.25, Reruns::EveryFrame));
    cpuRays.add(pass("reference_ao", 80.0, std::nullopt, Reruns::EveryFrame));
    EXPECT_FALSE(cpuRays.frameGpuMs().has_value());
    PassTimer staticOnly;  // a scene-static pass without GPU time does not matter
    staticOnly.add(pass("bvh", 3.0, std::nullopt, Reruns::WhenSceneChanges));
    EXPECT_FALSE(staticOnly.frameGpuMs().has_value()) << "no per-frame pass at all";
    staticOnly.add(pass("cone_ao", 9.0, 2.0, Reruns::EveryFrame));
    ASSERT_TRUE(staticOnly.frameGpuMs().has_value());
    EXPECT_DOUBLE_EQ(*staticOnly.frameGpuMs(), 2.0);
    EXPECT_FALSE(PassTimer().frameGpuMs().has_value());
}

// A program built inside a timed scope is the process's one-off cost: the scope's wall time
// leaves it out, and programBuildMsSoFar() holds it.
TEST(ProgramBuildTime, ATimedScopeLeavesOutTheProgramsBuiltInIt) {
    PassTimer timer;
    const double before = programBuildMsSoFar();
    {
        auto scope = timer.scope("pass", false);
        const double start = nowMs();
        while (nowMs() - start < 30.0) {
        }
        addProgramBuildMs(25.0);  // as the program cache reports a build of 25 ms
    }
    EXPECT_DOUBLE_EQ(programBuildMsSoFar() - before, 25.0);
    ASSERT_EQ(timer.timings().size(), 1u);
    EXPECT_GE(timer.timings()[0].wallMs, 4.9);  // 30 ms waited, 25 of them "building"
    EXPECT_LT(timer.timings()[0].wallMs, 20.0);
}
