// Quality of voxel cone tracing as a whole (issue 6): AO converges towards the ray-traced
// reference as the voxel grid refines, indirect light keeps its energy across resolutions,
// the Cornell box's indirect light is within a measured tolerance of the reference, the
// coloured walls bleed in the right direction, and renders are deterministic. Every
// comparison is against the Embree reference (an independent path) or between resolutions.
#include "eval/metrics.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "support/run_vct.h"
#include "support/test_scenes.h"
#include "cone/cone_bounce.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>

using namespace vct;

namespace {

Scene cornellBox() { return loadScene(vcttest::sourceDir() + "/scenes/cornell_box.gltf"); }

RenderRequest requestFor(const Scene& s, int size) {
    RenderRequest r;
    r.width = r.height = size;
    r.camera = resolveCamera(s, CameraRequest{}, 1.f);  // the file's own camera
    return r;
}

// Valid (non-sky) pixels: linear depth > 0.
Image surfaceMask(const Image& depth) {
    Image m(depth.width, depth.height, 1);
    for (size_t i = 0; i < depth.pixels.size(); ++i) m.pixels[i] = depth.pixels[i] > 0.f ? 1.f : 0.f;
    return m;
}

RenderResult renderChecked(RenderSession& session, const RenderRequest& r, const char* what) {
    RenderResult result = session.render(r);
    GlContext::shared().checkErrors(what);
    return result;
}

// The mean RGB of `indirect` over floor pixels (world y near 0) on one side of x = 0:
// side < 0 selects x < -0.5 (the red wall at x = -1), side > 0 selects x > 0.5 (green).
glm::dvec3 floorMean(const Image& indirect, const Image& position, int side) {
    glm::dvec3 sum(0.0);
    size_t n = 0;
    for (int y = 0; y < position.height; ++y)
        for (int x = 0; x < position.width; ++x) {
            const float px = position.at(x, y, 0), py = position.at(x, y, 1);
            if (std::abs(py) > 0.01f) continue;
            if (side < 0 ? px >= -0.5f : px <= 0.5f) continue;
            sum += glm::dvec3(indirect.at(x, y, 0), indirect.at(x, y, 1), indirect.at(x, y, 2));
            ++n;
        }
    EXPECT_GT(n, 20u) << "too few floor pixels on side " << side;
    return n ? sum / double(n) : sum;
}

// Cornell box renders shared by the energy, tolerance and bleeding tests (one session: the
// G-buffer is rasterized once; each voxel resolution voxelizes once).
struct CornellRenders {
    Scene scene = cornellBox();
    std::unique_ptr<RenderSession> session;
    Image mask, position;
    Image reference, referenceStderr;       // --gi reference indirect, its per-pixel stderr
    Image referenceMatched;                 // the same with reference.bounces = 3 (VCT's default depth)
    std::map<int, Image> vct;               // voxelRes -> --gi vct indirect
};

constexpr int kCornellSize = 64;
constexpr int kCornellSpp = 256;

CornellRenders& cornell() {
    static std::unique_ptr<CornellRenders> c;
    if (c) return *c;
    c = std::make_unique<CornellRenders>();
    c->session = std::make_unique<RenderSession>(c->scene);
    RenderRequest r = requestFor(c->scene, kCornellSize);
    r.gi = "reference";
    r.spp = kCornellSpp;
    r.aovs = {"indirect", "indirect_stderr", "depth", "position"};
    RenderResult ref = renderChecked(*c->session, r, "reference_gi");
    c->reference = ref.aovs.at("indirect");
    c->referenceStderr = ref.aovs.at("indirect_stderr");
    c->mask = surfaceMask(ref.aovs.at("depth"));
    c->position = ref.aovs.at("position");
    // vct.bounces = 1 (the default) carries light over at most three reflections: direct into
    // the voxels, one voxel bounce, the gather at the pixel; reference.bounces counts them too.
    r.params.set("reference.bounces", std::to_string(kDefaultVctBounces + 2));
    c->referenceMatched = renderChecked(*c->session, r, "reference_gi").aovs.at("indirect");
    r.params = ParamMap();
    r.gi = "vct";
    r.aovs = {"indirect"};
    for (int res : {32, 64, 128}) {
        r.voxelRes = res;
        c->vct[res] = renderChecked(*c->session, r, "cone_gi").aovs.at("indirect");
    }
    return *c;
}

}  // namespace

