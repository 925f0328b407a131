// Stiff and extreme cases (BRIEF section 6, issue 9): every AO and GI method over scenes
// generated in code. Each test asserts the invariants (finite, AO in [0, 1], radiance >= 0),
// the case's closed form or its agreement with the reference where one applies, and
// records a row of docs/stability.md (see stability_harness.h for the command).
#include "stability/stability_harness.h"

#include "gl/context.h"
#include "render/renderer.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace vct;
using namespace stab;

namespace {

RenderRequest baseRequest(const Camera& camera, float radius, int size = 40) {
    RenderRequest r;
    r.width = r.height = size;
    r.camera = camera;
    r.radius = radius;
    r.spp = 16;
    r.seed = 7;
    r.voxelRes = 48;
    r.sky = 1.f;
    r.params.set("reference.replicates", "1");
    return r;
}

using Outcomes = std::map<std::string, Outcome>;

// Runs `methods` over one session and checks the invariants of each.
Outcomes runAll(RenderSession& session, const RenderRequest& base, const std::vector<stab::Method>& methods,
                const std::string& caseName) {
    Outcomes out;
    for (const auto& m : methods) {
        Outcome o = runMethod(session, base, m);
        EXPECT_FALSE(o.refused) << caseName << " / " << m.label << ": " << o.message;
        for (const auto& v : o.violations) ADD_FAILURE() << caseName << " / " << m.label << ": " << v;
        out[m.label] = std::move(o);
    }
    return out;
}

// The relative error of a GI image against another: mean |a - b| / mean b.
double relativeDiff(const Image& a, const Image& b, const Image& depth) {
    const double mb = surfaceMean(b, depth);
    return meanAbsDiff(a, b, depth) / std::max(mb, 1e-30);
}

const stab::Method& methodNamed(const std::string& label) {
    static const std::vector<stab::Method> all = allMethodColumns();
    for (const auto& m : all)
        if (m.label == label) return m;
    throw std::runtime_error("no method " + label);
}

// Error of each AO method against the reference AO of the same render, and of vct GI
// against reference GI (relative); recorded as the row's cells.
void recordAgainstReference(const std::string& caseName, const Outcomes& o) {
    const Outcome* refAo = o.count("reference AO") ? &o.at("reference AO") : nullptr;
    const Outcome* refGi = o.count("reference GI") ? &o.at("reference GI") : nullptr;
    for (const auto& [label, out] : o) {
        const stab::Method& m = methodNamed(label);
        std::optional<double> err;
        if (out.ok()) {
            if (!m.isGi() && refAo && refAo->ok() && label != "reference AO")
                err = meanAbsDiff(out.ao, refAo->ao, refAo->depth);
            if (m.isGi() && refGi && refGi->ok() && label != "reference GI")
                err = relativeDiff(out.indirect, refGi->indirect, refGi->depth);
        }
        recordCell(caseName, label, cellFor(out, err));
    }
}

}  // namespace

// The same scene at 1e-4, 1 and 1e5 units, R, camera and znear scaled with it. AO and the
// radiance of a directional light (lux) and a sky are scale-free: every method must give
// the same image at every scale.
TEST(Stability, SceneScale) {
    const float scales[] = {1e-4f, 1.f, 1e5f};
    std::map<float, Outcomes> byScale;
    for (float k : scales) {
        Scene s = cornerScene(k);
        RenderSession session(s);
        RenderRequest r = baseRequest(cornerCamera(k), 0.5f * k);
        byScale[k] = runAll(session, r, allMethodColumns(), "scale");
    }
    recordCaseInfo("scale 1", "the corner scene (floor, box, back wall; sun 3 lux, sky 1) at unit scale, R = 0.5.",
                   "mean |AO - reference AO| over surface pixels; GI: mean |L - L_ref| / mean L_ref.");
    recordAgainstReference("scale 1", byScale[1.f]);
    for (float k : {1e-4f, 1e5f}) {
        const std::string name = std::string("scale ") + (k < 1 ? "1e-4" : "1e5");
        recordCaseInfo(name, "the corner scene scaled by " + fmt(k) + " (R, camera, znear scaled with it).",
                       "mean |x(scale) - x(1)| over surface pixels (AO), relative for GI; 0 = scale-invariant.");
        for (const auto& m : allMethodColumns()) {
            const Outcome& a = byScale[k].at(m.label);
            const Outcome& b = byScale[1.f].at(m.label);
            std::optional<double> diff;
            if (a.ok() && b.ok()) {
                diff = m.isGi() ? relativeDiff(a.indirect, b.indirect, b.depth)
                                : meanAbsDiff(a.ao, b.ao, b.depth);
                // Rasterization of a scaled scene covers the same pixels up to rounding, so every
                // method sees the same G-buffer up to a few edge pixels.
                const double tol = m.isGi() ? 0.05 : 0.01;
                EXPECT_LT(*diff, tol) << m.label << " is not scale-invariant at scale " << k;
            }
            Cell c = cellFor(a, diff);
            if (diff && *diff >= (m.isGi() ? 0.05 : 0.01)) c.ok = false;
            recordCell(name, m.label, c);
        }
    }
}

