// Every program the renderer can build stays within OpenGL 4.5's guaranteed minimums (8
// image uniforms and 8 storage blocks per stage, 16 texture units, 8 image units, ...), so a
// shader that links on llvmpipe's generous limits links on every conformant GPU. The
// programs come from the renderer's list of variants; a separate check at the end of the
// suite (tests/program_log) fails if any test compiled a program that list does not name.
#include "gl/context.h"
#include "gl/program_cache.h"
#include "gl/program_limits.h"
#include "render/program_list.h"
#include "support/raw_program.h"

#include <gtest/gtest.h>

#include <set>

using namespace vct;
using vcttest::linkCompute;
using vcttest::RawProgram;

namespace {

// `count` r32ui image uniforms at units 0..count-1, each written.
std::string imagesShader(int count) {
    std::string s = "#version 450 core\nlayout(local_size_x = 1) in;\n";
    for (int i = 0; i < count; ++i)
        s += "layout(r32ui, binding = " + std::to_string(i) + ") uniform uimage3D img" + std::to_string(i) + ";\n";
    s += "void main() {\n";
    for (int i = 0; i < count; ++i) s += "  imageAtomicAdd(img" + std::to_string(i) + ", ivec3(0), 1u);\n";
    return s + "}\n";
}

}  // namespace

TEST(ProgramLimits, TheCheckerCountsImageUniformsAndUnits) {
    GlContext& gl = GlContext::shared();
    // Nine images: over GL_MAX_COMPUTE_IMAGE_UNIFORMS and GL_MAX_IMAGE_UNITS (8 each).
    GLint imageUniforms = 0;
    glGetIntegerv(GL_MAX_COMPUTE_IMAGE_UNIFORMS, &imageUniforms);
    RawProgram nine = linkCompute(imagesShader(9));
    if (imageUniforms < 9) {
        // A GL that allows 8 (NVIDIA's) refuses the program itself, which is what the checker
        // finds ahead of time on llvmpipe's generous limits; the refusal's compile log may
        // arrive as a debug message, which is expected here.
        EXPECT_FALSE(nine.linked) << "a GL allowing " << imageUniforms << " image uniforms linked nine";
        try {
            gl.checkErrors("nine image uniforms, refused");
        } catch (const std::runtime_error&) {
        }
    } else {
        ASSERT_TRUE(nine.linked);
        const ProgramResources r = inspectProgram(nine.program.id());
        ASSERT_EQ(r.stages.size(), 1u);
        EXPECT_EQ(r.stages[0].first, GLenum(GL_COMPUTE_SHADER));
        EXPECT_EQ(r.stages[0].second.images, 9);
        EXPECT_EQ(r.maxImageUnit, 8);
        const std::vector<std::string> over = limitViolations(r, gl45MinimumLimits());
        ASSERT_EQ(over.size(), 3u);  // per stage, combined, highest unit
        EXPECT_NE(over[0].find("GL_MAX_COMPUTE_IMAGE_UNIFORMS is 8, the program uses 9"), std::string::npos)
            << over[0];
    }
    // Eight are within every limit.
    RawProgram eight = linkCompute(imagesShader(8));
    ASSERT_TRUE(eight.linked);
    const ProgramResources r8 = inspectProgram(eight.program.id());
    EXPECT_EQ(r8.stages[0].second.images, 8);
    EXPECT_TRUE(limitViolations(r8, gl45MinimumLimits()).empty());
    gl.checkErrors("program limits checker");
}

TEST(ProgramLimits, EveryRendererProgramIsWithinTheGl45Minimums) {
    GlContext& gl = GlContext::shared();
    const std::vector<ProgramKey> keys = rendererProgramVariants();
    ASSERT_GT(keys.size(), 40u);
    std::set<std::string> ids;
    for (const ProgramKey& key : keys) {
        EXPECT_TRUE(ids.insert(key.id()).second) << "listed twice: " << key.id();
        const GLuint program = cachedProgram(key);  // also checked against this device's limits
        const ProgramResources r = inspectProgram(program);
        for (const std::string& v : limitViolations(r, gl45MinimumLimits())) ADD_FAILURE() << key.id() << ": " << v;
        gl.checkErrors(key.id());
    }
}

TEST(ProgramLimits, ADeviceBelowAProgramsNeedsIsNamedWithTheLimitAndValue) {
    GlContext::shared();
    // The geometry pass of the voxelizer binds 7 accumulator images: a device with 6 refuses it.
    const ProgramKey key = computeProgramKey("voxelize/voxelize.glsl");
    const ProgramResources r = inspectProgram(cachedProgram(key));
    EXPECT_EQ(r.stages.at(0).second.images, 7);
    GlLimits small = gl45MinimumLimits();
    small.computeImages = 6;
    const std::vector<std::string> over = limitViolations(r, small);
    ASSERT_EQ(over.size(), 1u);
    EXPECT_EQ(over[0], "GL_MAX_COMPUTE_IMAGE_UNIFORMS is 6, the program uses 7 (compute stage image uniforms)");
}

TEST(ProgramLimits, EachProgramIsCompiledOnceHoweverOftenItIsUsed) {
    GlContext::shared();
    const ProgramKey key = computeProgramKey("ao/gtao.glsl");
    const GLuint first = cachedProgram(key);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(cachedProgram(key), first);
    EXPECT_EQ(programCompileCounts().at(key.id()), 1);
}
