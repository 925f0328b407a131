// Shared plumbing of the cone passes (not a public interface): program cache, the uniform
// block, binding the grid's textures.
#pragma once

#include "cone/cone_programs.h"
#include "cone/cone_settings.h"
#include "cone/cone_shared.h"
#include "cone/cone_trace.h"
#include "gl/handles.h"
#include "gl/program_cache.h"
#include "core/gbuffer.h"
#include "core/timing.h"
#include "voxelize/voxel_grid.h"

#include <functional>
#include <string>
#include <vector>

namespace vct::conedetail {

// Grid fields of the uniform block (voxelFromWorld, gridResolution).
void setGridUniforms(gpu::ConeUniforms& u, const VoxelGrid& grid);

// Uploads `u` into a fresh uniform buffer bound at CONE_UBO_BINDING; keep it alive until
// the dispatch is issued.
GlBuffer bindConeUniforms(const gpu::ConeUniforms& u);

// The uniform block of a cone pass over `grid` (image size left 0): march constants, the
// distance limit (world units), sky radiance, plane limit, the cone set.
gpu::ConeUniforms coneUniforms(bool gi, const VoxelGrid& grid, float maxDistWorld, float sky,
                               const ConeSettings& settings);

// The cones of a pass (the set's lanes) and how many one dispatch marches (cone_budget.h):
// a pass dispatches once per slice of `perDispatch` cones, each gather carrying its sums to
// the next (cone_common.glsl), so every slice count gives the same image.
struct ConeSlices {
    std::vector<glm::vec4> cones;
    int perDispatch = 1;
    int count() const { return int((cones.size() + size_t(perDispatch) - 1) / size_t(perDispatch)); }
};
// The slices of a pass with uniforms `u` (coneUniforms: grid, distance limit, step) whose
// volume runs `loopsPerStep` loop iterations per step (coneLoopBound).
ConeSlices coneSlices(const gpu::ConeUniforms& u, const ConeSettings& settings, int loopsPerStep);
// Loads slice `i` into the pass's bound uniform buffer: its cones and count, and whether its
// dispatch resumes (i > 0) and carries (a slice follows) the gathers' sums. Nothing to load
// for a pass of one slice: coneUniforms holds it.
void loadConeSlice(GLuint ubo, const ConeSlices& slices, int i);
// A buffer of `slots` gathers' carried sums bound at CONE_BINDING_CARRY when the pass has
// more than one slice (none otherwise).
GlBuffer bindConeCarry(const ConeSlices& slices, size_t slots);
// Loop iterations per step of the dense grid's march (coneLoopBound): the step, and the
// plane limit's level search when on.
int denseLoopsPerStep(const ConeSettings& settings);

// ConeUniforms::image of a pixel pass over `gbuffer`: its size, and the per-pixel turn of the
// cone set (vct.jitter) with its seed.
glm::ivec4 conePixelImage(const GBuffer& gbuffer, const ConeSettings& settings);

// Binds the grid's textures a cone pass samples (opacity or radiance, normals for GI's
// facing test, the directional levels when used); returns which directional levels are
// bound (the variant of the pass's program: an AO pass over an AO grid samples its packed
// opacity, over a lit grid the six RGBA textures' alpha).
ConeDirectional bindGridTextures(bool gi, const VoxelGrid& grid, const ConeSettings& settings);
// Whether a pass reading `directional` levels of `grid` reads optical depth (the programs'
// CONE_DEPTH_LEVELS variant): the grid's directional levels hold it and the pass reads them.
bool readsDepthLevels(const VoxelGrid& grid, ConeDirectional directional);
// Whether a pass reading `directional` levels reads them with vct.sharpen's filter (the
// programs' CONE_SHARPEN variant, whose s is ConeUniforms::camera.w).
bool readsSharpened(const ConeSettings& settings, ConeDirectional directional);
// Whether a pixel pass (AO or GI) reads the grid's sheet texels at the base level
// (vct.voxel.edges=sheet over directional levels). The bounces do not: their voxels' gathers
// keep the trilinear base (coneBounceProgramKey has no sheet variant), so a bounce costs what it
// did.
bool readsSheets(const VoxelGrid& grid, ConeDirectional directional);

// One cone pass bound and ready for its program's dispatch: uniforms uploaded and bound,
// the G-buffer, the grid's textures (opacity or radiance, directional mips, normals for
// GI's facing test) on their units. `directional`: the directional levels bound;
// `depthLevels`: whether they hold optical depth (readsDepthLevels); `sharpen`: whether they
// are read sharpened (readsSharpened).
struct BoundConePass {
    GlBuffer ubo;
    ConeDirectional directional = ConeDirectional::None;
    bool depthLevels = false;
    bool sharpen = false;
    bool sheets = false;  // the pass reads grid.sheets at the base level (CONE_SHEETS)
    ConeSlices slices;
};
BoundConePass bindConePass(bool gi, const VoxelGrid& grid, const GBuffer& gbuffer, float maxDistWorld, float sky,
                           const ConeSettings& settings);

// Runs a bound pixel pass: `program` over the G-buffer's pixels in CONE_LOCAL_SIZE tiles,
// writing a new GL_RGBA32F (GI) or GL_R32F (AO) texture of the G-buffer's size, and into a
// new `counts` buffer each pixel's (samples, fetches). With `traceScale` s > 1 it runs the
// pass's stages (CONE_STAGE_TRACE into an image of ceil(size / s), CONE_STAGE_RESOLVE over
// every pixel, one invocation per s x s region, in the resolve's own program
// (coneResolveProgramKey), CONE_STAGE_WIDE in that program over the pixels the resolve
// listed, then CONE_STAGE_OWN over the pixels the wide stage listed; a list stage runs when
// its list has entries), setting the stage in `ubo`, the pass's bound ConeUniforms. The
// stages that march cones (trace, own) run once per slice of `slices`.
GlTexture dispatchPixelPass(GLuint program, bool gi, const GBuffer& gbuffer, GlBuffer& counts, GLuint ubo,
                            int traceScale, const ConeSlices& slices);

// Runs `trace` (a cone pass that dispatches with dispatchPixelPass, and sets `dispatches` to
// its slices' count) in timer scope `name`; then, outside the timed span, sums its counts into
// `cost` when given: the readback is for the statistics, not part of the pass's cost.
GlTexture timedConePass(PassTimer& timer, const char* name, const GBuffer& gbuffer, ConeCost* cost,
                        const std::function<GlTexture(GlBuffer& counts, int& dispatches)>& trace);

// Throws InternalError naming `pass` if the grid is not usable.
void checkGrid(const VoxelGrid& grid, const std::string& pass);

}  // namespace vct::conedetail