// znear 1e-3 with the scene 1e3..1e4 away (far/near ~ 1e7) against znear 1: the
// reversed-Z float depth buffer keeps both alike.
TEST(Stability, NearFarRatio1e7) {
    const float k = 1000.f;
    Scene s = cornerScene(k);
    RenderSession session(s);
    Camera tiny = cornerCamera(k);
    tiny.znear = 1e-3f;
    Camera normal = cornerCamera(k);
    normal.znear = 1.f;
    Outcomes a = runAll(session, baseRequest(tiny, 0.5f * k), allMethodColumns(), "near/far");
    Outcomes b = runAll(session, baseRequest(normal, 0.5f * k), allMethodColumns(), "near/far");
    const std::string name = "near/far 1e7";
    recordCaseInfo(name, "the corner scene at 1000x, camera ~4e3 away with znear = 1e-3 (far/near ~ 1e7).",
                   "mean |x(znear 1e-3) - x(znear 1)| (AO), relative for GI.");
    for (const auto& m : allMethodColumns()) {
        std::optional<double> diff;
        if (a[m.label].ok() && b[m.label].ok()) {
            diff = m.isGi() ? relativeDiff(a[m.label].indirect, b[m.label].indirect, b[m.label].depth)
                            : meanAbsDiff(a[m.label].ao, b[m.label].ao, b[m.label].depth);
            EXPECT_LT(*diff, m.isGi() ? 0.05 : 0.01) << m.label;
        }
        recordCell(name, m.label, cellFor(a[m.label], diff));
    }
}

// An open plane seen at 89.9 degrees from its normal: A_R = 1 everywhere (nothing above
// it), and its indirect radiance is rho * L_sky.
TEST(Stability, GrazingPlane) {
    Scene s;
    const float rho = 0.5f;
    uint32_t mat = vcttest::addMaterial(s, glm::vec3(rho));
    const float half = 2e4f;
    vcttest::addQuad(s, glm::vec3(-half, 0, -half), glm::vec3(0, 0, 2 * half), glm::vec3(2 * half, 0, 0), mat);
    vcttest::finish(s);
    Camera c;
    c.eye = glm::vec3(0, 1, 0);
    const float angle = glm::radians(89.9f);
    c.target = c.eye + glm::vec3(0, -std::cos(angle), -std::sin(angle));
    c.yfov = 0.6f;
    c.znear = 1e-3f;
    c.zfar = 1e5f;
    RenderSession session(s);
    Outcomes o = runAll(session, baseRequest(c, 1.f), allMethodColumns(), "grazing");
    const std::string name = "grazing 89.9 deg";
    recordCaseInfo(name,
                   "a 4e4-wide plane, camera 1 above it looking 89.9 degrees from its normal (R = 1, rho 0.5, sky 1).",
                   "mean |AO - 1| (closed form: nothing above the plane); GI: mean |L - rho L_sky| / (rho L_sky).");
    for (const auto& m : allMethodColumns()) {
        const Outcome& out = o[m.label];
        std::optional<double> err;
        if (out.ok()) {
            err = m.isGi() ? meanAbsErrorTo(out.indirect, out.depth, rho * 1.0) / rho
                           : meanAbsErrorTo(out.ao, out.depth, 1.0);
        }
        recordCell(name, m.label, cellFor(out, err));
    }
    // The reference integrates exactly this configuration: it must find nothing.
    EXPECT_LT(meanAbsErrorTo(o["reference AO"].ao, o["reference AO"].depth, 1.0), 1e-6);
    EXPECT_LT(meanAbsErrorTo(o["reference GI"].indirect, o["reference GI"].depth, rho) / rho, 0.02);
}
