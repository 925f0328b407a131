#include "gl/program_limits.h"

#include "core/errors.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace vct {

namespace {

bool isImageType(GLenum t) {
    static const std::set<GLenum> types = {
        GL_IMAGE_1D, GL_IMAGE_2D, GL_IMAGE_3D, GL_IMAGE_2D_RECT, GL_IMAGE_CUBE, GL_IMAGE_BUFFER,
        GL_IMAGE_1D_ARRAY, GL_IMAGE_2D_ARRAY, GL_IMAGE_CUBE_MAP_ARRAY, GL_IMAGE_2D_MULTISAMPLE,
        GL_IMAGE_2D_MULTISAMPLE_ARRAY, GL_INT_IMAGE_1D, GL_INT_IMAGE_2D, GL_INT_IMAGE_3D, GL_INT_IMAGE_2D_RECT,
        GL_INT_IMAGE_CUBE, GL_INT_IMAGE_BUFFER, GL_INT_IMAGE_1D_ARRAY, GL_INT_IMAGE_2D_ARRAY,
        GL_INT_IMAGE_CUBE_MAP_ARRAY, GL_INT_IMAGE_2D_MULTISAMPLE, GL_INT_IMAGE_2D_MULTISAMPLE_ARRAY,
        GL_UNSIGNED_INT_IMAGE_1D, GL_UNSIGNED_INT_IMAGE_2D, GL_UNSIGNED_INT_IMAGE_3D,
        GL_UNSIGNED_INT_IMAGE_2D_RECT, GL_UNSIGNED_INT_IMAGE_CUBE, GL_UNSIGNED_INT_IMAGE_BUFFER,
        GL_UNSIGNED_INT_IMAGE_1D_ARRAY, GL_UNSIGNED_INT_IMAGE_2D_ARRAY, GL_UNSIGNED_INT_IMAGE_CUBE_MAP_ARRAY,
        GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE, GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY};
    return types.count(t) != 0;
}

bool isSamplerType(GLenum t) {
    static const std::set<GLenum> types = {
        GL_SAMPLER_1D, GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE, GL_SAMPLER_1D_SHADOW,
        GL_SAMPLER_2D_SHADOW, GL_SAMPLER_1D_ARRAY, GL_SAMPLER_2D_ARRAY, GL_SAMPLER_1D_ARRAY_SHADOW,
        GL_SAMPLER_2D_ARRAY_SHADOW, GL_SAMPLER_2D_MULTISAMPLE, GL_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_SAMPLER_CUBE_SHADOW, GL_SAMPLER_BUFFER, GL_SAMPLER_2D_RECT, GL_SAMPLER_2D_RECT_SHADOW,
        GL_SAMPLER_CUBE_MAP_ARRAY, GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW, GL_INT_SAMPLER_1D, GL_INT_SAMPLER_2D,
        GL_INT_SAMPLER_3D, GL_INT_SAMPLER_CUBE, GL_INT_SAMPLER_1D_ARRAY, GL_INT_SAMPLER_2D_ARRAY,
        GL_INT_SAMPLER_2D_MULTISAMPLE, GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_INT_SAMPLER_BUFFER,
        GL_INT_SAMPLER_2D_RECT, GL_INT_SAMPLER_CUBE_MAP_ARRAY, GL_UNSIGNED_INT_SAMPLER_1D,
        GL_UNSIGNED_INT_SAMPLER_2D, GL_UNSIGNED_INT_SAMPLER_3D, GL_UNSIGNED_INT_SAMPLER_CUBE,
        GL_UNSIGNED_INT_SAMPLER_1D_ARRAY, GL_UNSIGNED_INT_SAMPLER_2D_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE, GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_BUFFER, GL_UNSIGNED_INT_SAMPLER_2D_RECT, GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY};
    return types.count(t) != 0;
}

struct StageProp {
    GLenum stage;
    GLenum referencedBy;
};
const StageProp kStages[] = {{GL_VERTEX_SHADER, GL_REFERENCED_BY_VERTEX_SHADER},
                             {GL_GEOMETRY_SHADER, GL_REFERENCED_BY_GEOMETRY_SHADER},
                             {GL_FRAGMENT_SHADER, GL_REFERENCED_BY_FRAGMENT_SHADER},
                             {GL_COMPUTE_SHADER, GL_REFERENCED_BY_COMPUTE_SHADER}};
constexpr int kStageCount = 4;

const char* stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_FRAGMENT_SHADER: return "fragment";
    default: return "compute";
    }
}

