#include "clipmap/clipmap.h"

#include "cone/clipmap_shared.h"
#include "core/errors.h"
#include "gl/program_cache.h"
#include "voxelize/voxel_gl.h"
#include "voxelize/voxel_programs.h"
#include "voxelize/voxelize.h"
#include "voxelize/voxelize_shared.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace vct {

Bounds3 ClipmapLayout::bounds(int level) const {
    Bounds3 b;
    b.min = origin(level);
    b.max = b.min + glm::vec3(float(resolution) * voxelSize(level));
    return b;
}

ClipmapLayout computeClipmapLayout(const Bounds3& region, const glm::vec3& focus, int levelCount, int resolution) {
    if (levelCount < 1 || levelCount > gpu::CLIPMAP_MAX_LEVELS)
        throw InternalError("computeClipmapLayout", "vct.clipmap.levels = " + std::to_string(levelCount) +
                                                        " outside [1, 8]");
    if (region.empty()) throw InternalError("computeClipmapLayout", "empty region");
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(region.min[a]) || !std::isfinite(region.max[a]) || !std::isfinite(focus[a]))
            throw InternalError("computeClipmapLayout", "region or focus is not finite");
    ClipmapLayout c;
    c.levelCount = levelCount;
    // A multiple of 4, so half a level is a whole number of the next level's voxels. At least
    // 32: level l then sits >= res/4 - 1.5 = 6.5 voxels of level l + 1 inside it, clear of that
    // level's border margin and blend band (5 voxels), so the level of detail stays continuous.
    c.resolution = std::clamp((resolution + 3) / 4 * 4, 32, 512);
    c.region = region;
    c.focus = glm::clamp(focus, region.min, region.max);
    // The lattice depends on the region only, never on the focus: a camera that moves keeps
    // every voxel where it was, and a cascade that follows it moves by whole voxels. The
    // coarsest level covers the region from its centre with 3 voxels to spare on each side
    // (one for the snap of its centre, one of padding, one of trilinear reach).
    const float extent = std::max(region.maxExtent(), 1e-6f * std::max(1.f, glm::length(region.center())));
    const float coarseVoxel = extent / float(c.resolution - 6);
    c.baseVoxelSize = coarseVoxel / float(1 << (levelCount - 1));
    // Half a voxel below the region: a surface on the region's boundary (a floor at its bottom)
    // then lies inside a layer of voxels at every level, not on a face where rounding would
    // pick a different side per level and draw a seam where the levels meet.
    c.anchor = region.min - glm::vec3(0.5f * c.baseVoxelSize);
    auto snapped = [&](const glm::vec3& p, int level) {
        const glm::dvec3 index = glm::dvec3(p - c.anchor) / double(c.baseVoxelSize);
        const double snap = double(1 << level);  // one voxel of the level
        glm::ivec3 centre;
        for (int a = 0; a < 3; ++a) centre[a] = int(std::llround(index[a] / snap) * (long long)snap);
        return centre;
    };
    c.originIndex.assign(size_t(levelCount), glm::ivec3(0));
    const int top = levelCount - 1;
    c.originIndex[size_t(top)] = snapped(region.center(), top) - glm::ivec3((c.resolution / 2) << top);
    // Finer levels centre on the focus in steps of one of their voxels, kept inside the next
    // coarser level clear of its border margin and blend band (its level of detail stays
    // continuous). Nesting needs no alignment of the origins: the lattice is shared.
    for (int l = top - 1; l >= 0; --l) {
        const int parentVoxel = 1 << (l + 1);
        const int span = c.resolution << l;
        const int room = int(std::ceil(gpu::CLIPMAP_BORDER_MARGIN + gpu::CLIPMAP_BLEND_WIDTH + 1.f)) * parentVoxel;
        const glm::ivec3 parent = c.originIndex[size_t(l + 1)];
        const int parentSpan = c.resolution << (l + 1);
        glm::ivec3 origin = snapped(c.focus, l) - glm::ivec3(span / 2);
        for (int a = 0; a < 3; ++a) origin[a] = std::clamp(origin[a], parent[a] + room, parent[a] + parentSpan - span - room);
        c.originIndex[size_t(l)] = origin;
    }
    return c;
}

glm::vec3 clipmapFocus(const Bounds3& region, const Camera& camera, int levelCount, int resolution) {
    const ClipmapLayout atEye = computeClipmapLayout(region, camera.eye, levelCount, resolution);
    const glm::vec3 forward = camera.target - camera.eye;
    if (!(glm::length(forward) > 0.f)) return camera.eye;
    const float ahead = 0.25f * float(atEye.resolution) * atEye.baseVoxelSize;
    return camera.eye + glm::normalize(forward) * ahead;
}

