#include "gl/program.h"

#include "core/errors.h"
#include "gl/embedded_shaders.h"

#include <set>
#include <sstream>
#include <stdexcept>

namespace vct {

namespace {

const std::string& lookup(const std::string& name) {
    const auto& table = embeddedShaders();
    auto it = table.find(name);
    if (it == table.end()) throw InternalError("shader lookup", "no embedded shader named '" + name + "'");
    return it->second;
}

void expandInto(const std::string& name, std::ostringstream& out, std::set<std::string>& seen) {
    if (!seen.insert(name).second) return;  // every include acts as if guarded by #pragma once
    std::istringstream in(lookup(name));
    std::string line;
    while (std::getline(in, line)) {
        size_t p = line.find_first_not_of(" \t");
        // Only quoted includes are ours; <...> ones sit in `#ifdef __cplusplus` blocks.
        if (p != std::string::npos && line.compare(p, 8, "#include") == 0 &&
            line.find('<', p) == std::string::npos) {
            size_t a = line.find('"', p), b = line.find('"', a + 1);
            if (a == std::string::npos || b == std::string::npos)
                throw InternalError("shader lookup", "bad #include in shader '" + name + "': " + line);
            expandInto(line.substr(a + 1, b - a - 1), out, seen);
            continue;
        }
        if (p != std::string::npos && line.compare(p, 12, "#pragma once") == 0) continue;
        out << line << '\n';
    }
}

GlShader compile(GLenum stage, const std::string& name, const ShaderDefines& defines) {
    std::string src = expandShaderSource(name, defines);
    GLuint id = glCreateShader(stage);
    GlShader shader(id);
    const char* ptr = src.c_str();
    glShaderSource(id, 1, &ptr, nullptr);
    glCompileShader(id);
    GLint ok = 0;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(id, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
        glGetShaderInfoLog(id, len, nullptr, log.data());
        throw std::runtime_error("shader '" + name + "' failed to compile:\n" + log);
    }
    return shader;
}

GlProgram link(const std::vector<GLuint>& shaders, const std::string& name) {
    GlProgram program(glCreateProgram());
    for (GLuint s : shaders) glAttachShader(program.id(), s);
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
        glGetProgramInfoLog(program.id(), len, nullptr, log.data());
        throw std::runtime_error("program '" + name + "' failed to link:\n" + log);
    }
    for (GLuint s : shaders) glDetachShader(program.id(), s);
    return program;
}

}  // namespace

std::string expandShaderSource(const std::string& name, const ShaderDefines& defines) {
    std::ostringstream out;
    out << "#version 450 core\n";
    for (const auto& [k, v] : defines) out << "#define " << k << ' ' << v << '\n';
    out << "#define VCT_GLSL 1\n";
    std::set<std::string> seen;
    expandInto(name, out, seen);
    return out.str();
}

GlProgram buildComputeProgram(const std::string& name, const ShaderDefines& defines) {
    GlShader cs = compile(GL_COMPUTE_SHADER, name, defines);
    return link({cs.id()}, name);
}

GlProgram buildGraphicsProgram(const std::string& vertex, const std::string& fragment,
                               const ShaderDefines& defines, const std::string& geometry) {
    GlShader vs = compile(GL_VERTEX_SHADER, vertex, defines);
    GlShader fs = compile(GL_FRAGMENT_SHADER, fragment, defines);
    std::vector<GLuint> ids{vs.id(), fs.id()};
    GlShader gs;
    if (!geometry.empty()) { gs = compile(GL_GEOMETRY_SHADER, geometry, defines); ids.push_back(gs.id()); }
    return link(ids, vertex + "+" + fragment);
}

}  // namespace vct
