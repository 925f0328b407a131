#include "vct/vct_method.h"

#include "cone/cone_bounce.h"
#include "cone/cone_cost.h"
#include "cone/cone_programs.h"
#include "cone/cone_set.h"
#include "cone/cone_settings.h"
#include "cone/cone_trace.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "vct/sparse_vct.h"
#include "vct/vct_passes.h"
#include "vct/vct_settings.h"
#include "vct/voxel_region.h"
#include "vct/voxel_volume.h"
#include "voxelize/voxel_programs.h"

#include <cmath>
#include <sstream>
#include <string>

namespace vct {

namespace {

bool isVct(const std::string& method) { return method == kVctMethodName; }

// The voxel passes both cone methods share (declared by each; the planner keeps one).
void declareVoxelPasses(const PlanContext& ctx, PassDeclarations& d) {
    const RenderRequest& r = ctx.request;
    d.add({kPassVoxelize, {}, {kVoxels}, "world-space occupancy for cone tracing; " + voxelRegionExplanation(r)});
    // Without lights or emission the voxels still carry sky light once it bounces between
    // them (dense and sparse grids: clipmaps hold direct light only).
    const bool gi = isVct(r.gi);
    const bool skyBounces = gi && r.sky > 0.f && clipmapLevelCount(r) == 0 && readVctBounces(r.params) > 0;
    const bool radiance = gi && (ctx.lights() || ctx.scene.hasEmission || skyBounces);
    if (!gi)
        d.skip(kPassInject, "AO needs opacity only, not radiance (no --gi vct)");
    else if (!radiance)
        d.skip(kPassInject,
               "the scene has no lights and no emission, and no sky light bounces between voxels (--sky 0, "
               "vct.bounces=0 or clipmaps): cones see the sky directly");
    else if (!ctx.lights() && !ctx.scene.hasEmission)
        d.add({kPassInject, {kVoxels}, {kVoxelRadiance},
               "no lights or emission: empty direct light, then vct.bounces bounces of the sky light between the "
               "voxels (timed as 'bounce')"});
    else
        d.add({kPassInject, {kVoxels}, {kVoxelRadiance},
               "direct light and emission into the voxels, then vct.bounces diffuse bounces between them (dense "
               "grid; timed as 'bounce')" +
                   // The split depends on the fitted grid, known once it is voxelized.
                   (ctx.scene.lights > 1 ? "; " + std::to_string(ctx.scene.lights) +
                                               " lights over as many dispatches as the loop budget needs "
                                               "(vct.inject.dispatch-lights; --stats: voxels.inject_dispatches)"
                                         : std::string())});
    std::vector<ResourceId> mipReads{kVoxels};
    if (radiance) mipReads.push_back(kVoxelRadiance);
    const ConeSettings cone = readConeSettings(r.params);
    d.add({kPassMips, mipReads, {kVoxelMips},
           std::string("filtered levels for wide cones") +
               (wantsDepthLevels(cone) ? "; the directional levels hold optical depth (vct.opacity=depth)" : "")});
}

// The cones a cone pass marches, for --explain: the set, and its lanes when there are more
// than one (the grid's longest axis is --voxel-res, which auto's schedule reads).
std::string coneExplanation(const RenderRequest& r) {
    const ConeSettings c = readConeSettings(r.params);
    std::string s = std::to_string(c.coneCount) + " cones of " + std::to_string(int(std::lround(c.apertureDeg))) + " deg";
    const int lanes = resolveConeLanes(c.lanes, c.coneCount, r.voxelRes, c.lanesBase);
    if (lanes > 1) {
        s += ", each marched as " + std::to_string(lanes) + " lanes";
        if (c.lanes > 0) {
            s += " (vct.lanes)";
        } else {
            s += " (vct.lanes=auto at " + std::to_string(r.voxelRes) + "^3";
            if (c.lanesBase != gpu::CONE_LANES_BASE_RES) s += " with vct.lanes-base=" + std::to_string(c.lanesBase);
            s += ")";
        }
    }
    if (c.jitter) s += ", turned about the normal per pixel (vct.jitter, from the seed)";
    if (sharpensLevels(c)) {
        std::ostringstream sharpen;
        sharpen << c.sharpen;
        s += ", the directional levels sharpened along their axis (vct.sharpen=" + sharpen.str() +
             "), the base level once per axis";
    }
    if (c.aim) s += ", aimed from their offset start at their rays' points at the maximum distance (vct.aim)";
    if (c.endTaper) s += ", on levels that reach no further than the maximum distance near its end (vct.end-taper)";
    if (c.belowPlane == ConeBelowPlane::Mirror)
        s += ", the caps' parts below the surface's plane reflected above it (vct.below-plane=mirror)";
    if (c.levelBias != gpu::CONE_DEFAULT_LEVEL_BIAS) {
        std::ostringstream bias;
        bias << ", sampling the level log2(footprint) " << (c.levelBias < 0.f ? "- " : "+ ") << std::abs(c.levelBias)
             << " (vct.level-bias=" << c.levelBias << ")";
        s += bias.str();
    }
    if (c.traceScale > 1)
        s += ", traced for one pixel per " + std::to_string(c.traceScale) + "x" + std::to_string(c.traceScale) +
             " block and resolved for the others (vct.trace-scale)";
    return s;
}

void declareVoxelView(const PlanContext& ctx, PassDeclarations& d) {
    const RenderRequest& r = ctx.request;
    if (r.backend == "vdb")
        for (const std::string& aov : r.aovs)
            if (aov.rfind("voxel_", 0) == 0)
                throw UsageError("--aov " + aov + ": voxel_* AOVs show the dense grid: use --backend gl");
    d.add({kPassVoxelView, {kVoxelMips}, {kVoxelView}, "voxel grid seen from the camera"});
}

// What the AO and the GI cones of one render share.
struct VctFrame {
    bool built = false;
    VoxelVolume volume;
    bool viewsDone = false;
};

struct VctSession {
    VoxelVolumeCache dense;
    SparseVolumeCache sparse;
};

void traceVoxelViews(MethodContext& ctx, const VoxelGrid& grid) {
    const RenderRequest& r = ctx.request;
    const int level = vctSettings().read(r.params).viewLevel;
    for (const std::string& aov : r.aovs) {
        if (aov.rfind("voxel_", 0) != 0) continue;
        const std::string what = aov.substr(6);
        GlTexture t = rayMarchVoxels(grid, ctx.view, what, level, ctx.timer);
        GlContext::shared().checkErrors("voxel_view");
        const Image rgba = readTexture2D(t.id(), ctx.view.width, ctx.view.height, 4);
        const int channels = what == "opacity" ? 1 : 3;
        Image img(ctx.view.width, ctx.view.height, channels);
        for (size_t i = 0; i < size_t(ctx.view.width) * ctx.view.height; ++i)
            for (int c = 0; c < channels; ++c) img.pixels[i * channels + c] = rgba.pixels[4 * i + (what == "opacity" ? 3 : c)];
        ctx.outputs.setImage(ResourceId{aov}, std::move(img));
    }
}

void executeVct(MethodContext& ctx, MethodKind kind) {
    if (!ctx.plan.runs(kPassVoxelize)) return;
    const RenderRequest& r = ctx.request;
    ConeSettings cone = readConeSettings(r.params);
    cone.seed = coneJitterSeed(r.seed);
    VctSession& session = ctx.session.get<VctSession>("vct");
    if (r.backend == "vdb") {
        if (cone.jitter)
            throw UsageError("--param vct.jitter=1: the sparse backend (--backend vdb) traces one fixed cone set; "
                             "use --backend gl");
        if (cone.traceScale != 1)
            throw UsageError("--param vct.trace-scale=" + std::to_string(cone.traceScale) +
                             ": the sparse backend (--backend vdb) traces every pixel; use --backend gl");
        traceSparse(ctx, kind, sparseFrameFor(ctx, session.sparse, cone), cone);
        return;
    }
    VctFrame& frame = ctx.frame.get<VctFrame>("vct");
    if (!frame.built) {
        frame.volume = voxelVolumeFor(ctx, cone, session.dense);
        ctx.extra["voxels"] = frame.volume.stats;
        frame.built = true;
    }
    const VoxelVolume& v = frame.volume;
    GlContext& gl = GlContext::shared();
    ConeCost cost;
    if (kind == MethodKind::AO && ctx.plan.runs(kPassConeAo)) {
        GlTexture ao = v.clipmap ? coneTraceClipmapAO(*v.clipmap, *ctx.gbuffer, ctx.view, r.radius, cone, ctx.timer, &cost)
                                 : coneTraceAO(*v.grid, *ctx.gbuffer, ctx.view, r.radius, cone, ctx.timer, &cost);
        gl.checkErrors("cone_ao");
        ctx.extra["cone_ao"] = coneCostJson(cost, cone, r.voxelRes);
        ctx.outputs.setTexture(kAo, std::move(ao), 1);
    }
    if (kind == MethodKind::GI && ctx.plan.runs(kPassConeGi)) {
        GlTexture gi = v.clipmap ? coneTraceClipmapGI(*v.clipmap, *ctx.gbuffer, ctx.view, r.sky, cone, ctx.timer, &cost)
                                 : coneTraceGI(*v.grid, *ctx.gbuffer, ctx.view, r.sky, cone, ctx.timer, &cost);
        gl.checkErrors("cone_gi");
        ctx.extra["cone_gi"] = coneCostJson(cost, cone, r.voxelRes);
        ctx.outputs.setTexture(kGiIndirect, std::move(gi), 4);
    }
    if (ctx.plan.runs(kPassVoxelView) && !frame.viewsDone) {
        traceVoxelViews(ctx, *v.grid);
        frame.viewsDone = true;
    }
}

std::vector<ProgramKey> vctPrograms() {
    std::vector<ProgramKey> keys = voxelProgramVariants();
    for (const ProgramKey& k : coneProgramVariants()) keys.push_back(k);
    return keys;
}

Method makeVctMethod(MethodKind kind) {
    Method m;
    m.name = kVctMethodName;
    m.kind = kind;
    m.tracesCones = true;
    const bool ao = kind == MethodKind::AO;
    m.summary = ao ? "voxel cone traced AO: cones over the voxels' (directional) opacity, each limited to R"
                   : "voxel cone traced diffuse GI: cones gather the voxels' injected and bounced radiance";
    const std::string noVoxels = "no method reads voxels (--ao {ao}, --gi {gi})";
    m.passes = {{kPassVoxelize, noVoxels},
                {kPassInject, noVoxels},
                {kPassMips, noVoxels},
                {ao ? kPassConeAo : kPassConeGi, ao ? "--ao is not vct" : "--gi is not vct"},
                {kPassVoxelView, "no voxel grid in this render"}};
    m.aovs = {{{"voxel_albedo", 3, "voxel grid albedo, ray-marched from the camera"}, kVoxelView},
              {{"voxel_opacity", 1, "voxel grid opacity, ray-marched from the camera"}, kVoxelView}};
    if (!ao) m.aovs.push_back({{"voxel_radiance", 3, "voxel grid radiance, ray-marched from the camera"}, kVoxelView});
    m.settings = vctSettingDocs;
    m.presetValues = vctPresetValues;
    m.programs = vctPrograms;
    m.declare = [kind](const PlanContext& ctx, PassDeclarations& d) {
        declareVoxelPasses(ctx, d);
        if (kind == MethodKind::AO)
            d.add({kPassConeAo, {kGBufferSurface, kVoxelMips}, {kAo},
                   "world-space AO cones: " + coneExplanation(ctx.request)});
        else
            d.add({kPassConeGi, {kGBuffer, kVoxelMips}, {kGiIndirect}, "diffuse GI cones: " + coneExplanation(ctx.request)});
        declareVoxelView(ctx, d);
    };
    m.execute = [kind](MethodContext& ctx) { executeVct(ctx, kind); };
    return m;
}

}  // namespace

const Method& vctAoMethod() {
    static const Method m = makeVctMethod(MethodKind::AO);
    return m;
}

const Method& vctGiMethod() {
    static const Method m = makeVctMethod(MethodKind::GI);
    return m;
}

}  // namespace vct
