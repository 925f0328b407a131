#include "cone/cone_gpu.h"

#include "cone/cone_budget.h"
#include "cone/cone_set.h"
#include "core/errors.h"
#include "gl/readback.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <vector>

namespace vct::conedetail {

void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid) {
    u.voxelFromWorld = grid.voxelFromWorld;
    u.gridResolution = glm::vec4(glm::vec3(grid.resolution), float(grid.levels));
}

GlBuffer bindConeUniforms(const gpu::ConeUniforms& u) {
    GlBuffer ubo = createBuffer(sizeof(u), &u);  // dynamic: a reduced-resolution pass sets its stage
    glBindBufferBase(GL_UNIFORM_BUFFER, gpu::CONE_UBO_BINDING, ubo.id());
    return ubo;
}

namespace {

template <size_t N>
bool allPresent(const std::array<GlTexture, N>& textures) {
    return std::all_of(textures.begin(), textures.end(), [](const GlTexture& t) { return bool(t); });
}

// The directional levels a pass uses: none when vct.aniso=0 or the grid has none; an AO
// pass reads an AO grid's packed opacity, a GI pass (or an AO pass sharing a lit grid) the
// six RGBA textures.
ConeDirectional directionalLevels(bool gi, const VoxelGrid& grid, const ConeSettings& s) {
    if (!s.anisotropic || !grid.anisotropic || grid.levels < 2) return ConeDirectional::None;
    if (allPresent(grid.anisoRadiance)) return ConeDirectional::Six;
    if (!gi && grid.anisoOpacity) return ConeDirectional::Packed;
    return ConeDirectional::None;
}

}  // namespace

gpu::ConeUniforms coneUniforms(bool gi, const VoxelGrid& grid, float maxDistWorld, float sky,
                               const ConeSettings& settings) {
    gpu::ConeUniforms u{};
    setGridUniforms(u, grid);
    const int maxRes = std::max(grid.resolution.x, std::max(grid.resolution.y, grid.resolution.z));
    const ConeLanes lanes = coneMarchLanes(settings, maxRes);
    const float maxDist = maxDistWorld / grid.voxelSize;
    u.march = glm::vec4(coneFootprintTangent(settings, lanes.apertureDeg), settings.stepFactor, settings.offsetVoxels,
                        settings.maxAlpha);
    const float falloff = (!gi && settings.aoMapping == ConeAoMapping::Falloff && maxDist > 0.f)
                              ? gpu::CONE_FALLOFF_LAMBDA_R / maxDist
                              : 0.f;
    u.limits = glm::vec4(maxDist, sky, falloff, settings.planeLimit ? gpu::CONE_PLANE_LIMIT_RATIO : 0.f);
    // The first slice's cones (coneSlices); a pass of several loads the others (loadConeSlice).
    const size_t first = std::min(lanes.cones.size(), size_t(gpu::CONE_BLOCK_CONES));
    u.config = glm::ivec4(int(first), gi ? gpu::CONE_AO_LINEAR : int(settings.aoMapping), 0, 0);
    for (size_t i = 0; i < first; ++i) u.cones[i] = lanes.cones[i];
    u.lanes = glm::ivec4(lanes.lanesPerCone, 0,
                         (settings.aim ? gpu::CONE_LANES_AIM : 0) |
                             (settings.belowPlane == ConeBelowPlane::Mirror ? gpu::CONE_LANES_MIRROR : 0),
                         settings.endTaper ? 1 : 0);
    for (size_t i = 0; i < lanes.axes.size(); ++i) u.coneAxes[i] = lanes.axes[i];
    u.trace = glm::ivec4(settings.traceScale, gpu::CONE_STAGE_TRACE, 0, 0);
    u.camera.w = settings.sharpen;
    return u;
}

ConeSlices coneSlices(const gpu::ConeUniforms& u, const ConeSettings& settings, int loopsPerStep) {
    const glm::vec3 res = glm::vec3(u.gridResolution);
    ConeSlices slices;
    slices.cones = coneMarchLanes(settings, int(std::max(res.x, std::max(res.y, res.z)))).cones;
    // At most CONE_BLOCK_CONES: the first slice is what coneUniforms loaded.
    // With lane caps a march carries on through the zone past maxDist, after one shortened step.
    const float marched = u.limits.x + (u.caps.x > 0.f ? gpu::cone_capZone(u.limits.x, u.caps.x) + u.march.y : 0.f);
    slices.perDispatch = conesPerDispatch(marched, u.march.y, loopsPerStep, settings.dispatchCones);
    return slices;
}