// Reads the stage references of resource `index` of `iface`.
void referencedStages(GLuint program, GLenum iface, GLuint index, bool out[kStageCount]) {
    GLenum props[kStageCount];
    for (int s = 0; s < kStageCount; ++s) props[s] = kStages[s].referencedBy;
    GLint values[kStageCount] = {};
    glGetProgramResourceiv(program, iface, index, kStageCount, props, kStageCount, nullptr, values);
    for (int s = 0; s < kStageCount; ++s) out[s] = values[s] != 0;
}

}  // namespace

ProgramResources inspectProgram(GLuint program) {
    ProgramResources r;
    StageResources perStage[kStageCount];
    bool stagePresent[kStageCount] = {};
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) throw InternalError("inspectProgram", "program is not linked");

    GLint uniforms = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
    for (GLint i = 0; i < uniforms; ++i) {
        const GLenum props[] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE, GL_BLOCK_INDEX};
        GLint v[4] = {};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), 4, props, 4, nullptr, v);
        const GLenum type = GLenum(v[0]);
        const bool image = isImageType(type), sampler = isSamplerType(type);
        if (!(image || sampler) || v[3] != -1) continue;
        const int count = std::max(1, v[2]);
        bool stages[kStageCount];
        referencedStages(program, GL_UNIFORM, GLuint(i), stages);
        for (int s = 0; s < kStageCount; ++s) {
            if (!stages[s]) continue;
            stagePresent[s] = true;
            (image ? perStage[s].images : perStage[s].samplers) += count;
        }
        (image ? r.combined.images : r.combined.samplers) += count;
        for (int e = 0; e < count; ++e) {
            GLint unit = 0;
            glGetUniformiv(program, v[1] + e, &unit);
            int& highest = image ? r.maxImageUnit : r.maxTextureUnit;
            highest = std::max(highest, int(unit));
        }
    }
    for (GLenum iface : {GL_SHADER_STORAGE_BLOCK, GL_UNIFORM_BLOCK}) {
        GLint blocks = 0;
        glGetProgramInterfaceiv(program, iface, GL_ACTIVE_RESOURCES, &blocks);
        for (GLint i = 0; i < blocks; ++i) {
            const GLenum props[] = {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE};
            GLint v[2] = {};
            glGetProgramResourceiv(program, iface, GLuint(i), 2, props, 2, nullptr, v);
            bool stages[kStageCount];
            referencedStages(program, iface, GLuint(i), stages);
            const bool storage = iface == GL_SHADER_STORAGE_BLOCK;
            for (int s = 0; s < kStageCount; ++s) {
                if (!stages[s]) continue;
                stagePresent[s] = true;
                (storage ? perStage[s].storageBlocks : perStage[s].uniformBlocks) += 1;
            }
            (storage ? r.combined.storageBlocks : r.combined.uniformBlocks) += 1;
            if (storage) r.maxStorageBinding = std::max(r.maxStorageBinding, int(v[0]));
            else {
                r.maxUniformBinding = std::max(r.maxUniformBinding, int(v[0]));
                r.largestUniformBlockBytes = std::max(r.largestUniformBlockBytes, int64_t(v[1]));
            }
        }
    }
    for (int s = 0; s < kStageCount; ++s)
        if (stagePresent[s]) r.stages.push_back({kStages[s].stage, perStage[s]});
    return r;
}

GlLimits gl45MinimumLimits() { return GlLimits{}; }