// AO error against the reference falls as the grid refines 32 -> 64 -> 128 on
// floor_suzanne (its own camera, R = 0.5 m: 0.31, 0.16, 0.08 m voxels on its 10 m floor).
TEST(VctQuality, AoErrorFallsWithVoxelResolution) {
    const std::string path = vcttest::sharedScenesDir() + "/floor_suzanne.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "floor_suzanne.glb not found at " << path;
    Scene s = loadScene(path);
    RenderSession session(s);
    RenderRequest r = requestFor(s, 64);
    r.radius = 0.5f;
    r.ao = "reference";
    r.spp = 256;
    r.aovs = {"ao", "ao_stderr", "depth"};
    RenderResult ref = renderChecked(session, r, "reference_ao");
    const Image mask = surfaceMask(ref.aovs.at("depth"));
    const double noise = imageMean(ref.aovs.at("ao_stderr"), &mask);
    r.ao = "vct";
    r.aovs = {"ao"};
    std::map<int, ErrorMetrics> err;
    for (int res : {32, 64, 128}) {
        r.voxelRes = res;
        err[res] = computeErrorMetrics(renderChecked(session, r, "cone_ao").aovs.at("ao"), ref.aovs.at("ao"), &mask);
        std::printf("[vct quality] floor_suzanne AO R=0.5 64px voxelRes %3d: rmse %.4f mae %.4f bias %+.4f "
                    "(reference mean stderr %.4f)\n",
                    res, err[res].rmse, err[res].mae, err[res].bias, noise);
    }
    EXPECT_LT(err[64].rmse, err[32].rmse);
    EXPECT_LT(err[128].rmse, err[64].rmse);
}

// Doubling the resolution changes the mean indirect radiance by less than 10% (issue 6;
// injection is normalized by voxel footprint: BRIEF section 3). Measured (64 px, defaults):
// 0.3605, 0.3699, 0.3856 at 32, 64, 128: +2.6% then +4.2%. Two fixes brought the second step
// down from +13.2%: directional opacity blended as optical depth (cone_blendDirectional), and
// radiance seen from behind passing nothing (vox_facingWeight).
TEST(VctQuality, IndirectEnergyIndependentOfResolution) {
    CornellRenders& c = cornell();
    std::map<int, double> mean;
    for (const auto& [res, img] : c.vct) {
        mean[res] = imageMean(img, &c.mask);
        std::printf("[vct quality] cornell_box mean indirect voxelRes %3d: %.4f\n", res, mean[res]);
    }
    EXPECT_GT(mean[32], 0.0);
    EXPECT_LT(std::abs(mean[64] / mean[32] - 1.0), 0.10) << "32 -> 64";
    EXPECT_LT(std::abs(mean[128] / mean[64] - 1.0), 0.10) << "64 -> 128";
}

