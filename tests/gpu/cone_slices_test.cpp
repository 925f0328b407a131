// Cone passes split over dispatches (CONE_LOOP_BUDGET, shaders/cone/cone_shared.h;
// src/cone/cone_budget.h). The driver really runs the budget's loop iterations in one
// invocation; a march of more cones than one dispatch holds gives the sparse CPU march's values
// (one dispatch of them gave 0.36 where the sparse march gives 0.05: llvmpipe ended the
// invocation's loops); and any number of dispatches gives the same image, to the bit, in every
// stage that marches cones (trace, own, bounce; dense grid and clipmap).
#include "cone/cone_shared.h"
#include "eval/convergence.h"
#include "gl/context.h"
#include "gl/handles.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/filter_precision.h"
#include "support/raw_program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace vct;

namespace {

// Runs a one-invocation compute shader whose nested loops (outer x inner) and a following
// loop (tail) count their iterations; returns the count it wrote.
GLuint countedIterations(int outer, int inner, int tail) {
    const std::string source = "#version 450 core\n"
                               "layout(local_size_x = 1) in;\n"
                               "layout(std430, binding = 0) buffer Count { uint n; };\n"
                               "uniform ivec3 uLoops;\n"
                               "void main() {\n"
                               "  uint k = 0u;\n"
                               "  for (int a = 0; a < uLoops.x; ++a)\n"
                               "    for (int b = 0; b < uLoops.y; ++b) k++;\n"
                               "  for (int c = 0; c < uLoops.z; ++c) k++;\n"
                               "  n = k;\n"
                               "}\n";
    const vcttest::RawProgram probe = vcttest::linkCompute(source);
    EXPECT_TRUE(probe.linked);
    const GlProgram& program = probe.program;
    GlBuffer count = createBuffer(sizeof(GLuint));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, count.id());
    glUseProgram(program.id());
    glUniform3i(glGetUniformLocation(program.id(), "uLoops"), outer, inner, tail);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    GLuint n = 0;
    glGetNamedBufferSubData(count.id(), 0, sizeof(n), &n);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    return n;
}

ParamMap params(std::initializer_list<const char*> kv) {
    ParamMap p;
    for (const char* s : kv) p.set(s);
    return p;
}

RenderRequest request(const Scene& scene, bool gi) {
    RenderRequest r;
    r.width = 40;
    r.height = 32;
    r.camera = scene.cameras.front();
    r.voxelRes = 32;
    r.radius = 1.f;
    if (gi) {
        r.gi = "vct";
        r.aovs = {"indirect"};
    } else {
        r.ao = "vct";
        r.aovs = {"ao"};
    }
    return r;
}

}  // namespace

// One invocation runs the budget's iterations in nested loops and the margin the budget
// leaves the passes' other loops in a loop after them, every one of them.
TEST(ConeSlices, TheDriverRunsTheBudgetsIterationsInOneInvocation) {
    GlContext::shared();
    const int inner = 250, outer = gpu::CONE_LOOP_BUDGET / inner, tail = 4000;
    EXPECT_EQ(countedIterations(outer, inner, tail), GLuint(outer * inner + tail));
    // Past 65535 llvmpipe ends the loops (what the budget is for); not asserted: a driver
    // without the limit is what every GPU is.
    std::printf("an invocation asked for 70000 iterations ran %u\n", countedIterations(1, 70000, 0));
}

// 16 cones x 32 lanes with steps of 0.05 footprints: about 60 steps a lane, 30,000 loop
// iterations a gather and more (with the plane limit's search), which one dispatch cut short
// on llvmpipe. Split over the budget's dispatches, the dense march gives the sparse march's
// values at every point of the case.
TEST(ConeSlices, AMarchOfManyConesAgreesWithTheSparseMarch) {
    const ParamMap p = params({"vct.cones=16", "vct.lanes=32", "vct.grid=cube", "vct.step=0.05"});
    for (const AoConvergenceCase& c : aoConvergenceCases()) {
        if (c.name != "plate h=0.2R a=2R off") continue;
        const std::vector<double> dense = vctAoAt(c, 64, "gl", p);
        const std::vector<double> sparse = vctAoAt(c, 64, "vdb", p);
        EXPECT_LT(pointError(dense, sparse).max, vcttest::filterTolerance(2e-3, 0.02)) << c.name;
        return;
    }
    FAIL() << "the harness has no case plate h=0.2R a=2R off";
}

// The same render with one cone per dispatch and with the budget's: AO at full resolution and
// with a trace scale (trace and own stages), GI with a bounce (the bounce's gathers), and the
// clipmap; every pixel the same float.
TEST(ConeSlices, AnyNumberOfDispatchesGivesTheSameImage) {
    const Scene scene = loadScene(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf");
    RenderSession session(scene);
    struct Variant {
        bool gi;
        ParamMap params;
        const char* name;
    };
    const std::vector<Variant> variants = {
        {false, params({"vct.cones=16"}), "AO"},
        {false, params({"vct.cones=16", "vct.trace-scale=4"}), "AO, trace scale 4"},
        {true, params({"vct.cones=16", "vct.bounces=1"}), "GI, one bounce"},
        {false, params({"vct.cones=16", "vct.clipmap.levels=3"}), "AO, clipmap"},
    };
    for (const Variant& v : variants) {
        RenderRequest whole = request(scene, v.gi);
        whole.params = v.params;
        RenderRequest split = whole;
        split.params.set("vct.dispatch-cones", "1");
        const std::string aov = whole.aovs.front();
        const std::vector<float> a = session.render(whole).aovs.at(aov).pixels;
        const std::vector<float> b = session.render(split).aovs.at(aov).pixels;
        ASSERT_EQ(a.size(), b.size());
        size_t differ = 0;
        for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
        EXPECT_EQ(differ, 0u) << v.name;
        float sum = 0.f;
        for (float x : a) sum += x;
        EXPECT_GT(sum, 0.f) << v.name << ": the pass drew something";
    }
}