GlLimits deviceLimits() {
    auto get = [](GLenum e) {
        GLint v = 0;
        glGetIntegerv(e, &v);
        return int(v);
    };
    GlLimits l;
    l.computeImages = get(GL_MAX_COMPUTE_IMAGE_UNIFORMS);
    l.computeStorageBlocks = get(GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS);
    l.computeTextureUnits = get(GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS);
    l.computeUniformBlocks = get(GL_MAX_COMPUTE_UNIFORM_BLOCKS);
    l.fragmentImages = get(GL_MAX_FRAGMENT_IMAGE_UNIFORMS);
    l.fragmentStorageBlocks = get(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS);
    l.fragmentTextureUnits = get(GL_MAX_TEXTURE_IMAGE_UNITS);
    l.fragmentUniformBlocks = get(GL_MAX_FRAGMENT_UNIFORM_BLOCKS);
    l.vertexImages = get(GL_MAX_VERTEX_IMAGE_UNIFORMS);
    l.vertexStorageBlocks = get(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS);
    l.vertexTextureUnits = get(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS);
    l.vertexUniformBlocks = get(GL_MAX_VERTEX_UNIFORM_BLOCKS);
    l.geometryImages = get(GL_MAX_GEOMETRY_IMAGE_UNIFORMS);
    l.geometryStorageBlocks = get(GL_MAX_GEOMETRY_SHADER_STORAGE_BLOCKS);
    l.geometryTextureUnits = get(GL_MAX_GEOMETRY_TEXTURE_IMAGE_UNITS);
    l.geometryUniformBlocks = get(GL_MAX_GEOMETRY_UNIFORM_BLOCKS);
    l.combinedImages = get(GL_MAX_COMBINED_IMAGE_UNIFORMS);
    l.combinedStorageBlocks = get(GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS);
    l.imageUnits = get(GL_MAX_IMAGE_UNITS);
    l.storageBindings = get(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS);
    l.textureUnits = get(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS);
    l.uniformBindings = get(GL_MAX_UNIFORM_BUFFER_BINDINGS);
    l.uniformBlockBytes = get(GL_MAX_UNIFORM_BLOCK_SIZE);
    l.max3DTextureSize = get(GL_MAX_3D_TEXTURE_SIZE);
    GLint64 ssbo = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &ssbo);
    l.storageBlockBytes = int64_t(ssbo);
    l.maxTextureSize = get(GL_MAX_TEXTURE_SIZE);
    l.arrayTextureLayers = get(GL_MAX_ARRAY_TEXTURE_LAYERS);
    return l;
}