// The Cornell box's indirect light against --gi reference (256 spp, 64 px) with VCT's
// defaults (one extra bounce in the voxels). Light from the emissive panel is indirect in
// both (BRIEF section 1). Measured at 64^3 / 128^3: against the 4-bounce reference, mean
// -20.4% / -17.0%, RMSE 32% / 30% of the reference mean (its own per-pixel noise: 6.5%);
// against the bounce-matched reference (reference.bounces = 3), mean -13.9% / -10.3%; the
// rest is the light of the fourth and later reflections. Stated tolerance: mean within 22%
// of the 4-bounce and 15% of the matched reference, RMSE below 35% of the reference mean,
// and the mean's error shrinks from 64^3 to 128^3.
TEST(VctQuality, CornellIndirectNearReference) {
    CornellRenders& c = cornell();
    const double refMean = imageMean(c.reference, &c.mask);
    const double refNoise = imageMean(c.referenceStderr, &c.mask);
    ASSERT_GT(refMean, 0.0);
    std::map<int, double> relError;
    for (const auto& [res, img] : c.vct) {
        const ErrorMetrics e = computeErrorMetrics(img, c.reference, &c.mask, -1, 1.0);
        const double mean = imageMean(img, &c.mask);
        std::printf("[vct quality] cornell_box indirect voxelRes %3d: mean %.4f ref %.4f (rel %+.1f%%) rmse %.4f "
                    "(%.1f%% of ref mean) mae %.4f ref stderr %.4f\n",
                    res, mean, refMean, 100.0 * (mean / refMean - 1.0), e.rmse, 100.0 * e.rmse / refMean, e.mae,
                    refNoise);
        const double matchedMean = imageMean(c.referenceMatched, &c.mask);
        const ErrorMetrics em = computeErrorMetrics(img, c.referenceMatched, &c.mask, -1, 1.0);
        std::printf("[vct quality]   against reference.bounces = %d: mean %.4f (rel %+.1f%%) rmse %.4f\n",
                    kDefaultVctBounces + 2, matchedMean, 100.0 * (mean / matchedMean - 1.0), em.rmse);
        if (res >= 64) {
            EXPECT_LT(std::abs(mean / matchedMean - 1.0), 0.15) << "voxelRes " << res << " (matched)";
        }
        relError[res] = std::abs(mean / refMean - 1.0);
        if (res < 64) continue;  // 32^3 is a coarse preview: printed, not held to the tolerance
        EXPECT_LT(relError[res], 0.22) << "voxelRes " << res;
        EXPECT_LT(e.rmse / refMean, 0.35) << "voxelRes " << res;
    }
    EXPECT_LT(relError[128], relError[64]) << "the mean indirect does not approach the reference as the grid refines";
}

// Colour bleeding: on the floor near the red wall (x < -0.5) the indirect light is redder
// (higher r/g) than near the green wall (x > 0.5), in VCT as in the reference, and the
// contrast log(r/g near red / r/g near green) is at least half the reference's. Measured:
// reference 1.499 / 0.882; VCT 1.430 / 0.845 at 64^3 (99% of the reference's contrast),
// 1.397 / 0.859 at 128^3 (92%).
TEST(VctQuality, WallsBleedColourOntoTheFloor) {
    CornellRenders& c = cornell();
    auto ratio = [](glm::dvec3 v) { return v.x / std::max(v.y, 1e-9); };
    const double refRed = ratio(floorMean(c.reference, c.position, -1));
    const double refGreen = ratio(floorMean(c.reference, c.position, +1));
    std::printf("[vct quality] cornell_box floor r/g reference: near red %.3f near green %.3f\n", refRed, refGreen);
    ASSERT_GT(refRed, refGreen) << "the reference itself shows no bleeding: the test's selection is wrong";
    for (const auto& [res, img] : c.vct) {
        const double red = ratio(floorMean(img, c.position, -1));
        const double green = ratio(floorMean(img, c.position, +1));
        const double contrast = std::log(red / green), refContrast = std::log(refRed / refGreen);
        std::printf("[vct quality] cornell_box floor r/g vct %3d: near red %.3f near green %.3f (contrast %.0f%% of "
                    "the reference's)\n",
                    res, red, green, 100.0 * contrast / refContrast);
        EXPECT_GT(red, 1.0) << "voxelRes " << res << ": no red near the red wall";
        EXPECT_LT(green, 1.0) << "voxelRes " << res << ": no green near the green wall";
        EXPECT_GT(contrast, 0.5 * refContrast) << "voxelRes " << res;
    }
}

