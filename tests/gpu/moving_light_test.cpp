// A light that moves between frames: the session uploads it, renders new shadow maps, and VCT
// injects and bounces anew into the voxels it keeps; nothing upstream of injection (the
// G-buffer, the voxelization) runs again, and the indirect light follows the light.
#include "render/renderer.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vct;

namespace {

int countOf(const RenderSession& s, const char* pass) {
    auto it = s.passRunCounts().find(pass);
    return it == s.passRunCounts().end() ? 0 : it->second;
}

bool ran(const RenderResult& r, const std::string& pass) {
    for (const PassTiming& p : r.passes)
        if (p.name == pass) return true;
    return false;
}

}  // namespace

TEST(MovingLight, RerunsInjectionAndNothingUpstreamOfIt) {
    Scene scene = loadScene(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_moving_light.gltf");
    ASSERT_TRUE(animationMovesLights(scene, "light_sweep")) << describeLightAnimations(scene);
    RenderSession session(scene);
    RenderRequest r;
    r.width = r.height = 32;
    r.camera = scene.cameras.front();
    r.voxelRes = 32;
    r.sky = 0.f;
    r.gi = "vct";
    r.aovs = {"indirect", "direct"};
    poseLights(scene, "light_sweep", 0.0);
    session.lightsChanged();
    const RenderResult a = session.render(r);
    ASSERT_EQ(countOf(session, "voxelize"), 1);
    ASSERT_EQ(countOf(session, "inject"), 1);
    const int gbuffers = countOf(session, "gbuffer"), shadows = countOf(session, "shadow");

    // The same frame again: nothing of the scene reruns.
    const RenderResult still = session.render(r);
    EXPECT_EQ(countOf(session, "inject"), 1);
    EXPECT_EQ(still.aovs.at("indirect").pixels, a.aovs.at("indirect").pixels);

    const glm::vec3 before = scene.lights[0].position;
    ASSERT_EQ(poseLights(scene, "light_sweep", 2.0), 1);
    ASSERT_GT(glm::length(scene.lights[0].position - before), 0.3f);
    session.lightsChanged();
    const RenderResult b = session.render(r);
    EXPECT_EQ(countOf(session, "voxelize"), 1) << "a moved light voxelized the scene again";
    EXPECT_EQ(countOf(session, "gbuffer"), gbuffers) << "a moved light rasterized the G-buffer again";
    EXPECT_EQ(countOf(session, "inject"), 2);
    EXPECT_EQ(countOf(session, "shadow"), shadows + 1);
    EXPECT_TRUE(ran(b, "inject"));
    EXPECT_FALSE(ran(b, "voxelize"));
    // The light moved: direct and indirect light change.
    double changeDirect = 0.0, changeIndirect = 0.0;
    for (size_t i = 0; i < a.aovs.at("direct").pixels.size(); ++i) {
        changeDirect += std::abs(a.aovs.at("direct").pixels[i] - b.aovs.at("direct").pixels[i]);
        changeIndirect += std::abs(a.aovs.at("indirect").pixels[i] - b.aovs.at("indirect").pixels[i]);
    }
    EXPECT_GT(changeDirect, 1.0);
    EXPECT_GT(changeIndirect, 0.1);

    // Back where it was: the same radiance as the first frame, injected again.
    poseLights(scene, "light_sweep", 0.0);
    session.lightsChanged();
    const RenderResult c = session.render(r);
    EXPECT_EQ(countOf(session, "voxelize"), 1);
    EXPECT_EQ(c.aovs.at("indirect").pixels, a.aovs.at("indirect").pixels);
}
