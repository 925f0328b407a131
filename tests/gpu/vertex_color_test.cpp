// Vertex colours (glTF COLOR_0) multiply the base colour in every estimator that reads one:
// the G-buffer, the dense and sparse voxelizers and the path tracer. Checked against
// independent paths: the same colours given as material factors instead must render the
// same images, and the G-buffer's interpolated colour must match the CPU's barycentric one.
// Their alpha, like the material's, takes part in the alpha test everywhere, shadow maps too.
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "scene/texture_sampler.h"
#include "support/run_vct.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace vct;

namespace {

// The Cornell box with every material's base colour moved to its triangles' vertices: the
// factors become white and Scene::colors carries what they were.
Scene coloursFromMaterials(const Scene& s) {
    Scene out = s;
    out.colors.assign(s.positions.size(), glm::vec4(1.f));
    std::vector<int> owner(s.positions.size(), -1);
    for (size_t t = 0; t < s.triangles.size(); ++t) {
        const uint32_t m = s.triangleMaterial[t];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = s.triangles[t][k];
            // A vertex shared by two materials could not carry both colours.
            EXPECT_TRUE(owner[v] < 0 || owner[v] == int(m)) << "vertex " << v;
            owner[v] = int(m);
            out.colors[v] = s.materials[m].baseColorFactor;
        }
    }
    for (Material& m : out.materials) m.baseColorFactor = glm::vec4(1.f);
    return out;
}

RenderResult renderBox(const Scene& s, const std::string& gi, const std::string& backend) {
    RenderSession session(s);
    RenderRequest r;
    r.width = r.height = 40;
    r.camera = resolveCamera(s, CameraRequest{}, 1.f);
    r.gi = gi;
    r.backend = backend;
    r.voxelRes = 32;
    r.spp = 4;
    r.seed = 3;
    r.aovs = {"albedo", "indirect", "beauty"};
    RenderResult out = session.render(r);
    GlContext::shared().checkErrors(("vertex colours, " + gi + " " + backend).c_str());
    return out;
}

}  // namespace

TEST(VertexColors, ColoursOnVerticesRenderAsTheSameColoursOnMaterials) {
    const Scene factors = loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf");
    ASSERT_TRUE(factors.colors.empty());
    const Scene vertices = coloursFromMaterials(factors);
    struct Estimator {
        std::string gi, backend;
    };
    for (const Estimator& e : {Estimator{"vct", "gl"}, Estimator{"vct", "vdb"}, Estimator{"reference", "gl"}}) {
        const RenderResult a = renderBox(factors, e.gi, e.backend);
        const RenderResult b = renderBox(vertices, e.gi, e.backend);
        const std::string what = e.gi + " " + e.backend;
        // The red and green walls make the albedo AOV far from grey: a pass that ignored the
        // vertex colours would see white walls.
        EXPECT_LT(computeErrorMetrics(b.aovs.at("albedo"), a.aovs.at("albedo")).maxAbs, 1e-6) << what;
        for (const char* aov : {"indirect", "beauty"}) {
            const Image& ia = a.aovs.at(aov);
            double peak = 0.0;
            for (float v : ia.pixels) peak = std::max(peak, double(v));
            ASSERT_GT(peak, 0.0) << what << " " << aov;
            EXPECT_LT(computeErrorMetrics(b.aovs.at(aov), ia).maxAbs, 1e-4 * peak) << what << " " << aov;
        }
    }
    // And the colours count: the white-factored box without them is another image.
    Scene white = vertices;
    white.colors.clear();
    EXPECT_GT(computeErrorMetrics(renderBox(white, "vct", "gl").aovs.at("indirect"),
                                  renderBox(factors, "vct", "gl").aovs.at("indirect"))
                  .maxAbs,
              1e-2);
}

