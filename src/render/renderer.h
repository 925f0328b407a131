// The renderer core: executes a RenderPlan over one scene. A RenderSession owns the
// scene's GPU copy and caches what several renders of the same scene can share (the
// G-buffer per camera and size, the shadow maps, the voxel grids per resolution), so a
// comparison of many methods rasterizes once and voxelizes once. It knows nothing of the
// command line or of files.
#pragma once

#include "core/request.h"
#include "core/settings.h"
#include "core/timing.h"
#include "image/image.h"
#include "render/plan.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

namespace vct {

struct RenderResult {
    RenderPlan plan;
    std::map<std::string, Image> aovs;  // requested AOVs, linear float, top row first
    std::vector<PassTiming> passes;     // passes that ran in this render (cached ones not repeated)
    double totalMs = 0.0;               // wall clock of this render (the cold cost when nothing was reused)
    // totalMs less the passes that rerun only when the scene or its lights change (voxels,
    // injection, bounces, mips, shadow maps, the reference's BVH; core/timing.h): what the
    // next frame of the same static scene costs.
    double frameMs = 0.0;
    // The GPU time of the per-frame passes where every one has it (PassTimer::frameGpuMs).
    std::optional<double> frameGpuMs;
    // Wall time of the programs this render built (their first use in the process): in
    // totalMs, not in its passes' times nor in frameMs.
    double programBuildMs = 0.0;
    nlohmann::json extra = nlohmann::json::object();  // method statistics (rays, voxel memory, ...)
    // --param keys nobody read: not in this render, nor with the same value and methods in an
    // earlier render of the session whose cached state (a voxel grid) this one reused.
    std::vector<std::string> unusedParams;
};

class RenderSession {
public:
    explicit RenderSession(const Scene& scene);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    RenderResult render(const RenderRequest& request);
    // The scene's lights moved (the Scene this session was made with, changed in place by the
    // caller: scene/gltf_animation.h's poseLights): uploads them and drops the shadow maps; the
    // methods see new lights through their keys (VCT injects again into the voxels it keeps).
    void lightsChanged();
    // The scene's triangles moved (posed in place by the caller: scene/gltf_animation.h's
    // poseAnimation): uploads them again and drops everything built from them, the G-buffers,
    // the shadow maps and every method's state (voxel grids, the BVH), so the next render
    // rebuilds them in full.
    void geometryChanged();
    const Scene& scene() const { return mScene; }
    const SceneFeatures& features() const { return mFeatures; }
    // How many times each shared pass actually ran in this session (tests use it to check
    // that a comparison voxelizes once).
    const std::map<std::string, int>& passRunCounts() const { return mRunCounts; }

private:
    struct Impl;
    const Scene& mScene;
    SceneFeatures mFeatures;
    std::map<std::string, int> mRunCounts;
    std::unique_ptr<Impl> mImpl;
};

// The renderer's own --param keys (the shadow map size); the methods' are in the registry.
std::vector<SettingDoc> rendererSettingDocs();
// Every --param key a render can read: the renderer's and every registered method's, once.
std::vector<SettingDoc> allSettingDocs();

// JSON for --stats: passes, totals, sizes, renderer string, core count, scene counts,
// passes_run and passes_skipped.
nlohmann::json statsJson(const RenderResult& result, const RenderRequest& request, const Scene& scene);

}  // namespace vct