void loadConeSlice(GLuint ubo, const ConeSlices& slices, int i) {
    if (slices.count() <= 1) return;
    const size_t first = size_t(i) * size_t(slices.perDispatch);
    const size_t n = std::min(size_t(slices.perDispatch), slices.cones.size() - first);
    glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, cones)), GLsizeiptr(n * sizeof(glm::vec4)),
                         &slices.cones[first]);
    const GLint count = GLint(n);
    glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, config)), sizeof(count), &count);
    const GLint firstLane = GLint(first);
    glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, lanes) + sizeof(GLint)), sizeof(firstLane),
                         &firstLane);
    const GLint split = (i > 0 ? gpu::CONE_SPLIT_RESUME : 0) | (i + 1 < slices.count() ? gpu::CONE_SPLIT_CARRY : 0);
    glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, trace) + 3 * sizeof(GLint)), sizeof(split),
                         &split);
}

GlBuffer bindConeCarry(const ConeSlices& slices, size_t slots) {
    if (slices.count() <= 1 || slots == 0) return GlBuffer();
    GlBuffer carry = createBuffer(slots * 8 * sizeof(float));  // ConeCarried: two vec4
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_CARRY, carry.id());
    return carry;
}

int denseLoopsPerStep(const ConeSettings& settings) { return settings.planeLimit ? 2 : 1; }

glm::ivec4 conePixelImage(const GBuffer& gbuffer, const ConeSettings& settings) {
    return glm::ivec4(gbuffer.width, gbuffer.height, settings.jitter ? 1 : 0, int(settings.seed));
}

bool readsDepthLevels(const VoxelGrid& grid, ConeDirectional directional) {
    return grid.depthLevels && directional != ConeDirectional::None;
}

bool readsSheets(const VoxelGrid& grid, ConeDirectional directional) {
    return grid.sheets && directional != ConeDirectional::None;
}

bool readsSharpened(const ConeSettings& settings, ConeDirectional directional) {
    return sharpensLevels(settings) && directional != ConeDirectional::None;
}

ConeDirectional bindGridTextures(bool gi, const VoxelGrid& grid, const ConeSettings& settings) {
    const ConeDirectional directional = directionalLevels(gi, grid, settings);
    glBindTextureUnit(gpu::CONE_UNIT_OPACITY, gi ? grid.radiance.id() : grid.opacity.id());
    if (gi) glBindTextureUnit(gpu::CONE_UNIT_NORMAL, grid.normal.id());
    if (directional == ConeDirectional::Six)
        for (int i = 0; i < 6; ++i) glBindTextureUnit(gpu::CONE_UNIT_ANISO + i, grid.anisoRadiance[i].id());
    if (directional == ConeDirectional::Packed) glBindTextureUnit(gpu::CONE_UNIT_ANISO, grid.anisoOpacity.id());
    if (readsSheets(grid, directional)) {
        glBindTextureUnit(gpu::CONE_UNIT_SHEETS, grid.sheets.id());
        glBindTextureUnit(gpu::CONE_UNIT_SHEET_EXTENTS, grid.sheetExtents.id());
    }
    return directional;
}

BoundConePass bindConePass(bool gi, const VoxelGrid& grid, const GBuffer& gbuffer, float maxDistWorld, float sky,
                           const ConeSettings& settings) {
    gpu::ConeUniforms u = coneUniforms(gi, grid, maxDistWorld, sky, settings);
    u.image = conePixelImage(gbuffer, settings);
    BoundConePass bound;
    bindGBufferTextures(gbuffer);  // the shaders texelFetch position, normal, geomNormal, albedo
    bound.directional = bindGridTextures(gi, grid, settings);
    bound.depthLevels = readsDepthLevels(grid, bound.directional);
    bound.sharpen = readsSharpened(settings, bound.directional);
    bound.sheets = readsSheets(grid, bound.directional);
    // Lane caps where AO's march reads sheets (cone_sampleSheets, laneCapTangent); GI's cones
    // run to the grid's end, which no lane's cap is about.
    if (bound.sheets && !gi) {
        const glm::ivec3 res = grid.resolution;
        const ConeLanes lanes = coneMarchLanes(settings, std::max(res.x, std::max(res.y, res.z)));
        u.caps.x = laneCapTangent(lanes.lanesPerCone, lanes.apertureDeg);
    }
    bound.ubo = bindConeUniforms(u);
    bound.slices = coneSlices(u, settings, denseLoopsPerStep(settings));
    return bound;
}