TEST(VertexColors, TheGBufferInterpolatesThemAsTheBarycentricsDo) {
    // One quad facing the camera, a different colour at each corner.
    Scene s;
    const uint32_t m = vcttest::addMaterial(s, glm::vec3(1.f));
    vcttest::addQuad(s, glm::vec3(-1.f, -1.f, 0.f), glm::vec3(2.f, 0.f, 0.f), glm::vec3(0.f, 2.f, 0.f), m);
    s.colors = {glm::vec4(1.f, 0.f, 0.f, 1.f), glm::vec4(0.f, 1.f, 0.f, 1.f), glm::vec4(0.f, 0.f, 1.f, 1.f),
                glm::vec4(1.f, 1.f, 1.f, 1.f)};
    vcttest::finish(s);
    RenderSession session(s);
    RenderRequest r;
    r.width = r.height = 32;
    r.camera = vcttest::lookAt(s, glm::vec3(0.f, 0.f, 3.f), glm::vec3(0.f), 30.f);
    r.aovs = {"albedo", "position"};
    const RenderResult out = session.render(r);
    GlContext::shared().checkErrors("vertex colour interpolation");
    const Image& albedo = out.aovs.at("albedo");
    const Image& position = out.aovs.at("position");
    int checked = 0;
    double worst = 0.0;
    for (int y = 0; y < albedo.height; ++y)
        for (int x = 0; x < albedo.width; ++x) {
            const glm::vec3 p(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2));
            if (std::abs(p.x) > 0.95f || std::abs(p.y) > 0.95f) continue;  // background and the quad's edge
            // The quad's triangles: (0, 1, 2) below the diagonal x = y, (0, 2, 3) above it.
            const glm::vec2 q = 0.5f * (glm::vec2(p) + 1.f);  // (0, 0) at corner 0, (1, 1) at corner 2
            if (std::abs(q.x - q.y) < 0.05f) continue;      // the diagonal: either triangle
            const uint32_t tri = q.x > q.y ? 0u : 1u;
            const glm::vec3 b = q.x > q.y ? glm::vec3(1.f - q.x, q.x - q.y, q.y) : glm::vec3(1.f - q.y, q.x, q.y - q.x);
            const glm::vec4 expected = vertexColorAt(s, tri, b);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(albedo.at(x, y, c) - expected[c])));
            ++checked;
        }
    EXPECT_GT(checked, 200);
    EXPECT_LT(worst, 2e-3);
}

TEST(VertexColors, TheirAlphaTakesPartInTheAlphaTest) {
    // A floor under a plate whose vertex alpha is 0 and whose material is alpha-masked: the
    // plate is cut away everywhere, so every estimator sees the floor alone.
    Scene open;
    const uint32_t floorMaterial = vcttest::addMaterial(open, glm::vec3(0.8f));
    vcttest::addQuad(open, glm::vec3(-2.f, 0.f, 2.f), glm::vec3(4.f, 0.f, 0.f), glm::vec3(0.f, 0.f, -4.f),
                     floorMaterial);
    Scene cut = open;
    Material masked;
    masked.alphaMask = true;
    masked.alphaCutoff = 0.5f;
    cut.materials.push_back(masked);
    vcttest::addQuad(cut, glm::vec3(-0.5f, 0.3f, 0.5f), glm::vec3(1.f, 0.f, 0.f), glm::vec3(0.f, 0.f, -1.f),
                     uint32_t(cut.materials.size() - 1));
    cut.colors.assign(cut.positions.size(), glm::vec4(1.f));
    for (size_t v = 4; v < 8; ++v) cut.colors[v] = glm::vec4(1.f, 1.f, 1.f, 0.f);
    Scene solid = cut;  // the same plate, opaque by its vertex alpha
    for (size_t v = 4; v < 8; ++v) solid.colors[v].a = 1.f;
    vcttest::finish(open);
    vcttest::finish(cut);
    vcttest::finish(solid);
    auto ao = [](const Scene& s, const std::string& method, const std::string& backend) {
        RenderSession session(s);
        RenderRequest r;
        r.width = r.height = 24;
        r.camera = vcttest::lookAt(s, glm::vec3(0.f, 4.f, 0.01f), glm::vec3(0.f), 40.f);
        r.ao = method;
        r.backend = backend;
        r.voxelRes = 32;
        r.spp = 16;
        r.radius = 1.f;
        r.params.set("vct.region", "scene");
        r.aovs = {"ao"};
        const RenderResult out = session.render(r);
        GlContext::shared().checkErrors(("vertex alpha, " + method + " " + backend).c_str());
        return out.aovs.at("ao");
    };
    struct Estimator {
        std::string method, backend;
    };
    for (const Estimator& e : {Estimator{"reference", "gl"}, Estimator{"vct", "gl"}, Estimator{"vct", "vdb"}}) {
        const std::string what = e.method + " " + e.backend;
        // The floor's bounds differ with the plate (the grid fits the scene): compare the cut
        // plate against the solid one's, which must differ, and against the floor alone
        // where the grid is the same (the reference has none).
        EXPECT_GT(computeErrorMetrics(ao(solid, e.method, e.backend), ao(cut, e.method, e.backend)).maxAbs, 0.1)
            << what;
        if (e.method == "reference")
            EXPECT_EQ(computeErrorMetrics(ao(cut, e.method, e.backend), ao(open, e.method, e.backend)).maxAbs, 0.0)
                << what;
        else {
            const Image a = ao(cut, e.method, e.backend);
            double darkest = 1.0;
            for (float v : a.pixels) darkest = std::min(darkest, double(v));
            EXPECT_GT(darkest, 0.9) << what << ": the floor alone is open";
        }
    }
}

