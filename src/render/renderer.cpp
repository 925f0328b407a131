#include "render/renderer.h"

#include "ao/screen_space_ao.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "raster/gbuffer_pass.h"
#include "raster/lighting_pass.h"
#include "raster/shadow_pass.h"
#include "render/gpu_scene.h"
#include "render/method_passes.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace vct {

struct RenderSession::Impl {
    GpuScene gpu;
    std::map<std::string, std::shared_ptr<GBuffer>> gbuffers;  // keyed by camera + size
    std::unique_ptr<ShadowMaps> shadows;
    MethodCache methods;  // voxel grids and other per-method shared state
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

}  // namespace

RenderSession::RenderSession(const Scene& scene)
    : mScene(scene), mFeatures(analyzeScene(scene)), mImpl(std::make_unique<Impl>()) {
    GlContext::shared();
    mImpl->gpu = uploadScene(scene);
    GlContext::shared().checkErrors("upload");
}

RenderSession::~RenderSession() = default;

RenderResult RenderSession::render(const RenderRequest& request) {
    if (request.width < 1 || request.height < 1 || request.width > 16384 || request.height > 16384)
        throw std::invalid_argument("--size " + std::to_string(request.width) + "x" + std::to_string(request.height) +
                                    ": each side must be in [1, 16384]");
    if (!std::isfinite(request.radius) || request.radius <= 0.f)
        throw std::invalid_argument("--radius must be finite and > 0");
    if (!std::isfinite(request.sky) || request.sky < 0.f)
        throw std::invalid_argument("--sky must be finite and >= 0");
    if (request.backend != "gl" && request.backend != "vdb")
        throw std::invalid_argument("--backend " + request.backend + ": expected gl or vdb");

    GlContext& gl = GlContext::shared();
    RenderResult result;
    result.plan = planRender(mFeatures, request);
    const RenderPlan& plan = result.plan;
    PassTimer timer(gl.info().gpuTimerQueries);
    const double start = nowMs();
    const View view = makeView(request.camera, request.width, request.height);

    // G-buffer: shared across renders of the same view.
    std::shared_ptr<GBuffer> gbuffer;
    if (plan.runs("gbuffer")) {
        auto& slot = mImpl->gbuffers[viewKey(view)];
        if (!slot) {
            slot = std::make_shared<GBuffer>(renderGBuffer(mImpl->gpu, view, timer));
            gl.checkErrors("gbuffer");
            mRunCounts["gbuffer"]++;
        }
        gbuffer = slot;
    }
    GlTexture direct;
    if (plan.runs("shadow")) {
        if (!mImpl->shadows) {
            const int size = request.params.getInt("shadow.size", 1024, 16, 8192, "shadow map texels per side");
            mImpl->shadows = std::make_unique<ShadowMaps>(renderShadowMaps(mImpl->gpu, mScene, size, timer));
            gl.checkErrors("shadow");
            mRunCounts["shadow"]++;
        }
    }
    if (plan.runs("direct")) {
        direct = computeDirectLighting(*gbuffer, mImpl->gpu, *mImpl->shadows, timer);
        gl.checkErrors("direct");
    }

    // AO and GI estimators.
    MethodOutputs m = runMethodPasses(plan, request, mScene, mImpl->gpu, gbuffer.get(), view, timer,
                                      mImpl->methods, mRunCounts, result.extra);

    // CPU methods (the reference, the sparse backend) hand images: the composite reads textures.
    if (plan.runs("composite")) {
        if (!m.ao && !m.aoImage.empty()) {
            m.ao = createTexture2D(GL_R32F, request.width, request.height);
            uploadTexture2D(m.ao.id(), m.aoImage);
        }
        if (!m.indirect && !m.indirectImage.empty()) {
            m.indirect = createTexture2D(GL_RGBA32F, request.width, request.height);
            uploadTexture2D(m.indirect.id(), m.indirectImage);
        }
    }
    CompositeOutputs comp;
    if (plan.runs("composite")) {
        CompositeInputs in;
        in.direct = direct ? &direct : nullptr;
        in.ao = m.ao ? &m.ao : nullptr;
        in.indirect = m.indirect ? &m.indirect : nullptr;
        in.sky = request.sky;
        comp = composite(*gbuffer, in, timer);
        gl.checkErrors("composite");
    }

    // Read back the requested AOVs.
    const int w = request.width, h = request.height;
    for (const auto& aov : request.aovs) {
        Image img;
        if (aov == "beauty") img = m.ptBeauty.empty() ? channelsOf(readTexture2D(comp.beauty.id(), w, h, 4), 0, 3) : m.ptBeauty;
        else if (aov == "ao") img = !m.aoImage.empty() ? m.aoImage : readTexture2D(m.ao.id(), w, h, 1);
        else if (aov == "ao_stderr") img = m.aoStderr;
        else if (aov == "indirect_stderr") img = m.indirectStderr;
        else if (aov == "direct") {
            if (!m.ptDirect.empty()) img = m.ptDirect;
            else if (direct) img = channelsOf(readTexture2D(direct.id(), w, h, 4), 0, 3);
            else img = Image(w, h, 3, 0.f);
        } else if (aov == "indirect") {
            if (!m.indirectImage.empty()) img = m.indirectImage;
            else img = channelsOf(readTexture2D((m.indirect ? m.indirect : comp.indirect).id(), w, h, 4), 0, 3);
        } else if (aov == "normal") img = channelsOf(readTexture2D(gbuffer->normal.id(), w, h, 4), 0, 3);
        else if (aov == "position") img = channelsOf(readTexture2D(gbuffer->position.id(), w, h, 4), 0, 3);
        else if (aov == "depth") img = channelsOf(readTexture2D(gbuffer->position.id(), w, h, 4), 3, 1);
        else if (aov == "albedo") img = channelsOf(readTexture2D(gbuffer->albedo.id(), w, h, 4), 0, 3);
        else if (aov == "emission") img = channelsOf(readTexture2D(gbuffer->emission.id(), w, h, 4), 0, 3);
        else if (aov.rfind("voxel_", 0) == 0) img = m.voxelViews.at(aov);
        else throw std::invalid_argument("unknown AOV '" + aov + "'");
        result.aovs[aov] = std::move(img);
    }
    gl.checkErrors("readback");
    result.totalMs = nowMs() - start;
    result.passes = timer.timings();
    return result;
}

