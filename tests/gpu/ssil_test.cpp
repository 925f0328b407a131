// Screen-space indirect light with visibility bitmasks (src/ssil): an open plane under the sky
// reflects albedo x sky, the plan feeds it the direct light, and on the Cornell box its mean
// indirect light is compared with the path tracer's one-bounce indirect light.
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/plan.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "support/run_vct.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

using namespace vct;

namespace {

Image surfaceMask(const Image& depth) {
    Image m(depth.width, depth.height, 1);
    for (size_t i = 0; i < depth.pixels.size(); ++i) m.pixels[i] = depth.pixels[i] > 0.f ? 1.f : 0.f;
    return m;
}

RenderRequest requestFor(const Scene& s, int size) {
    RenderRequest r;
    r.width = r.height = size;
    r.camera = resolveCamera(s, CameraRequest{}, 1.f);
    return r;
}

}  // namespace

TEST(Ssil, ReadsTheDirectLightOfLitScenes) {
    SceneFeatures lit;
    lit.triangles = 10;
    lit.lights = 1;
    RenderRequest r;
    r.gi = "ssil";
    r.aovs = {"indirect"};
    RenderPlan p = planRender(lit, r);
    for (const char* pass : {"gbuffer", "shadow", "direct", "ssil", "ssil_atrous"})
        EXPECT_TRUE(p.runs(PassId{pass})) << pass << "\n" << describePlan(p);
    SceneFeatures dark = lit;
    dark.lights = 0;
    p = planRender(dark, r);
    EXPECT_TRUE(p.runs(PassId{"ssil"}));
    EXPECT_FALSE(p.runs(PassId{"direct"}));
    r.params.set("ssil.filter", "0");
    EXPECT_FALSE(planRender(dark, r).runs(PassId{"ssil_atrous"}));
}

// Nothing on screen rises above the plane, so every sector is clear: indirect = albedo x sky
// (the sector measures sum to 1 over the hemisphere), whatever the sun does.
TEST(Ssil, OpenPlaneReflectsTheSky) {
    Scene s = loadScene(vcttest::sourceDir() + "/scenes/open_plane.gltf");
    RenderSession session(s);
    RenderRequest r = requestFor(s, 64);
    r.gi = "ssil";
    r.sky = 0.7f;
    r.aovs = {"indirect", "albedo", "depth"};
    RenderResult res = session.render(r);
    GlContext::shared().checkErrors("ssil");
    const Image mask = surfaceMask(res.aovs.at("depth"));
    const double mean = imageMean(res.aovs.at("indirect"), &mask);
    const double expected = r.sky * imageMean(res.aovs.at("albedo"), &mask);
    std::printf("[ssil] open plane: mean indirect %.4f, albedo x sky %.4f\n", mean, expected);
    EXPECT_NEAR(mean / expected, 1.0, 0.02);
}

// The Cornell box (its own camera sees the whole open box) against the path tracer with
// reference.bounces = 2: light after at most two reflections, so emission after one or two,
// the point light after two (its one is the direct term), the sky after one or two. SSIL
// gathers the lit G-buffer (direct + emission) once, so it has the emission after one
// reflection, the point light after two and the sky after one, but not the emission's or the
// sky's second reflection: light that reaches p only by way of a surface lit indirectly.
// Measured (64 px, defaults; reference 256 spp): with the sky (1, the default) the mean is
// +6.1 % of the path tracer's, RMSE 44 % of the mean; without it -14.1 %, RMSE 100 %
// (unfiltered: -4.7 %, RMSE 193 %: the luminance term of the filter drops part of the rare
// bright samples that hit the small, 8x emissive panel; pt-denoised at 4 spp and 2 bounces:
// -10.7 %, RMSE 37 %). Held to: within 10 % with the sky, 20 % without.
TEST(Ssil, CornellBoxAgainstOneBouncePathTracing) {
    Scene s = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    RenderSession session(s);
    for (float sky : {1.f, 0.f}) {
        RenderRequest r = requestFor(s, 64);
        r.sky = sky;
        r.gi = "reference";
        r.spp = 256;
        r.params.set("reference.bounces", "2");
        r.aovs = {"indirect", "indirect_stderr", "depth"};
        RenderResult ref = session.render(r);
        const Image mask = surfaceMask(ref.aovs.at("depth"));
        const double refMean = imageMean(ref.aovs.at("indirect"), &mask);
        r.params = ParamMap();
        r.gi = "ssil";
        r.aovs = {"indirect"};
        RenderResult res = session.render(r);
        GlContext::shared().checkErrors("ssil");
        const Image& indirect = res.aovs.at("indirect");
        const double mean = imageMean(indirect, &mask);
        const ErrorMetrics e = computeErrorMetrics(indirect, ref.aovs.at("indirect"), &mask, -1, 1.0);
        std::printf("[ssil] cornell_box sky %.0f: mean indirect %.4f vs path tracer (bounces 2) %.4f: %+.1f%%, rmse "
                    "%.4f (%.1f%% of the mean), reference stderr %.4f\n",
                    sky, mean, refMean, 100.0 * (mean / refMean - 1.0), e.rmse, 100.0 * e.rmse / refMean,
                    imageMean(ref.aovs.at("indirect_stderr"), &mask));
        EXPECT_LT(std::abs(mean / refMean - 1.0), sky > 0.f ? 0.10 : 0.20) << "sky " << sky;
    }
}
