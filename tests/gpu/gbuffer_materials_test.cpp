// The G-buffer drawn without materials (RenderPlan::gbufferMaterials): a render whose passes
// and AOVs read no albedo or emission skips them, and its images are the ones the full
// G-buffer gives. Checked against an independent path: the same request with the albedo AOV
// added, which draws the materials, in a session of its own.
#include "eval/metrics.h"
#include "gl/context.h"
#include "methods/registry.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace vct;

namespace {

RenderRequest smallRequest(const Scene& s) {
    RenderRequest r;
    r.width = r.height = 32;
    r.camera = resolveCamera(s, CameraRequest{}, 1.f);
    r.voxelRes = 32;
    r.spp = 4;
    r.radius = 1.f;
    return r;
}

}  // namespace

TEST(GBufferMaterials, AoAloneDrawsNoMaterialAndGivesTheSameImage) {
    const std::string path = vcttest::sourceDir() + "/scenes/offscreen_overhang.gltf";
    const Scene scene = loadScene(path);
    for (const Method* m : registeredMethods()) {
        if (m->kind != MethodKind::AO) continue;
        RenderRequest r = smallRequest(scene);
        r.ao = m->name;
        r.aovs = {"ao"};
        RenderSession surfaceOnly(scene);
        const RenderResult a = surfaceOnly.render(r);
        r.aovs = {"ao", "albedo"};
        RenderSession full(scene);
        const RenderResult b = full.render(r);
        GlContext::shared().checkErrors("gbuffer materials");
        // The denoised ray tracer's filter weighs neighbours by albedo; the others read the
        // surface alone.
        const bool readsAlbedo = m->name == "rtao-denoised";
        EXPECT_EQ(a.plan.gbufferMaterials, readsAlbedo) << m->name;
        EXPECT_TRUE(b.plan.gbufferMaterials) << m->name;
        EXPECT_EQ(computeErrorMetrics(a.aovs.at("ao"), b.aovs.at("ao")).maxAbs, 0.0) << m->name;
    }
}

TEST(GBufferMaterials, GtaoMultiBounceReadsTheAlbedo) {
    const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    RenderRequest r = smallRequest(scene);
    r.ao = "gtao";
    r.aovs = {"ao"};
    r.params.set("gtao.multibounce", "1");
    RenderSession session(scene);
    const RenderResult bounced = session.render(r);
    EXPECT_TRUE(bounced.plan.gbufferMaterials);
    r.params.set("gtao.multibounce", "0");
    const RenderResult plain = session.render(r);
    EXPECT_FALSE(plain.plan.gbufferMaterials);
    // The red and green walls' albedo lifts the visibility the multi-bounce fit returns: had
    // the pass read a G-buffer without albedo, both images would be the same.
    EXPECT_GT(computeErrorMetrics(bounced.aovs.at("ao"), plain.aovs.at("ao")).maxAbs, 1e-3);
    GlContext::shared().checkErrors("gtao multibounce");
}

TEST(GBufferMaterials, AFullGBufferServesALaterRenderAndNotTheOtherWayRound) {
    const Scene scene = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    RenderSession session(scene);
    RenderRequest r = smallRequest(scene);
    r.ao = "vct";
    r.aovs = {"ao"};
    session.render(r);
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 1);
    // The beauty composites albedo and emission: the view's G-buffer is drawn again, whole.
    r.aovs = {"beauty"};
    const RenderResult lit = session.render(r);
    EXPECT_TRUE(lit.plan.gbufferMaterials);
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 2);
    // ...and serves the AO-only render after it.
    r.aovs = {"ao"};
    session.render(r);
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 2);
    r.aovs = {"albedo"};
    const RenderResult albedo = session.render(r);
    EXPECT_EQ(session.passRunCounts().at("gbuffer"), 2);
    float peak = 0.f;
    for (float v : albedo.aovs.at("albedo").pixels) peak = std::max(peak, v);
    EXPECT_GT(peak, 0.1f) << "the kept G-buffer holds the albedo";
    GlContext::shared().checkErrors("gbuffer cache");
}