nlohmann::json statsJson(const RenderResult& result, const RenderRequest& request, const Scene& scene) {
    nlohmann::json j;
    const auto& info = GlContext::shared().info();
    j["passes"] = nlohmann::json::array();
    for (const auto& p : result.passes) {
        nlohmann::json e{{"name", p.name}, {"wall_ms", p.wallMs}};
        e["gpu_ms"] = p.gpuMs ? nlohmann::json(*p.gpuMs) : nlohmann::json(nullptr);
        j["passes"].push_back(e);
    }
    j["total_ms"] = result.totalMs;
    j["width"] = request.width;
    j["height"] = request.height;
    j["gl_renderer"] = info.renderer;
    j["gl_version"] = info.version;
    j["gl_platform"] = info.platform;
    j["cores"] = std::thread::hardware_concurrency();
    j["scene"] = {{"path", scene.path}, {"triangles", scene.triangles.size()},
                  {"materials", scene.materials.size()}, {"lights", scene.lights.size()}};
    j["ao"] = request.ao;
    j["gi"] = request.gi;
    j["radius"] = request.radius;
    j["seed"] = request.seed;
    j["passes_run"] = result.plan.runNames();
    j["passes_skipped"] = nlohmann::json::array();
    for (const auto& s : result.plan.skipped) j["passes_skipped"].push_back({{"pass", s.name}, {"reason", s.reason}});
    j["plan_notes"] = result.plan.notes;
    for (auto it = result.extra.begin(); it != result.extra.end(); ++it) j[it.key()] = it.value();
    return j;
}

}  // namespace vct
