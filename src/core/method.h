// The seam between the renderer and the estimators. A method (an AO or a GI estimator)
// describes itself in one `Method` value: its name as --ao/--gi accept it, its kind, its
// settings, the passes it can run with the resources each reads and writes, and the
// function that runs them. The registry (src/methods) lists every method; the renderer
// plans and runs a render through these declarations alone and never names a method.
//
// Adding a method: a folder with the method's code and a `const Method& xxxMethod()`, its
// shaders under shaders/, and one line in src/methods/registry.cpp.
#pragma once

#include "core/gbuffer.h"
#include "core/gpu_scene.h"
#include "core/pass.h"
#include "core/request.h"
#include "core/scene_features.h"
#include "core/settings.h"
#include "core/timing.h"
#include "core/view.h"
#include "gl/handles.h"
#include "gl/program_cache.h"
#include "image/image.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vct {

enum class MethodKind { AO, GI };
const char* toString(MethodKind k);  // "ao" | "gi"

// An output a method adds to the renderer's (the reference's standard errors, the voxel
// views). `resource` is what the method writes for it.
struct MethodAov {
    AovInfo info;
    ResourceId resource;
};

// A pass a method can run, and why it does not run when its method is not chosen: the
// reason's "{ao}" and "{gi}" become the request's --ao and --gi ("--ao {ao} is not a
// screen-space method").
struct MethodPass {
    PassId id;
    std::string unusedReason;
};

// What a method's declarations may look at.
struct PlanContext {
    const SceneFeatures& scene;
    const RenderRequest& request;
    bool lights() const { return scene.lights > 0; }
};

// Where a method's declarations go: the passes it runs for this request, in execution
// order, and why any of its passes cannot serve this request.
struct PassDeclarations {
    std::vector<PassDecl> passes;
    std::map<std::string, std::string> notApplicable;  // pass name -> reason
    void add(PassDecl d) { passes.push_back(std::move(d)); }
    void skip(PassId id, std::string reason) { notApplicable[std::string(id.name)] = std::move(reason); }
};

// Typed state kept under a string key: a session's (voxel grids, a BVH) or one render's
// (the voxel volume the AO and GI cones of one render share).
class StateStore {
public:
    template <class T>
    T& get(const std::string& key) {
        std::shared_ptr<void>& p = mItems[key];
        if (!p) p = std::make_shared<T>();
        return *static_cast<T*>(p.get());
    }
    // Drops every method's state (the scene's geometry changed: voxels and BVHs are stale).
    void clear() { mItems.clear(); }

private:
    std::map<std::string, std::shared_ptr<void>> mItems;
};

// A resource a method hands to the composite and the readback: a GL texture of the G-buffer's
// size (bottom row first, `channels` of it meaningful) or a CPU image (top row first).
struct FrameResource {
    GlTexture texture;
    int textureChannels = 0;
    Image image;
};

class FrameOutputs {
public:
    void setTexture(ResourceId id, GlTexture texture, int channels);
    void setImage(ResourceId id, Image image);
    const FrameResource* find(ResourceId id) const;
    FrameResource* find(ResourceId id);

private:
    std::map<std::string, FrameResource, std::less<>> mResources;
};

// Everything a method's passes may read and write in one render.
struct MethodContext {
    const RenderPlan& plan;
    const RenderRequest& request;
    const Scene& scene;
    const SceneFeatures& features;
    const GpuScene& gpu;
    const GBuffer* gbuffer;  // null when the plan rasterizes no G-buffer
    const View& view;
    PassTimer& timer;
    StateStore& session;     // kept across the renders of one session
    StateStore& frame;       // shared by the methods of this render
    FrameOutputs& outputs;
    std::map<std::string, int>& runCounts;  // how often shared passes (voxelize, ...) ran
    nlohmann::json& extra;                  // statistics for --stats and compare records
    // The renderer's own resources of this render, by id, for a method whose pass declared it
    // reads them (kDirect: the punctual lights' direct light, RGBA32F, the G-buffer's size).
    std::map<std::string, const GlTexture*, std::less<>> rendererTextures = {};

    // The renderer's texture `id`, or null where the plan ran no pass that writes it.
    const GlTexture* rendererTexture(ResourceId id) const {
        auto it = rendererTextures.find(id.name);
        return it == rendererTextures.end() ? nullptr : it->second;
    }
};

struct Method {
    std::string name;      // as --ao / --gi accept it
    MethodKind kind = MethodKind::AO;
    std::string summary;   // one line for --help
    std::vector<MethodPass> passes;  // every pass it can run
    std::vector<MethodAov> aovs;     // outputs it adds to the renderer's
    // The ground truth: comparisons score the other methods against it and never list it
    // among the scored variants.
    bool groundTruth = false;
    // Lights the image itself (a path tracer): it writes kBeauty and kDirect, and the
    // renderer runs no shadow, direct or composite pass.
    bool lightsTheImage = false;
    // Traces cones (vct.cones, vct.aperture): its AO converges, as its voxels refine, to the
    // cone model of that cone set (--ao reference --param reference.cone-model=1), and
    // comparisons split its error into the cone set's and the voxels'.
    bool tracesCones = false;
    std::function<std::vector<SettingDoc>()> settings;  // every --param key it reads
    // The values the presets `params` names (gtao.preset, vct.preset) give the keys they set,
    // as --param would write them: what a record holds for a key the user did not give, where
    // the settings' default text ("the preset's") is not a value. Empty: no presets.
    std::function<std::map<std::string, std::string>(const ParamMap& params)> presetValues;
    std::function<std::vector<ProgramKey>()> programs;  // every GL program it can build
    std::function<void(const PlanContext&, PassDeclarations&)> declare;
    std::function<void(MethodContext&)> execute;
};

}  // namespace vct