namespace {

const GLbitfield kPixelPassWritten = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                     GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                                     GL_SHADER_STORAGE_BARRIER_BIT;

// ConeUniforms::trace's component `component` in the bound pass's uniform buffer.
void setTraceUniform(GLuint ubo, int component, GLint value) {
    glNamedBufferSubData(ubo, GLintptr(offsetof(gpu::ConeUniforms, trace) + size_t(component) * sizeof(GLint)),
                         sizeof(value), &value);
}

// One stage of a pixel pass writing `image`, over groups x groupsY work groups.
void dispatchStageGroups(GLuint ubo, GLint stage, GLuint image, GLenum format, GLuint groups, GLuint groupsY) {
    setTraceUniform(ubo, 1, stage);
    glBindImageTexture(gpu::CONE_IMAGE_OUTPUT, image, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
    glDispatchCompute(groups, groupsY, 1);
    glMemoryBarrier(kPixelPassWritten);
}

// One stage over w x h invocations in CONE_LOCAL_SIZE tiles.
void dispatchStage(GLuint ubo, GLint stage, GLuint image, GLenum format, int w, int h) {
    dispatchStageGroups(ubo, stage, image, format, groupCount(w, gpu::CONE_LOCAL_SIZE),
                        groupCount(h, gpu::CONE_LOCAL_SIZE));
}

// A stage over the pixels a previous stage listed: the own stage (count at entry 0 of the
// list's header) or the wide stage (entry 1). Their count comes back to the CPU (four bytes)
// rather than feeding an indirect dispatch: llvmpipe was seen to read indirect arguments
// before the pass that wrote them had finished (voxelize.cpp). Returns the count.
GLuint dispatchListStage(GLuint ubo, GLint stage, GLuint list, GLuint image, GLenum format) {
    GLuint listed = 0;
    const GLintptr countAt = (stage == gpu::CONE_STAGE_WIDE ? 1 : 0) * GLintptr(sizeof(GLuint));
    glGetNamedBufferSubData(list, countAt, sizeof(listed), &listed);
    const GLuint perGroup = GLuint(gpu::CONE_LOCAL_SIZE * gpu::CONE_LOCAL_SIZE);
    const GLuint maxGroups = 65535;  // the GL minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT
    for (GLuint base = 0; base < listed; base += maxGroups * perGroup) {
        setTraceUniform(ubo, 2, GLint(base));
        dispatchStageGroups(ubo, stage, image, format, std::min(maxGroups, (listed - base + perGroup - 1) / perGroup),
                            1);
    }
    return listed;
}

}  // namespace

GlTexture dispatchPixelPass(GLuint program, bool gi, const GBuffer& gbuffer, GlBuffer& counts, GLuint ubo,
                            int traceScale, const ConeSlices& slices) {
    const GLenum format = gi ? GL_RGBA32F : GL_R32F;
    const int s = std::max(1, traceScale);
    GlTexture out = createTexture2D(format, gbuffer.width, gbuffer.height);
    const size_t pixels = size_t(gbuffer.width) * size_t(gbuffer.height);
    // Zeroed: with a trace scale only the traced pixels (and those that trace their own) write.
    counts = createBuffer(pixels * 2 * sizeof(float));
    glClearNamedBufferData(counts.id(), GL_R32F, GL_RED, GL_FLOAT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_COUNTS, counts.id());
    // The gathers' sums between slices, per pixel (the traced and own stages' pixels are the
    // image's; the own stage starts its gathers anew).
    GlBuffer carry = bindConeCarry(slices, pixels);
    glUseProgram(program);
    if (s == 1) {
        for (int i = 0; i < slices.count(); ++i) {
            loadConeSlice(ubo, slices, i);
            dispatchStage(ubo, gpu::CONE_STAGE_TRACE, out.id(), format, gbuffer.width, gbuffer.height);
        }
    } else {
        // The trace stage: one pixel per s x s block into the traced image.
        const int tw = (gbuffer.width + s - 1) / s, th = (gbuffer.height + s - 1) / s;
        GlTexture traced = createTexture2D(format, tw, th);
        for (int i = 0; i < slices.count(); ++i) {
            loadConeSlice(ubo, slices, i);
            dispatchStage(ubo, gpu::CONE_STAGE_TRACE, traced.id(), format, tw, th);
        }
        // The resolve stage over every pixel (cone_resolve.glsl), listing those its four
        // blocks do not share for the wide stage, which lists those no block shares: two
        // lists of up to every pixel, a uint each.
        GlBuffer own = createBuffer((gpu::CONE_OWN_LIST_HEADER + 2 * pixels) * sizeof(GLuint));
        glClearNamedBufferSubData(own.id(), GL_R32UI, 0, 2 * sizeof(GLuint), GL_RED_INTEGER, GL_UNSIGNED_INT,
                                  nullptr);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_OWN_LIST, own.id());
        glBindImageTexture(gpu::CONE_IMAGE_TRACED, traced.id(), 0, GL_FALSE, 0, GL_READ_ONLY, format);
        glUseProgram(cachedProgram(coneResolveProgramKey(gi)));
        // One invocation per region of pixels that share their four nearest blocks
        // (cone_resolve.glsl): the blocks and one more region on each axis.
        dispatchStage(ubo, gpu::CONE_STAGE_RESOLVE, out.id(), format, tw + 1, th + 1);
        // Only the wide stage lists pixels for the own stage: without silhouettes, no second
        // count to read back.
        const GLuint wide = dispatchListStage(ubo, gpu::CONE_STAGE_WIDE, own.id(), out.id(), format);
        glBindImageTexture(gpu::CONE_IMAGE_TRACED, 0, 0, GL_FALSE, 0, GL_READ_ONLY, format);
        glUseProgram(program);
        if (wide > 0) {
            for (int i = 0; i < slices.count(); ++i) {
                loadConeSlice(ubo, slices, i);
                dispatchListStage(ubo, gpu::CONE_STAGE_OWN, own.id(), out.id(), format);
            }
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_OWN_LIST, 0);
    }
    glUseProgram(0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_COUNTS, 0);
    if (carry) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::CONE_BINDING_CARRY, 0);
    return out;
}