TEST(VertexColors, TexelsTheAlphaTestCutsCastNoShadow) {
    // A floor lit from straight above, under a plate whose texels are all cut away: by the
    // material's alpha (factor 0) or by its vertex colours' (0): the shadow maps see the
    // floor alone, as the G-buffer and the ray tracer do; the same plate kept casts a shadow.
    Scene open;
    const uint32_t floorMaterial = vcttest::addMaterial(open, glm::vec3(0.8f));
    vcttest::addQuad(open, glm::vec3(-2.f, 0.f, 2.f), glm::vec3(4.f, 0.f, 0.f), glm::vec3(0.f, 0.f, -4.f),
                     floorMaterial);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::vec3(0.f, -1.f, 0.f);
    sun.color = glm::vec3(2.f);
    open.lights.push_back(sun);
    auto withPlate = [&](float materialAlpha, float vertexAlpha) {
        Scene s = open;
        Material plate;
        plate.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, materialAlpha);
        plate.alphaMask = true;
        plate.alphaCutoff = 0.5f;
        plate.doubleSided = true;
        s.materials.push_back(plate);
        vcttest::addQuad(s, glm::vec3(-0.5f, 0.5f, 0.5f), glm::vec3(1.f, 0.f, 0.f), glm::vec3(0.f, 0.f, -1.f),
                         uint32_t(s.materials.size() - 1));
        s.colors.assign(s.positions.size(), glm::vec4(1.f));
        for (size_t v = 4; v < 8; ++v) s.colors[v].a = vertexAlpha;
        vcttest::finish(s);
        return s;
    };
    vcttest::finish(open);
    // From the side, below the plate's height: the floor under the plate is in view.
    auto direct = [](const Scene& s) {
        RenderSession session(s);
        RenderRequest r;
        r.width = r.height = 32;
        r.camera = vcttest::lookAt(s, glm::vec3(0.f, 0.3f, 2.5f), glm::vec3(0.f, 0.f, 0.f), 50.f);
        r.aovs = {"direct"};
        const RenderResult out = session.render(r);
        GlContext::shared().checkErrors("alpha-tested shadows");
        return out.aovs.at("direct");
    };
    const Image floorAlone = direct(open);
    const double shadowed = computeErrorMetrics(direct(withPlate(1.f, 1.f)), floorAlone).maxAbs;
    EXPECT_GT(shadowed, 0.1);  // the kept plate's shadow on the floor
    EXPECT_LT(computeErrorMetrics(direct(withPlate(0.f, 1.f)), floorAlone).maxAbs, 0.01 * shadowed);
    EXPECT_LT(computeErrorMetrics(direct(withPlate(1.f, 0.f)), floorAlone).maxAbs, 0.01 * shadowed);
}