// An emissive panel (Le, albedo 0) three voxels above a floor (albedo 0.5), no lights, no sky,
// seen from a camera in the gap. Facing the floor, the panel lights it (the reference gives
// albedo * Le * F with F the view factor); facing away, the floor sees only the panel's back,
// which emits nothing (the reference gives 0). VCT follows both: radiance leaves voxels from
// their fronts (vox_facingWeight of the filtered normals at every level). Measured (48 px, 64^3), in units of albedo * Le: facing
// the floor VCT 1.000 / reference 0.931; facing away VCT 0.000 / reference 0 (0.26 before).
TEST(VctQuality, EmitterSeenFromBehindPassesNoLight) {
    const float Le = 4.f, albedo = 0.5f;
    const float voxel = 4.f / 62.f, h = 3.f * voxel;  // 64 voxels over the 4 m floor, padded by one
    auto floorUnderPanel = [&](bool facingFloor, const std::string& gi) {
        Scene s;
        const uint32_t floorMat = vcttest::addMaterial(s, glm::vec3(albedo));
        const uint32_t lamp = vcttest::addMaterial(s, glm::vec3(0.f), glm::vec3(Le));
        s.materials[lamp].doubleSided = false;  // emits from its front only (glTF culls the back)
        vcttest::addQuad(s, {-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, floorMat);
        if (facingFloor)
            vcttest::addQuad(s, {-1, h, -1}, {2, 0, 0}, {0, 0, 2}, lamp);  // normal -y
        else
            vcttest::addQuad(s, {-1, h, -1}, {0, 0, 2}, {2, 0, 0}, lamp);  // normal +y
        vcttest::finish(s);
        RenderSession session(s);
        RenderRequest r;
        r.width = r.height = 48;
        CameraRequest cam;
        cam.hasEye = true;
        cam.eye = glm::vec3(1.4f, 0.5f * h, 1.4f);
        cam.target = glm::vec3(0.f, 0.f, 0.f);
        cam.fovDeg = 60.f;
        r.camera = resolveCamera(s, cam, 1.f);
        r.gi = gi;
        r.sky = 0.f;
        r.spp = 64;
        r.voxelRes = 64;
        r.aovs = {"indirect", "position", "depth"};
        RenderResult out = renderChecked(session, r, "emitter behind");
        const Image& ind = out.aovs.at("indirect");
        const Image& pos = out.aovs.at("position");
        const Image& depth = out.aovs.at("depth");
        double sum = 0.0;
        size_t n = 0;
        for (int y = 0; y < pos.height; ++y)
            for (int x = 0; x < pos.width; ++x) {
                const glm::vec3 p(pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2));
                if (!(depth.at(x, y, 0) > 0.f)) continue;  // sky
                if (std::abs(p.y) > 1e-3f || std::abs(p.x) > 0.7f || std::abs(p.z) > 0.7f) continue;
                sum += ind.at(x, y, 0);
                ++n;
            }
        EXPECT_GT(n, 30u) << "too few floor pixels under the panel";
        return n ? float(sum / double(n)) / (albedo * Le) : 0.f;
    };
    const float front = floorUnderPanel(true, "vct"), frontRef = floorUnderPanel(true, "reference");
    const float back = floorUnderPanel(false, "vct"), backRef = floorUnderPanel(false, "reference");
    std::printf("[vct quality] floor under a panel, / (albedo Le): facing the floor vct %.3f ref %.3f; facing away "
                "vct %.4f ref %.4f\n",
                front, frontRef, back, backRef);
    EXPECT_GT(frontRef, 0.6f);
    EXPECT_LT(backRef, 0.01f);
    EXPECT_NEAR(front, frontRef, 0.15f * frontRef);
    EXPECT_LT(back, 0.05f);
}

// Two fresh sessions (two voxelizations, injections and cone passes) give bit-identical AO,
// indirect and beauty.
TEST(VctQuality, RendersAreBitIdentical) {
    Scene s = cornellBox();
    RenderRequest r = requestFor(s, 48);
    r.ao = "vct";
    r.gi = "vct";
    r.voxelRes = 64;
    r.aovs = {"beauty", "ao", "indirect"};
    RenderSession first(s), second(s);
    RenderResult a = renderChecked(first, r, "vct determinism");
    RenderResult b = renderChecked(second, r, "vct determinism");
    for (const auto& aov : r.aovs) {
        const Image& x = a.aovs.at(aov);
        const Image& y = b.aovs.at(aov);
        ASSERT_EQ(x.pixels.size(), y.pixels.size()) << aov;
        size_t differing = 0;
        for (size_t i = 0; i < x.pixels.size(); ++i)
            if (std::memcmp(&x.pixels[i], &y.pixels[i], sizeof(float)) != 0) ++differing;
        EXPECT_EQ(differing, 0u) << aov << ": values differ between two renders";
    }
}
