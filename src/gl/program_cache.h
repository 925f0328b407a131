// The one cache of GL programs: every pass asks it for its program by key (shader files and
// defines), and each key is compiled and linked once per GL context, so once per session
// however many passes and renders use it. Every program it builds is checked against the
// device's resource limits (gl/program_limits.h) before first use: a shader that would
// exceed them is refused with a message naming the shader, the limit and the value.
//
// Keys are values: a pass builds its key with a function of its own, and the same function
// lists every variant it can build (see the renderer's program list), so a test can link
// and inspect every program the renderer can use without rendering.
#pragma once

#include "gl/program.h"

#include <map>
#include <string>
#include <vector>

namespace vct {

struct ProgramKey {
    std::string compute;   // compute shader, or empty for a graphics program
    std::string vertex;    // graphics: vertex and fragment shaders
    std::string fragment;
    ShaderDefines defines;  // injected after #version, in this order

    // "voxelize/voxelize.glsl|BIG_PASS=1" or "raster/a.glsl+raster/b.glsl|...": the cache key.
    std::string id() const;
    std::string name() const;  // the shader file(s), for messages
    bool operator<(const ProgramKey& o) const { return id() < o.id(); }
    bool operator==(const ProgramKey& o) const { return id() == o.id(); }
};

ProgramKey computeProgramKey(const std::string& shader, ShaderDefines defines = {});
ProgramKey graphicsProgramKey(const std::string& vertex, const std::string& fragment, ShaderDefines defines = {});

// The program of `key`, compiled, linked and checked against the device's limits on first
// use; later calls return the same name. Throws std::runtime_error on a compile or link
// error or a limit the program exceeds. Needs the current GL context.
GLuint cachedProgram(const ProgramKey& key);

// How many times each key was compiled in this process (1 once built: tests check that no
// pass rebuilds its programs).
const std::map<std::string, int>& programCompileCounts();

// Where VCT_PROGRAM_LOG names a file, every compiled key's id() is appended to it, one per
// line: the test suite collects the programs its tests built and checks each is listed.
constexpr const char* kProgramLogVariable = "VCT_PROGRAM_LOG";

}  // namespace vct
