// An object that moves between frames: the session uploads the posed triangles and rebuilds
// everything made from them (G-buffer, voxels, the BVH), so a frame after the move is the frame
// a fresh session renders of the posed scene, bit for bit; and the posed vertices are where the
// loader puts the object when the file places it there without an animation.
#include "render/renderer.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "scene/scene_library.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vct;

namespace {

int countOf(const RenderSession& s, const char* pass) {
    auto it = s.passRunCounts().find(pass);
    return it == s.passRunCounts().end() ? 0 : it->second;
}

const std::string kScene = std::string(VCT_SOURCE_DIR) + "/scenes/cornell_moving_box.gltf";

RenderRequest aoRequest(const Scene& scene, const std::string& ao) {
    RenderRequest r;
    r.width = 32;
    r.height = 24;
    r.camera = scene.cameras.front();
    r.voxelRes = 32;
    r.radius = 0.5f;
    r.spp = 8;
    r.ao = ao;
    r.aovs = {"ao"};
    return r;
}

}  // namespace

// The pose at the end of the slide against the file's own box placed there statically: the
// loader's bake of the node transform and the pose of the rest vertices are independent paths.
TEST(MovingObject, APoseMatchesTheObjectPlacedThereWithoutAnimation) {
    Scene scene = loadScene(kScene);
    ASSERT_TRUE(animationMovesGeometry(scene, "box_slide")) << describeMeshAnimations(scene);
    tinygltf::Model model = makeProjectScene("cornell_moving_box").build();
    model.animations.clear();
    int box = -1;
    for (size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].name == "short_box") box = int(n);
    ASSERT_GE(box, 0);
    for (double t : {1.0, 2.0}) {
        const float u = float(t / 2.0);
        const glm::vec3 at = glm::mix(glm::vec3(0.35f, 0.3f, 0.35f), glm::vec3(-0.3f, 0.3f, 0.55f), u);
        model.nodes[size_t(box)].translation = {at.x, at.y, at.z};
        const Scene placed = sceneFromModel(model, "placed.gltf");
        ASSERT_EQ(poseMeshes(scene, "box_slide", t), 1);
        ASSERT_EQ(placed.positions.size(), scene.positions.size());
        float worst = 0.f, worstNormal = 0.f;
        for (size_t v = 0; v < placed.positions.size(); ++v) {
            worst = std::max(worst, glm::length(placed.positions[v] - scene.positions[v]));
            worstNormal = std::max(worstNormal, glm::length(placed.normals[v] - scene.normals[v]));
        }
        EXPECT_LT(worst, 1e-5f) << "at t = " << t;
        EXPECT_LT(worstNormal, 1e-5f) << "at t = " << t;
    }
}

TEST(MovingObject, AMoveRebuildsWhatTheGeometryMadeAndMatchesAFreshSession) {
    Scene scene = loadScene(kScene);
    scene.bounds = animationBounds(scene, "box_slide");
    RenderSession session(scene);
    poseMeshes(scene, "box_slide", 0.0);
    session.geometryChanged();
    const RenderResult vct0 = session.render(aoRequest(scene, "vct"));
    const RenderResult ref0 = session.render(aoRequest(scene, "reference"));
    ASSERT_EQ(countOf(session, "voxelize"), 1);
    const int gbuffers = countOf(session, "gbuffer");
    // The same frame again: nothing is rebuilt.
    EXPECT_EQ(session.render(aoRequest(scene, "vct")).aovs.at("ao").pixels, vct0.aovs.at("ao").pixels);
    EXPECT_EQ(countOf(session, "voxelize"), 1);

    ASSERT_EQ(poseMeshes(scene, "box_slide", 2.0), 1);
    session.geometryChanged();
    const RenderResult vct1 = session.render(aoRequest(scene, "vct"));
    const RenderResult ref1 = session.render(aoRequest(scene, "reference"));
    EXPECT_EQ(countOf(session, "voxelize"), 2) << "a moved object did not voxelize the scene again";
    EXPECT_EQ(countOf(session, "gbuffer"), gbuffers + 1) << "a moved object reused the G-buffer";
    EXPECT_NE(vct1.aovs.at("ao").pixels, vct0.aovs.at("ao").pixels);
    EXPECT_NE(ref1.aovs.at("ao").pixels, ref0.aovs.at("ao").pixels);

    // Nothing stale survives the move: a session made for the posed scene renders the same.
    const Scene posed = scene;
    RenderSession fresh(posed);
    EXPECT_EQ(fresh.render(aoRequest(posed, "vct")).aovs.at("ao").pixels, vct1.aovs.at("ao").pixels);
    EXPECT_EQ(fresh.render(aoRequest(posed, "reference")).aovs.at("ao").pixels, ref1.aovs.at("ao").pixels);
}