namespace {

// The mean of level `fine`'s voxels into each voxel of level `coarse` they fill
// (clipmap_nest.glsl). `fineOrigin` is the fine level's voxel 0 in fine voxels from the coarse
// level's voxel 0, so coarse voxel c holds fine voxels 2c - fineOrigin and the next one per axis:
// with an odd origin, the coarse voxels at both ends are only half filled and keep their own.
void nestLevel(const VoxelGrid& fine, VoxelGrid& coarse, const glm::ivec3& fineOrigin) {
    glm::ivec3 first, count;
    for (int a = 0; a < 3; ++a) {
        first[a] = (fineOrigin[a] + 1) >> 1;  // ceil(fineOrigin / 2), fineOrigin >= 0 inside the parent
        const int last = (fine.resolution[a] - 2 + fineOrigin[a]) >> 1;
        count[a] = std::max(0, last - first[a] + 1);
    }
    if (count.x == 0 || count.y == 0 || count.z == 0) return;
    auto copy = [&](const GlTexture& src, const GlTexture& dst) {
        const GLenum format = textureInternalFormat(dst.id());
        const GLuint p = cachedProgram(clipmapNestProgramKey(format));
        setUniform(p, "uCount", count);
        setUniform(p, "uCoarseFirst", first);
        setUniform(p, "uFineFirst", 2 * first - fineOrigin);
        glBindTextureUnit(0, src.id());
        bindImage3D(0, dst.id(), 0, GL_WRITE_ONLY, format);
        glUseProgram(p);
        const int g = gpu::VOX_GRID_GROUP;
        glDispatchCompute(groupCount(count.x, g), groupCount(count.y, g), groupCount(count.z, g));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    };
    copy(fine.opacity, coarse.opacity);
    if (fine.radiance && coarse.radiance) copy(fine.radiance, coarse.radiance);
    glBindTextureUnit(0, 0);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(0);
}

}  // namespace

Clipmap buildClipmap(const GpuScene& gpuScene, const Scene& scene, const ClipmapLayout& layout, bool inject,
                     const ParamMap& params, PassTimer& timer, bool attributes) {
    const int n = layout.levelCount;
    if (n < 1 || int(layout.originIndex.size()) != n) throw InternalError("buildClipmap", "layout has no levels");
    Clipmap cm;
    cm.layout = layout;
    cm.levels.resize(size_t(n));
    const size_t firstTiming = timer.timings().size();
    const glm::ivec3 res(layout.resolution);
    for (int l = 0; l < n; ++l)
        cm.levels[size_t(l)] = voxelizeGrid(gpuScene, makeGridLayout(layout.origin(l), layout.voxelSize(l), res),
                                            params, timer, "voxelize_l" + std::to_string(l), inject, attributes);
    if (inject) {
        for (int l = 0; l < n; ++l) {
            std::vector<const VoxelGrid*> outer;
            for (int k = l + 1; k < n; ++k) outer.push_back(&cm.levels[size_t(k)]);
            injectRadiance(cm.levels[size_t(l)], gpuScene, scene, params, timer, outer,
                           "inject_l" + std::to_string(l));
        }
    }
    for (int l = 0; l < n; ++l) {
        if (l > 0) {
            auto scope = timer.scope("nest_l" + std::to_string(l), true, Reruns::WhenSceneChanges);
            // Level l-1's voxel 0 in its own voxels from level l's (origins are whole voxels of l-1).
            const glm::ivec3 fineOrigin =
                (layout.originIndex[size_t(l - 1)] - layout.originIndex[size_t(l)]) / (1 << (l - 1));
            nestLevel(cm.levels[size_t(l - 1)], cm.levels[size_t(l)], fineOrigin);
        }
        buildMips(cm.levels[size_t(l)], false, timer, "mips_l" + std::to_string(l));
    }
    cm.levelMs.assign(size_t(n), 0.0);
    const auto& timings = timer.timings();
    for (size_t i = firstTiming; i < timings.size(); ++i) {
        const std::string& name = timings[i].name;
        const size_t at = name.rfind("_l");
        if (at == std::string::npos) continue;
        const int l = std::atoi(name.c_str() + at + 2);
        if (l >= 0 && l < n) cm.levelMs[size_t(l)] += timings[i].wallMs;
    }
    for (const VoxelGrid& g : cm.levels) cm.memoryBytes += g.memoryBytes;
    return cm;
}

nlohmann::json clipmapStats(const Clipmap& cm) {
    nlohmann::json levels = nlohmann::json::array();
    for (int l = 0; l < cm.layout.levelCount; ++l) {
        const VoxelGrid& g = cm.levels[size_t(l)];
        const Bounds3 b = cm.layout.bounds(l);
        levels.push_back({{"level", l},
                          {"min", {b.min.x, b.min.y, b.min.z}},
                          {"max", {b.max.x, b.max.y, b.max.z}},
                          {"extent", float(cm.layout.resolution) * g.voxelSize},
                          {"voxel_size", g.voxelSize},
                          {"occupied", g.occupiedVoxels},
                          {"inject_dispatches", g.injectDispatches},
                          {"memory_bytes", g.memoryBytes},
                          {"time_ms", cm.levelMs.empty() ? 0.0 : cm.levelMs[size_t(l)]}});
    }
    const glm::vec3 f = cm.layout.focus;
    return {{"levels", levels},
            {"level_count", cm.layout.levelCount},
            {"resolution", cm.layout.resolution},
            {"voxel_size", cm.layout.baseVoxelSize},
            {"focus", {f.x, f.y, f.z}},
            {"mips", "isotropic"},
            {"memory_bytes", cm.memoryBytes}};
}

}  // namespace vct
