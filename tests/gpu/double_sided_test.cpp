// glTF doubleSided materials in voxel cone tracing: a doubleSided surface is lit, and its light
// leaves, from whichever face the light reaches (two-sided voxels, voxelize_shared.h), so a
// closed box wound outwards but doubleSided is lit inside as the same box wound inwards; a
// single-sided box wound outwards stays one-sided (its inside is its back). Independent paths:
// the same box with its winding reversed, the other backend, and the path tracer.
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "support/run_vct.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace vct;

namespace {

enum class Winding { Outward, Inward };

// A closed 2^3 box (albedo 0.6) with a point light inside, off centre.
Scene litBox(Winding winding, bool doubleSided) {
    Scene s;
    const uint32_t wall = vcttest::addMaterial(s, glm::vec3(0.6f));
    s.materials[wall].doubleSided = doubleSided;
    const glm::vec3 lo(0.f), hi(2.f);
    if (winding == Winding::Outward) {
        vcttest::addBox(s, lo, hi, wall);
    } else {
        // addBox's quads with u and v swapped: every normal points into the box.
        const glm::vec3 x(2, 0, 0), y(0, 2, 0), z(0, 0, 2);
        vcttest::addQuad(s, lo, x, y, wall);
        vcttest::addQuad(s, lo + z, y, x, wall);
        vcttest::addQuad(s, lo, y, z, wall);
        vcttest::addQuad(s, lo + x, z, y, wall);
        vcttest::addQuad(s, lo, z, x, wall);
        vcttest::addQuad(s, lo + y, x, z, wall);
    }
    Light light;
    light.name = "inside";
    light.type = LightType::Point;
    light.color = glm::vec3(4.f);
    light.position = glm::vec3(0.6f, 1.4f, 0.7f);
    s.lights.push_back(light);
    vcttest::finish(s);
    return s;
}

struct Lit {
    double mean = 0.0;  // mean indirect over the pixels
    Image indirect, position;
};

const glm::vec3 kBoxEye(1.7f, 1.f, 1.8f), kBoxTarget(0.5f, 0.8f, 0.f);

Lit renderIndirect(const Scene& s, const std::string& gi, const std::string& backend, int voxelRes, int spp = 16,
                   glm::vec3 eye = kBoxEye, glm::vec3 target = kBoxTarget, const ParamMap& extra = ParamMap()) {
    RenderSession session(s);
    RenderRequest r;
    r.width = r.height = 48;
    CameraRequest cam;
    cam.hasEye = true;
    cam.eye = eye;
    cam.target = target;
    cam.fovDeg = 70.f;
    r.camera = resolveCamera(s, cam, 1.f);
    r.gi = gi;
    r.backend = backend;
    r.sky = 0.f;
    r.voxelRes = voxelRes;
    r.spp = spp;
    // Matched reflections: VCT's default (the voxels' direct light, one voxel bounce, the gather
    // at the pixel) against paths of at most three.
    r.params.set("reference.bounces", "3");
    for (const auto& [k, v] : extra.values()) r.params.set(k, v);
    r.aovs = {"indirect", "position", "depth"};
    RenderResult out = session.render(r);
    GlContext::shared().checkErrors(("double-sided box, " + gi + " " + backend).c_str());
    Lit lit;
    lit.indirect = out.aovs.at("indirect");
    lit.position = out.aovs.at("position");
    double sum = 0.0;
    for (int y = 0; y < lit.indirect.height; ++y)
        for (int x = 0; x < lit.indirect.width; ++x) sum += lit.indirect.at(x, y, 0);
    lit.mean = sum / double(lit.indirect.width * lit.indirect.height);
    return lit;
}

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) sum += double(a.pixels[i] - b.pixels[i]) * (a.pixels[i] - b.pixels[i]);
    return std::sqrt(sum / double(a.pixels.size()));
}

}  // namespace

