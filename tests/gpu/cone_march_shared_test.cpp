// The cone march is one text for C++ and GLSL (shaders/cone/cone_march_shared.h, with the
// tangent frame of shaders/common/tangent_frame.h): here the same inputs go through it on the
// CPU and in a compute shader (cone_march_check.glsl), over the analytic slab volume of
// cone_march_check.h, and every output must agree to 1e-6 (relative above 1). On llvmpipe the
// largest difference is 5.4e-7, in a march's radiance, where the shader's exp2 and log2
// approximations add up over the steps. Between them the inputs take each branch of the
// march: plane limit on and off, falloff on and off, saturation with the close, leaving the
// box, and the volume's position-dependent level bound.
#include "cone/cone_march_check.h"
#include "cone/cone_programs.h"
#include "gl/context.h"
#include "gl/handles.h"
#include "gl/program_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vct {
namespace {

using gpu::ConeCheckInput;
using gpu::ConeCheckOutput;

static_assert(sizeof(ConeCheckInput) == 8 * sizeof(glm::vec4), "std430 layout of ConeCheckInput");
static_assert(sizeof(ConeCheckOutput) == 7 * sizeof(glm::vec4), "std430 layout of ConeCheckOutput");

constexpr float kTanHalf60 = 0.57735027f;  // tan(30 deg): the default 60 deg cones
constexpr float kTanHalf10 = 0.08748866f;  // tan(5 deg): a narrow cone, level 0 for a while

glm::vec4 unit(float x, float y, float z, float w = 0.f) { return glm::vec4(glm::normalize(glm::vec3(x, y, z)), w); }

// The inputs: what each is for is said beside it.
std::vector<ConeCheckInput> checkInputs() {
    std::vector<ConeCheckInput> in;
    auto add = [&](glm::vec4 n, glm::vec4 march, glm::vec4 origin, glm::vec3 d, glm::vec4 limits) {
        ConeCheckInput c;
        c.normal = n;
        c.march = march;
        c.origin = origin;
        c.direction = glm::vec4(glm::normalize(d), 0.f);
        c.direction.w = c.direction.z;  // rise against a geometric normal along +z
        c.limits = limits;
        c.partial = glm::vec4(0.1f, 0.05f, 0.02f, 0.3f);
        c.incoming = glm::vec4(0.2f, 0.1f, 0.05f, 0.4f);
        c.step = glm::vec4(0.5f, 1.f, 2.25f, 0.f);
        in.push_back(c);
    };
    // AO cone up through the slab, plane limit and falloff on.
    add(glm::vec4(0, 0, 1, 0), {kTanHalf60, 0.5f, 0.99f, 1.5f}, {16.f, 16.f, 8.5f, 1.5f}, {0.3f, 0.2f, 0.93f},
        {10.f, 0.4f, 3.7f, 0.f});
    // GI cone, plane limit off, run until it leaves the box; a tilted normal.
    add(unit(0.2f, -0.5f, 0.84f), {kTanHalf60, 0.5f, 0.99f, 0.f}, {6.f, 20.f, 4.f, 1.5f}, {0.5f, -0.3f, 0.8f},
        {110.f, 0.f, 7.3f, 0.f});
    // Narrow cone down through the slab into the band x > 24 where the volume refuses fine
    // levels; a normal at the -z pole.
    add(glm::vec4(0, 0, -1, 0), {kTanHalf10, 0.5f, 0.99f, 1.5f}, {20.f, 10.f, 28.f, 1.5f}, {0.35f, 0.1f, -0.93f},
        {60.f, 0.f, 12.1f, 0.f});
    // Narrow cone straight through the slab's full thickness: saturates and closes.
    add(unit(-0.6f, 0.3f, -0.74f), {0.02f, 0.5f, 0.95f, 0.f}, {10.f, 10.f, 2.f, 1.5f}, {0.f, 0.f, 1.f},
        {60.f, 0.f, 30.f, 0.f});
    // Along the slab towards +x from inside the band: leaves the box after a few steps.
    add(unit(0.7f, 0.7f, 0.1f), {kTanHalf60, 0.5f, 0.99f, 0.f}, {30.f, 5.f, 16.f, 1.5f}, {1.f, 0.05f, 0.02f},
        {50.f, 0.f, 1.9f, 0.f});
    // A normal with n.z = -0: frame_fromZ takes it as +z's side, on both processors. A
    // grazing cone that reaches the slab's lower ramp late.
    add(glm::vec4(1.f, 0.f, -0.f, 0.f), {kTanHalf60, 0.5f, 0.99f, 1.5f}, {3.f, 16.f, 11.5f, 1.5f},
        {0.97f, 0.1f, 0.06f}, {25.f, 0.16f, 5.5f, 0.f});
    // Grazing AO cone: the plane limit keeps the level low for long.
    add(unit(0.f, 0.1f, 1.f), {kTanHalf60, 0.5f, 0.99f, 1.5f}, {4.f, 4.f, 11.8f, 1.5f}, {0.9f, 0.8f, 0.05f},
        {26.f, 0.15f, 9.4f, 0.f});
    // Starting inside the slab, a 16-cone aperture, beta 1.
    add(unit(-0.4f, 0.6f, 0.3f), {0.46630766f, 1.f, 0.99f, 1.5f}, {16.f, 16.f, 15.f, 1.5f}, {-0.4f, 0.6f, 0.3f},
        {12.f, 0.33f, 0.6f, 0.f});
    // Compositing: a transparent sample with radiance (the k branch), and a partial result
    // that the sample pushes past max alpha (the close renormalizes).
    in[1].incoming = glm::vec4(0.03f, 0.02f, 0.01f, 0.f);
    in[2].partial = glm::vec4(0.4f, 0.3f, 0.2f, 0.988f);
    in[2].step = glm::vec4(2.f, 4.f, 17.f, 0.f);
    in[6].step = glm::vec4(0.37f, 1.f, 0.9f, 0.f);
    return in;
}

std::vector<ConeCheckOutput> evaluateOnGpu(const std::vector<ConeCheckInput>& in) {
    GlContext::shared();
    const GLuint program = cachedProgram(coneMarchCheckProgramKey());
    GlBuffer inputs = createBuffer(in.size() * sizeof(ConeCheckInput), in.data());
    GlBuffer outputs = createBuffer(in.size() * sizeof(ConeCheckOutput));
    glUseProgram(program);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_CHECK_BINDING_INPUTS, inputs.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_CHECK_BINDING_OUTPUTS, outputs.id());
    glDispatchCompute(GLuint((in.size() + gpu::CONE_CHECK_GROUP - 1) / gpu::CONE_CHECK_GROUP), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<ConeCheckOutput> out(in.size());
    glGetNamedBufferSubData(outputs.id(), 0, GLsizeiptr(out.size() * sizeof(ConeCheckOutput)), out.data());
    GlContext::shared().checkErrors("cone_march_check");
    return out;
}

const char* kOutputNames[] = {"frame t", "frame b", "frame n", "lod", "composite", "closed", "march"};

TEST(ConeMarchShared, CpuAndShaderAgree) {
    const std::vector<ConeCheckInput> in = checkInputs();
    std::vector<ConeCheckOutput> cpu;
    gpu::ConeCheckVolume volume;
    for (const ConeCheckInput& c : in) cpu.push_back(gpu::cone_checkEvaluate(volume, c));
    const std::vector<ConeCheckOutput> gpuOut = evaluateOnGpu(in);

    float worst = 0.f;
    for (size_t i = 0; i < in.size(); ++i) {
        const glm::vec4* a = &cpu[i].frameT;
        const glm::vec4* b = &gpuOut[i].frameT;
        for (int v = 0; v < 7; ++v)
            for (int k = 0; k < 4; ++k) {
                const float x = a[v][k], y = b[v][k];
                const float err = std::abs(x - y) / std::max(1.f, std::abs(x));
                worst = std::max(worst, err);
                EXPECT_LE(err, 1e-6f) << "input " << i << ", " << kOutputNames[v] << "[" << k << "]: cpu " << x
                                      << ", shader " << y;
            }
    }
    std::printf("[cone_march_shared] %zu inputs, 28 outputs each: largest CPU-shader difference %.2e\n", in.size(),
                worst);

    // The inputs do reach the branches they are there for (on the CPU; the shader agrees).
    EXPECT_EQ(cpu[3].march.w, 1.f) << "the saturating cone closes";
    EXPECT_EQ(cpu[6].lod.x, 0.f) << "the plane limit holds the grazing cone at level 0";
    EXPECT_LT(cpu[1].march.w, 0.99f) << "the GI cone leaves with sky left";
    EXPECT_EQ(cpu[2].closed.w, 1.f) << "the close renormalizes";
    EXPECT_LT(cpu[0].closed.w, 0.99f) << "an unsaturated result stays open";
    EXPECT_EQ(cpu[4].lod.w, 1.f) << "leaving the box along +x";
    EXPECT_EQ(cpu[4].lod.z, 0.f) << "inside the box";
    EXPECT_GT(cpu[4].lod.y, cpu[4].lod.x) << "the band x > 24 refuses the footprint's level";
    for (const ConeCheckOutput& o : cpu) EXPECT_GT(o.march.w, 0.f) << "every cone meets the slab";
}

}  // namespace
}  // namespace vct