GlTexture timedConePass(PassTimer& timer, const char* name, const GBuffer& gbuffer, ConeCost* cost,
                        const std::function<GlTexture(GlBuffer& counts, int& dispatches)>& trace) {
    GlBuffer counts;
    GlTexture out;
    int dispatches = 0;
    {
        auto scope = timer.scope(name);
        out = trace(counts, dispatches);
    }
    if (cost) {
        const size_t pixels = size_t(gbuffer.width) * size_t(gbuffer.height);
        std::vector<float> c(pixels * 2);
        glGetNamedBufferSubData(counts.id(), 0, GLsizeiptr(c.size() * sizeof(float)), c.data());
        // Surface pixels as the passes see them (position w > 0): the per-pixel figures' divisor,
        // whether a pixel traced its own cones or was resolved from its neighbours'.
        const Image position = readTexture2D(gbuffer.position.id(), gbuffer.width, gbuffer.height, 4);
        *cost = ConeCost{};
        for (size_t i = 0; i < pixels; ++i) cost->addPixel(c[2 * i], c[2 * i + 1], position.pixels[4 * i + 3] > 0.f);
        cost->dispatches = dispatches;
    }
    return out;
}

void checkGrid(const VoxelGrid& grid, const std::string& pass) {
    if (glm::any(glm::lessThan(grid.resolution, glm::ivec3(1))))
        throw InternalError(pass, "voxel grid has no resolution");
    if (!(grid.voxelSize > 0.f) || !std::isfinite(grid.voxelSize))
        throw InternalError(pass, "voxel grid has voxelSize " + std::to_string(grid.voxelSize));
    if (grid.levels < 1) throw InternalError(pass, "voxel grid has no mip levels");
    if (!grid.opacity) throw InternalError(pass, "voxel grid has no opacity texture");
}

}  // namespace vct::conedetail
