#include "render/renderer.h"

#include "core/errors.h"
#include "core/memory_usage.h"
#include "core/method.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "methods/registry.h"
#include "raster/gbuffer_pass.h"
#include "raster/lighting_pass.h"
#include "raster/shadow_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <thread>

namespace vct {

namespace {

struct RendererSettings {
    int shadowSize = 1024;  // shadow map texels per side
};

const SettingsTable<RendererSettings>& rendererSettings() {
    static const auto table = SettingsTable<RendererSettings>().integer(
        "shadow.size", &RendererSettings::shadowSize, 16, 8192, "shadow map texels per side");
    return table;
}

}  // namespace

std::vector<SettingDoc> rendererSettingDocs() { return rendererSettings().docs(); }

std::vector<SettingDoc> allSettingDocs() {
    std::vector<SettingDoc> all = rendererSettingDocs();
    std::set<std::string> seen;
    for (const SettingDoc& d : all) seen.insert(d.key);
    for (const Method* m : registeredMethods())
        if (m->settings)
            for (const SettingDoc& d : m->settings())
                if (seen.insert(d.key).second) all.push_back(d);
    return all;
}

// G-buffers a session keeps (one per view and size).
constexpr size_t kMaxCachedGBuffers = 8;

struct RenderSession::Impl {
    GpuScene gpu;
    std::map<std::string, std::shared_ptr<GBuffer>> gbuffers;  // keyed by camera + size
    std::unique_ptr<ShadowMaps> shadows;
    int shadowSize = 0;  // the shadow.size the cached maps were rendered with
    std::set<std::string> paramsRead;  // "ao|gi|key=value" of every key a render read
    StateStore methods;  // the methods' state across renders (voxel grids, the BVH)
};

namespace {

std::string viewKey(const View& v) {
    std::ostringstream k;
    const float* e = glm::value_ptr(v.clipFromWorld);
    k << v.width << 'x' << v.height;
    for (int i = 0; i < 16; ++i) k << ',' << e[i];
    return k.str();
}

Image channelsOf(const Image& src, int first, int count) {
    Image out(src.width, src.height, count);
    for (size_t p = 0; p < size_t(src.width) * src.height; ++p)
        for (int c = 0; c < count; ++c) out.pixels[p * count + c] = src.pixels[p * src.channels + first + c];
    return out;
}

// A method's resource as a texture for the composite: CPU images (the reference, the sparse
// backend) are uploaded.
const GlTexture* asTexture(FrameOutputs& outputs, ResourceId id, GLenum format, int width, int height) {
    FrameResource* r = outputs.find(id);
    if (!r) return nullptr;
    if (!r->texture && !r->image.empty()) {
        r->texture = createTexture2D(format, width, height);
        uploadTexture2D(r->texture.id(), r->image);
    }
    return r->texture ? &r->texture : nullptr;
}

// The first `channels` of a method's resource (texture read back, or the CPU image).
Image resourceImage(const FrameOutputs& outputs, ResourceId id, int channels, int width, int height) {
    const FrameResource* r = outputs.find(id);
    if (!r) throw InternalError("readback", "no method wrote '" + std::string(id.name) + "'");
    if (!r->image.empty()) return r->image.channels == channels ? r->image : channelsOf(r->image, 0, channels);
    Image img = readTexture2D(r->texture.id(), width, height, r->textureChannels);
    return r->textureChannels == channels ? img : channelsOf(img, 0, channels);
}

}  // namespace

RenderSession::RenderSession(const Scene& scene)
    : mScene(scene), mFeatures(analyzeScene(scene)), mImpl(std::make_unique<Impl>()) {
    GlContext::shared();
    mImpl->gpu = uploadScene(scene);
    GlContext::shared().checkErrors("upload");
}

RenderSession::~RenderSession() = default;

void RenderSession::lightsChanged() {
    uploadLights(mImpl->gpu, mScene);
    mImpl->shadows.reset();
    GlContext::shared().checkErrors("lights");
}

void RenderSession::geometryChanged() {
    mImpl->methods.clear();
    mImpl->gbuffers.clear();
    mImpl->shadows.reset();
    mImpl->gpu = uploadScene(mScene);
    mFeatures = analyzeScene(mScene);
    GlContext::shared().checkErrors("geometry");
}

RenderResult RenderSession::render(const RenderRequest& request) {
    if (request.width < 1 || request.height < 1 || request.width > 16384 || request.height > 16384)
        throw UsageError("--size " + std::to_string(request.width) + "x" + std::to_string(request.height) +
                         ": each side must be in [1, 16384]");
    if (!std::isfinite(request.radius) || request.radius <= 0.f) throw UsageError("--radius must be finite and > 0");
    if (!std::isfinite(request.sky) || request.sky < 0.f) throw UsageError("--sky must be finite and >= 0");
    if (request.backend != "gl" && request.backend != "vdb")
        throw UsageError("--backend " + request.backend + ": expected gl or vdb");

    GlContext& gl = GlContext::shared();
    RenderResult result;
    result.plan = planRender(mFeatures, request);
    const RenderPlan& plan = result.plan;
    const ActiveMethods active = activeMethods(request);
    PassTimer timer(gl.info().gpuTimerQueries);
    const double start = nowMs(), builtBefore = programBuildMsSoFar();
    const View view = makeView(request.camera, request.width, request.height);

    // G-buffer: shared across renders of the same view that reuse what they can.
    std::shared_ptr<GBuffer> gbuffer;
    if (plan.runs(kPassGBuffer)) {
        const std::string key = viewKey(view);
        // A camera path asks for a new view every frame: keep the last few, not every one.
        if (!mImpl->gbuffers.count(key) && mImpl->gbuffers.size() >= kMaxCachedGBuffers) mImpl->gbuffers.clear();
        auto& slot = mImpl->gbuffers[key];
        // A cold render draws its G-buffer too: the rasterizing methods' costs include the
        // raster as the reference's include its primary rays. A G-buffer drawn without
        // materials serves only renders that read none; one with them serves every render.
        if (!slot || !request.reuseSceneData || (plan.gbufferMaterials && !slot->hasMaterials())) {
            slot = std::make_shared<GBuffer>(renderGBuffer(mImpl->gpu, view, timer, plan.gbufferMaterials));
            gl.checkErrors("gbuffer");
            mRunCounts["gbuffer"]++;
        }
        gbuffer = slot;
    }
    GlTexture direct;
    if (plan.runs(kPassShadow)) {
        // Read on every render, not only the first: a session serves many requests (the
        // Python module's), and a key read once would be "unknown" to the next one.
        const int size = rendererSettings().read(request.params).shadowSize;
        if (!mImpl->shadows || mImpl->shadowSize != size) {
            mImpl->shadowSize = size;
            mImpl->shadows = std::make_unique<ShadowMaps>(renderShadowMaps(mImpl->gpu, mScene, size, timer));
            gl.checkErrors("shadow");
            mRunCounts["shadow"]++;
        }
    }
    if (plan.runs(kPassDirect)) {
        direct = computeDirectLighting(*gbuffer, mImpl->gpu, *mImpl->shadows, timer);
        gl.checkErrors("direct");
    }

    // The AO and GI estimators.
    StateStore frame;
    FrameOutputs outputs;
    for (const Method* m : active.list()) {
        MethodContext ctx{plan,     request, mScene,  mFeatures, mImpl->gpu, gbuffer.get(), view,
                          timer,    mImpl->methods, frame, outputs, mRunCounts, result.extra};
        if (direct) ctx.rendererTextures.emplace(std::string(kDirect.name), &direct);
        m->execute(ctx);
    }

    const int w = request.width, h = request.height;
    CompositeOutputs comp;
    if (plan.runs(kPassComposite)) {
        CompositeInputs in;
        in.direct = direct ? &direct : nullptr;
        in.ao = asTexture(outputs, kAo, GL_R32F, w, h);
        in.indirect = asTexture(outputs, kGiIndirect, GL_RGBA32F, w, h);
        in.sky = request.sky;
        comp = composite(*gbuffer, in, timer);
        gl.checkErrors("composite");
    }

    // Read back the requested AOVs.
    const bool lit = active.gi && active.gi->lightsTheImage;
    for (const auto& aov : request.aovs) {
        Image img;
        if (aov == "beauty") img = lit ? resourceImage(outputs, kBeauty, 3, w, h) : channelsOf(readTexture2D(comp.beauty.id(), w, h, 4), 0, 3);
        else if (aov == "ao") img = resourceImage(outputs, kAo, 1, w, h);
        else if (aov == "direct") {
            if (lit) img = resourceImage(outputs, kDirect, 3, w, h);
            else if (direct) img = channelsOf(readTexture2D(direct.id(), w, h, 4), 0, 3);
            else img = Image(w, h, 3, 0.f);
        } else if (aov == "indirect") {
            img = active.gi ? resourceImage(outputs, kGiIndirect, 3, w, h)
                            : channelsOf(readTexture2D(comp.indirect.id(), w, h, 4), 0, 3);
        } else if (aov == "normal") img = channelsOf(readTexture2D(gbuffer->normal.id(), w, h, 4), 0, 3);
        else if (aov == "position") img = channelsOf(readTexture2D(gbuffer->position.id(), w, h, 4), 0, 3);
        else if (aov == "depth") img = channelsOf(readTexture2D(gbuffer->position.id(), w, h, 4), 3, 1);
        else if (aov == "albedo") img = channelsOf(readTexture2D(gbuffer->albedo.id(), w, h, 4), 0, 3);
        else if (aov == "emission") img = channelsOf(readTexture2D(gbuffer->emission.id(), w, h, 4), 0, 3);
        else {
            // A method's own AOV, written under its name.
            const AovInfo* info = findAov(aov);
            if (!info) throw UsageError("unknown AOV '" + aov + "'");
            img = resourceImage(outputs, ResourceId{aov}, info->channels, w, h);
        }
        result.aovs[aov] = std::move(img);
    }
    gl.checkErrors("readback");
    // A key this render did not read, but an earlier render of the same methods read with
    // the same value, went into state this one reused (a cached voxel grid): it is no typo.
    const std::string methods = request.ao + "|" + request.gi + "|";
    const std::vector<std::string> unread = request.params.unusedKeys();
    for (const auto& [key, value] : request.params.values()) {
        const std::string read = methods + key + "=" + value;
        if (std::find(unread.begin(), unread.end(), key) == unread.end()) mImpl->paramsRead.insert(read);
        else if (!mImpl->paramsRead.count(read)) result.unusedParams.push_back(key);
    }
    result.totalMs = nowMs() - start;
    result.programBuildMs = programBuildMsSoFar() - builtBefore;
    result.frameMs = std::max(0.0, result.totalMs - timer.sceneStaticMs() - result.programBuildMs);
    result.frameGpuMs = timer.frameGpuMs();
    result.passes = timer.timings();
    return result;
}

nlohmann::json statsJson(const RenderResult& result, const RenderRequest& request, const Scene& scene) {
    nlohmann::json j;
    const auto& info = GlContext::shared().info();
    j["passes"] = nlohmann::json::array();
    for (const auto& p : result.passes) {
        nlohmann::json e{{"name", p.name}, {"wall_ms", p.wallMs},
                         {"reruns", p.reruns == Reruns::EveryFrame ? "every_frame" : "when_scene_changes"}};
        e["gpu_ms"] = p.gpuMs ? nlohmann::json(*p.gpuMs) : nlohmann::json(nullptr);
        j["passes"].push_back(e);
    }
    j["total_ms"] = result.totalMs;
    j["frame_ms"] = result.frameMs;
    j["program_build_ms"] = result.programBuildMs;
    j["frame_gpu_ms"] = result.frameGpuMs ? nlohmann::json(*result.frameGpuMs) : nlohmann::json(nullptr);
    j["width"] = request.width;
    j["height"] = request.height;
    j["gl_renderer"] = info.renderer;
    j["gl_version"] = info.version;
    j["gl_platform"] = info.platform;
    j["cores"] = std::thread::hardware_concurrency();
    // The process's peak so far: this render's and any earlier one's in the same process.
    j["peak_rss_bytes"] = peakResidentBytes();
    j["scene"] = {{"path", scene.path}, {"triangles", scene.triangles.size()},
                  {"materials", scene.materials.size()}, {"lights", scene.lights.size()}};
    j["ao"] = request.ao;
    j["gi"] = request.gi;
    j["radius"] = request.radius;
    j["seed"] = request.seed;
    j["passes_run"] = result.plan.runNames();
    j["passes_skipped"] = nlohmann::json::array();
    for (const auto& s : result.plan.skipped) j["passes_skipped"].push_back({{"pass", std::string(s.id.name)}, {"reason", s.reason}});
    j["plan_notes"] = result.plan.notes;
    for (auto it = result.extra.begin(); it != result.extra.end(); ++it) j[it.key()] = it.value();
    return j;
}

}  // namespace vct
