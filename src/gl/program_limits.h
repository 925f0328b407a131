// What a linked program uses of the GL's per-stage resources (image uniforms, shader storage
// blocks, samplers, uniform blocks), read by program introspection, and the limits to hold
// it to: OpenGL 4.5's guaranteed minimums, which every conformant driver meets (NVIDIA's
// exposes exactly 8 image uniforms per stage), or the current device's own.
//
// llvmpipe allows far more than the minimums, so a shader can pass every test here and fail
// to link on a user's GPU; the test suite holds every program to the minimums, and the
// program cache refuses, before first use, a program the current device cannot run.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

struct StageResources {
    int images = 0;         // image uniforms (arrays count each element)
    int storageBlocks = 0;  // shader storage blocks
    int samplers = 0;       // sampler uniforms = texture units used
    int uniformBlocks = 0;
};

struct ProgramResources {
    std::vector<std::pair<GLenum, StageResources>> stages;  // GL_COMPUTE_SHADER, GL_VERTEX_SHADER, ...
    StageResources combined;  // each resource counted once per program
    int maxImageUnit = -1;    // highest image unit / binding point / texture unit any resource uses
    int maxStorageBinding = -1;
    int maxTextureUnit = -1;
    int maxUniformBinding = -1;
    int64_t largestUniformBlockBytes = 0;
};

// Reads the active resources of a linked program (glGetProgramInterfaceiv / glGetProgramResourceiv).
ProgramResources inspectProgram(GLuint program);

struct GlLimits {
    // Per stage (compute, fragment; vertex and geometry where noted).
    int computeImages = 8, computeStorageBlocks = 8, computeTextureUnits = 16, computeUniformBlocks = 12;
    int fragmentImages = 8, fragmentStorageBlocks = 8, fragmentTextureUnits = 16, fragmentUniformBlocks = 12;
    int vertexImages = 0, vertexStorageBlocks = 0, vertexTextureUnits = 16, vertexUniformBlocks = 12;
    int geometryImages = 0, geometryStorageBlocks = 0, geometryTextureUnits = 16, geometryUniformBlocks = 12;
    // Per program and binding points.
    int combinedImages = 8, combinedStorageBlocks = 8;
    int imageUnits = 8;             // image bindings must be below this
    int storageBindings = 8;        // shader storage binding points
    int textureUnits = 32;          // texture unit numbers must be below this (the spec guarantees 80
                                    // combined; the project keeps to 32 so any stage mix fits)
    int uniformBindings = 72;
    int64_t uniformBlockBytes = 16384;
    // Resources.
    int max3DTextureSize = 2048;
    int64_t storageBlockBytes = int64_t(1) << 27;  // 128 MiB per shader storage binding
    int maxTextureSize = 16384;
    int arrayTextureLayers = 2048;
};

// OpenGL 4.5 core's guaranteed minimums (the defaults above).
GlLimits gl45MinimumLimits();
// The current context's limits (glGetIntegerv); needs a current context.
GlLimits deviceLimits();

// One line per limit `resources` exceeds: "<limit> is <allowed>, the program uses <value> (<what>)".
std::vector<std::string> limitViolations(const ProgramResources& resources, const GlLimits& limits);

// Throws std::runtime_error naming `what`, the limit and the size if `bytes` exceeds the
// device's shader storage block size (and the guaranteed 128 MiB).
void checkStorageBufferSize(size_t bytes, const std::string& what);

// Lines for `vct info`: the limits above as the device reports them, and its memory where
// the driver says (NVX_gpu_memory_info, ATI_meminfo); needs a current context.
std::vector<std::string> describeDeviceLimits();

}  // namespace vct