// Measured (48 px, 64^3): outward doubleSided 0.3565, inward single-sided 0.3568, outward
// single-sided 0 (every wall seen from behind); the sparse backend within RMSE 1e-3; the path
// tracer with matched reflections 0.42 (VCT's closed-box bias, the same for both windings).
TEST(DoubleSided, AnOutwardWoundDoubleSidedBoxIsLitInsideAsTheInwardWoundOne) {
    const Lit outward = renderIndirect(litBox(Winding::Outward, true), "vct", "gl", 64);
    const Lit inward = renderIndirect(litBox(Winding::Inward, false), "vct", "gl", 64);
    const Lit oneSided = renderIndirect(litBox(Winding::Outward, false), "vct", "gl", 64);
    const Lit sparse = renderIndirect(litBox(Winding::Outward, true), "vct", "vdb", 64);
    const Lit traced = renderIndirect(litBox(Winding::Outward, true), "reference", "gl", 64, 64);
    std::printf("[double sided] mean indirect: outward doubleSided %.4f, inward %.4f, outward single-sided %.4f, "
                "sparse %.4f (rmse %.5f), path tracer %.4f\n",
                outward.mean, inward.mean, oneSided.mean, sparse.mean, rmse(sparse.indirect, outward.indirect),
                traced.mean);
    ASSERT_GT(inward.mean, 0.1);
    EXPECT_NEAR(outward.mean, inward.mean, 0.01 * inward.mean);
    EXPECT_LT(rmse(outward.indirect, inward.indirect), 0.02 * inward.mean);
    EXPECT_LT(oneSided.mean, 0.05 * inward.mean) << "a single-sided wall seen from behind passes no light";
    EXPECT_LT(rmse(sparse.indirect, outward.indirect), 0.01) << "the backends disagree on two-sided voxels";
    // The path tracer reflects from both faces of every surface: the doubleSided box is lit as
    // brightly as VCT's within its closed-box bias (a quarter low here at 64^3).
    EXPECT_GT(outward.mean, 0.7 * traced.mean);
    EXPECT_LT(outward.mean, 1.05 * traced.mean);
}