std::vector<std::string> limitViolations(const ProgramResources& r, const GlLimits& l) {
    std::vector<std::string> out;
    auto check = [&](int64_t value, int64_t allowed, const std::string& limit, const std::string& what) {
        if (value > allowed)
            out.push_back(limit + " is " + std::to_string(allowed) + ", the program uses " + std::to_string(value) +
                          " (" + what + ")");
    };
    for (const auto& [stage, s] : r.stages) {
        const std::string st = stageName(stage);
        int images = 0, storage = 0, textures = 0, uniformBlocks = 0;
        std::string prefix;
        switch (stage) {
        case GL_COMPUTE_SHADER:
            images = l.computeImages, storage = l.computeStorageBlocks, textures = l.computeTextureUnits,
            uniformBlocks = l.computeUniformBlocks, prefix = "GL_MAX_COMPUTE_";
            break;
        case GL_FRAGMENT_SHADER:
            images = l.fragmentImages, storage = l.fragmentStorageBlocks, textures = l.fragmentTextureUnits,
            uniformBlocks = l.fragmentUniformBlocks, prefix = "GL_MAX_FRAGMENT_";
            break;
        case GL_VERTEX_SHADER:
            images = l.vertexImages, storage = l.vertexStorageBlocks, textures = l.vertexTextureUnits,
            uniformBlocks = l.vertexUniformBlocks, prefix = "GL_MAX_VERTEX_";
            break;
        default:
            images = l.geometryImages, storage = l.geometryStorageBlocks, textures = l.geometryTextureUnits,
            uniformBlocks = l.geometryUniformBlocks, prefix = "GL_MAX_GEOMETRY_";
            break;
        }
        check(s.images, images, prefix + "IMAGE_UNIFORMS", st + " stage image uniforms");
        check(s.storageBlocks, storage, prefix + "SHADER_STORAGE_BLOCKS", st + " stage storage blocks");
        check(s.samplers, textures,
              stage == GL_FRAGMENT_SHADER ? "GL_MAX_TEXTURE_IMAGE_UNITS" : prefix + "TEXTURE_IMAGE_UNITS",
              st + " stage samplers");
        check(s.uniformBlocks, uniformBlocks, prefix + "UNIFORM_BLOCKS", st + " stage uniform blocks");
    }
    check(r.combined.images, l.combinedImages, "GL_MAX_COMBINED_IMAGE_UNIFORMS", "image uniforms of all stages");
    check(r.combined.storageBlocks, l.combinedStorageBlocks, "GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS",
          "storage blocks of all stages");
    check(r.maxImageUnit + 1, l.imageUnits, "GL_MAX_IMAGE_UNITS", "highest image unit + 1");
    check(r.maxStorageBinding + 1, l.storageBindings, "GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS",
          "highest storage binding + 1");
    check(r.maxTextureUnit + 1, l.textureUnits, "texture units", "highest texture unit + 1");
    check(r.maxUniformBinding + 1, l.uniformBindings, "GL_MAX_UNIFORM_BUFFER_BINDINGS",
          "highest uniform block binding + 1");
    check(r.largestUniformBlockBytes, l.uniformBlockBytes, "GL_MAX_UNIFORM_BLOCK_SIZE",
          "bytes of the largest uniform block");
    return out;
}

void checkStorageBufferSize(size_t bytes, const std::string& what) {
    static const int64_t deviceBytes = deviceLimits().storageBlockBytes;
    if (int64_t(bytes) > deviceBytes)
        throw std::runtime_error(what + " needs a " + std::to_string(bytes >> 20) +
                                 " MiB shader storage buffer; this GL allows " + std::to_string(deviceBytes >> 20) +
                                 " MiB (GL_MAX_SHADER_STORAGE_BLOCK_SIZE)");
}

std::vector<std::string> describeDeviceLimits() {
    const GlLimits d = deviceLimits(), m = gl45MinimumLimits();
    auto line = [](const std::string& name, int64_t value, int64_t minimum) {
        return name + ": " + std::to_string(value) + " (GL 4.5 guarantees " + std::to_string(minimum) + ")";
    };
    std::vector<std::string> out = {
        line("max compute image uniforms", d.computeImages, m.computeImages),
        line("max image units", d.imageUnits, m.imageUnits),
        line("max compute storage blocks", d.computeStorageBlocks, m.computeStorageBlocks),
        line("max compute texture units", d.computeTextureUnits, m.computeTextureUnits),
        line("max 3D texture size", d.max3DTextureSize, m.max3DTextureSize),
        line("max storage block bytes", d.storageBlockBytes, m.storageBlockBytes),
        line("max uniform block bytes", d.uniformBlockBytes, m.uniformBlockBytes),
    };
    constexpr GLenum kNvxTotalKb = 0x9048, kNvxAvailableKb = 0x9049, kAtiTextureFree = 0x87FC;
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint total = 0, available = 0;
        glGetIntegerv(kNvxTotalKb, &total);
        glGetIntegerv(kNvxAvailableKb, &available);
        out.push_back("device memory: " + std::to_string(total / 1024) + " MiB, " + std::to_string(available / 1024) +
                      " MiB available (NVX_gpu_memory_info)");
    } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint free[4] = {};
        glGetIntegerv(kAtiTextureFree, free);
        out.push_back("device memory: " + std::to_string(free[0] / 1024) + " MiB free for textures (ATI_meminfo)");
    } else {
        out.push_back("device memory: not reported by the driver");
    }
    return out;
}

}  // namespace vct
