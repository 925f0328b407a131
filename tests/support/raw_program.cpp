#include "support/raw_program.h"

namespace vcttest {

RawProgram linkCompute(const std::string& source) {
    vct::GlShader cs(glCreateShader(GL_COMPUTE_SHADER));
    const char* src = source.c_str();
    glShaderSource(cs.id(), 1, &src, nullptr);
    glCompileShader(cs.id());
    GLint compiled = 0, linked = 0;
    glGetShaderiv(cs.id(), GL_COMPILE_STATUS, &compiled);
    RawProgram p{vct::GlProgram(glCreateProgram()), false};
    glAttachShader(p.program.id(), cs.id());
    glLinkProgram(p.program.id());
    glGetProgramiv(p.program.id(), GL_LINK_STATUS, &linked);
    p.linked = compiled && linked;
    return p;
}

}  // namespace vcttest