// A doubleSided panel lit from behind (its winding faces away from the light) lights the floor
// under it on the light's side, as the same panel wound towards the light does; single-sided and
// wound away it passes nothing (its front is dark).
TEST(DoubleSided, APanelLitFromBehindLightsTheSideTheLightIsOn) {
    auto floorUnder = [](bool panelFacesLight, bool doubleSided) {
        Scene s;
        const uint32_t floorMat = vcttest::addMaterial(s, glm::vec3(0.5f));
        const uint32_t panelMat = vcttest::addMaterial(s, glm::vec3(0.8f));
        s.materials[floorMat].doubleSided = false;
        s.materials[panelMat].doubleSided = doubleSided;
        vcttest::addQuad(s, {-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, floorMat);  // normal +y
        // A vertical panel at z = 0: normal -z (towards the light) or +z.
        if (panelFacesLight)
            vcttest::addQuad(s, {-1, 0, 0}, {0, 1.5f, 0}, {2, 0, 0}, panelMat);
        else
            vcttest::addQuad(s, {-1, 0, 0}, {2, 0, 0}, {0, 1.5f, 0}, panelMat);
        Light light;
        light.type = LightType::Point;
        light.color = glm::vec3(3.f);
        light.position = glm::vec3(0.f, 1.2f, -1.2f);
        s.lights.push_back(light);
        vcttest::finish(s);
        // Seen from the light's side; the floor's pixels there (z < -0.1).
        const Lit lit = renderIndirect(s, "vct", "gl", 64, 16, glm::vec3(1.2f, 1.f, -2.6f), glm::vec3(0.f, 0.3f, 0.f));
        double sum = 0.0;
        size_t n = 0;
        for (int y = 0; y < lit.position.height; ++y)
            for (int x = 0; x < lit.position.width; ++x)
                if (std::abs(lit.position.at(x, y, 1)) < 0.01f && lit.position.at(x, y, 2) < -0.1f) {
                    sum += lit.indirect.at(x, y, 0);
                    ++n;
                }
        EXPECT_GT(n, 200u) << "the floor is not in view";
        return n ? sum / double(n) : 0.0;
    };
    const double facing = floorUnder(true, false);
    const double behindDoubleSided = floorUnder(false, true);
    const double behindOneSided = floorUnder(false, false);
    std::printf("[double sided] floor's mean indirect: panel facing the light %.4f, doubleSided and facing away "
                "%.4f, single-sided and facing away %.4f\n",
                facing, behindDoubleSided, behindOneSided);
    ASSERT_GT(facing, 0.01);
    EXPECT_NEAR(behindDoubleSided, facing, 0.02 * facing);
    EXPECT_LT(behindOneSided, 0.5 * facing);
}

// The same closed box (wound inwards, single-sided) with optical-depth levels
// (vct.opacity=depth): cones that cross a wall at a coarse level no longer pass part of their
// transmittance to the black sky outside.
TEST(DoubleSided, OpticalDepthLevelsKeepAClosedBoxsLightInside) {
    ParamMap depth;
    depth.set("vct.opacity", "depth");
    const Lit alpha = renderIndirect(litBox(Winding::Inward, false), "vct", "gl", 64);
    const Lit dense = renderIndirect(litBox(Winding::Inward, false), "vct", "gl", 64, 16, kBoxEye, kBoxTarget, depth);
    const Lit sparse = renderIndirect(litBox(Winding::Inward, false), "vct", "vdb", 64, 16, kBoxEye, kBoxTarget, depth);
    const Lit traced = renderIndirect(litBox(Winding::Inward, false), "reference", "gl", 64, 64);
    std::printf("[optical depth] mean indirect: alpha %.4f, depth %.4f, depth sparse %.4f (rmse %.5f), path tracer %.4f\n",
                alpha.mean, dense.mean, sparse.mean, rmse(sparse.indirect, dense.indirect), traced.mean);
    EXPECT_LT(rmse(sparse.indirect, dense.indirect), 0.01) << "the backends disagree on depth levels";
    EXPECT_GT(dense.mean, alpha.mean);
}


// The lit inside of the outward-wound doubleSided box against the path tracer (three
// reflections) at 128^3: optical-depth levels keep it within 10% (measured +8.6%; +11.5% at
// 64^3, +6.8% at 256^3), and so do opacity levels sharpened along their axis (vct.sharpen=4:
// measured +7.8%), where the default opacity levels lose a fifth of it through the walls
// (measured -20%, and -15% / -23% at 64^3 / 256^3: the leak grows as the grid refines).
TEST(DoubleSided, WithDepthOrSharpenedLevelsTheLitInsideIsWithinTenPercentOfThePathTracer) {
    ParamMap depth;
    depth.set("vct.opacity", "depth");
    const Scene box = litBox(Winding::Outward, true);
    const Lit traced = renderIndirect(box, "reference", "gl", 128, 64);
    const Lit withDepth = renderIndirect(box, "vct", "gl", 128, 16, kBoxEye, kBoxTarget, depth);
    const Lit withAlpha = renderIndirect(box, "vct", "gl", 128);
    ParamMap sharpen;
    sharpen.set("vct.sharpen", "4");
    const Lit withSharpen = renderIndirect(box, "vct", "gl", 128, 16, kBoxEye, kBoxTarget, sharpen);
    std::printf("[128^3] mean indirect: depth %.4f, alpha %.4f, alpha sharpened %.4f, path tracer %.4f\n",
                withDepth.mean, withAlpha.mean, withSharpen.mean, traced.mean);
    EXPECT_NEAR(withDepth.mean, traced.mean, 0.10 * traced.mean);
    EXPECT_NEAR(withSharpen.mean, traced.mean, 0.10 * traced.mean);
    EXPECT_LT(withAlpha.mean, 0.9 * traced.mean) << "the opacity levels' leak this test documents is gone: "
                                                     "compare both encodings again";
}
