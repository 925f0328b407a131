// Stability at the ends of the parameter ranges: R near 0 and larger than the scene, voxel
// grids 4^3 to 512^3, cone apertures near 0 and 180 degrees, albedo 0 and 1 with many
// bounces (energy bounded by its closed form), emission 1e6, sky 0, invalid input in code.
#include "stability/stability_harness.h"

#include "gl/context.h"
#include "render/renderer.h"
#include "support/test_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <map>

using namespace vct;
using namespace stab;

namespace {

RenderRequest requestFor(const Camera& camera, float radius, int size = 40) {
    return baseRequest(camera, radius, size, 11);
}

using Outcomes = std::map<std::string, Outcome>;

Outcomes runMethods(RenderSession& session, const RenderRequest& r, const std::vector<stab::Method>& methods,
                    const std::string& caseName, bool expectAccepted = true) {
    Outcomes out;
    for (const auto& m : methods) {
        Outcome o = runMethod(session, r, m);
        if (expectAccepted) {
            EXPECT_FALSE(o.refused) << caseName << " / " << m.label << ": " << o.message;
        }
        for (const auto& v : o.violations) ADD_FAILURE() << caseName << " / " << m.label << ": " << v;
        out[m.label] = std::move(o);
    }
    return out;
}

const stab::Method& col(const std::string& label) {
    static const std::vector<stab::Method> all = allMethodColumns();
    for (const auto& m : all)
        if (m.label == label) return m;
    throw std::runtime_error(label);
}

std::optional<double> errorToReference(const stab::Method& m, const Outcome& o, const Outcomes& all) {
    if (!o.ok()) return std::nullopt;
    if (!m.isGi()) {
        const Outcome& ref = all.count("reference AO") ? all.at("reference AO") : o;
        if (&ref == &o || !ref.ok()) return std::nullopt;
        return meanAbsDiff(o.ao, ref.ao, ref.depth);
    }
    const Outcome& ref = all.count("reference GI") ? all.at("reference GI") : o;
    if (&ref == &o || !ref.ok()) return std::nullopt;
    return meanAbsDiff(o.indirect, ref.indirect, ref.depth) / std::max(surfaceMean(ref.indirect, ref.depth), 1e-30);
}

}  // namespace

TEST(StabilityParams, RadiusNearZeroAndLargerThanTheScene) {
    Scene s = cornerScene(1.f);
    RenderSession session(s);
    {
        auto o = runMethods(session, requestFor(cornerCamera(1.f), 1e-4f), aoMethodColumns(), "R 1e-4");
        recordCaseInfo("R = 1e-4", "the corner scene (4 units wide) with R = 1e-4.",
                       "mean |AO - 1| (A_R -> 1 as R -> 0; Crytek's sphere reads ~0.5 on flat ground by design).");
        for (const auto& m : aoMethodColumns()) {
            const Outcome& out = o[m.label];
            std::optional<double> err;
            if (out.ok()) err = meanAbsErrorTo(out.ao, out.depth, 1.0);
            recordCell("R = 1e-4", m.label, cellFor(out, err));
            if (err && m.ao != "ssao-crytek") {
                EXPECT_LT(*err, 0.05) << m.label << ": AO does not tend to 1 as R -> 0";
            }
        }
    }
    {
        auto o = runMethods(session, requestFor(cornerCamera(1.f), 1e3f), aoMethodColumns(), "R 1e3");
        recordCaseInfo("R = 1e3", "the corner scene with R = 1000 (250x the scene).",
                       "mean |AO - reference AO| over surface pixels.");
        for (const auto& m : aoMethodColumns())
            recordCell("R = 1e3", m.label, cellFor(o[m.label], errorToReference(m, o[m.label], o)));
    }
}

// 4^3 .. 256^3 run; 512^3 either runs or is refused with a clear error, never a crash.
// Each grid's wall time and memory go to the findings.
TEST(StabilityParams, VoxelGridResolutions) {
    Scene s = cornerScene(1.f);
    RenderSession session(s);
    const std::vector<stab::Method> methods = {col("vct AO"), col("vct GI"), col("reference AO"), col("reference GI")};
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f, 32);
    auto ref = runMethods(session, r, {col("reference AO"), col("reference GI")}, "voxels ref");
    // 512^3 takes about a minute and several GB on llvmpipe: only with VCT_STABILITY_SLOW=1
    // (scripts/make_stability_doc.sh sets it).
    std::vector<int> resolutions = {4, 16, 64, 256};
    const char* slow = std::getenv("VCT_STABILITY_SLOW");
    if (slow && std::string(slow) == "1") resolutions.push_back(512);
    else recordNote("voxels 512^3: not run (set VCT_STABILITY_SLOW=1; scripts/make_stability_doc.sh does).");
    // This scene's 1024x513x1024: GI's grid (~41 GB) is refused by the memory estimate on a
    // machine with < 82 GB; AO's grid of opacity alone (~9 GB) where the GL cannot allocate it
    // (llvmpipe caps one texture's size below its 2 GB accumulator).
    resolutions.push_back(1024);
    for (int res : resolutions) {
        r.voxelRes = res;
        const std::string name = "voxels " + std::to_string(res) + "^3";
        recordCaseInfo(name, "vct on the corner scene with a " + std::to_string(res) + "^3 grid (R = 0.5).",
                       "mean |AO - reference AO|; GI: mean |L - L_ref| / mean L_ref. The grid's wall time is in "
                       "the findings.");
        Outcomes o;
        for (const auto& label : {"vct AO", "vct GI"}) {
            Outcome out = runMethod(session, r, col(label));
            if (res <= 256) {
                EXPECT_FALSE(out.refused) << name << " " << label << ": " << out.message;
            } else if (out.refused) {  // must say what is wrong, not fail somewhere deep
                EXPECT_NE(out.message.find("voxel"), std::string::npos) << out.message;
            }
            for (const auto& v : out.violations) ADD_FAILURE() << name << " / " << label << ": " << v;
            o[label] = std::move(out);
        }
        for (const auto& [label, out] : ref) o[label] = out;
        for (const auto& label : {"vct AO", "vct GI"}) {
            recordCell(name, label, cellFor(o[label], errorToReference(col(label), o[label], o)));
            recordNote(name + " " + label + ": " + (o[label].refused ? "refused (" + o[label].message + ")"
                                                                      : fmt(o[label].ms / 1000.0) + " s"));
        }
        if (o["vct GI"].ok()) {
            // Voxel memory of the grid (GPU textures) as the renderer reports it.
            RenderRequest rg = r;
            rg.gi = "vct";
            rg.aovs = {"indirect"};
            RenderResult res2 = session.render(rg);  // cached grid: no new voxelization
            if (res2.extra.contains("voxels"))
                recordNote(name + " voxel memory: " +
                           fmt(res2.extra["voxels"].value("memory_bytes", 0.0) / 1048576.0) + " MiB");
        }
    }
}

TEST(StabilityParams, ConeApertureExtremes) {
    Scene s = cornerScene(1.f);
    RenderSession session(s);
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f);
    auto ref = runMethods(session, r, {col("reference AO"), col("reference GI")}, "aperture ref");
    for (const char* aperture : {"1.01", "178.99"}) {
        RenderRequest ra = r;
        ra.params.set("vct.aperture", aperture);
        const std::string name = std::string("cone aperture ") + aperture + " deg";
        auto o = runMethods(session, ra, {col("vct AO"), col("vct GI")}, name);
        for (const auto& [label, out] : ref) o[label] = out;
        recordCaseInfo(name, std::string("vct with every cone ") + aperture + " degrees wide (6 cones, R = 0.5).",
                       "mean |AO - reference AO|; GI relative to the reference.");
        for (const auto& label : {"vct AO", "vct GI"})
            recordCell(name, label, cellFor(o[label], errorToReference(col(label), o[label], o)));
        // Degenerate cones still estimate the integral: a near-zero aperture marches each cone
        // as a ray, a near-180-degree one as a wide blur (measured: AO 0.023 / 0.021 from the
        // reference, GI 0.055 / 0.058 relative).
        const auto ao = errorToReference(col("vct AO"), o["vct AO"], o);
        const auto gi = errorToReference(col("vct GI"), o["vct GI"], o);
        ASSERT_TRUE(ao && gi) << name;
        EXPECT_LT(*ao, 0.1) << name;
        EXPECT_LT(*gi, 0.25) << name;
    }
}

// Albedo 0: no indirect light at all, whatever the bounces.
TEST(StabilityParams, AlbedoZeroManyBounces) {
    Scene s = cornerScene(1.f, glm::vec3(0.f));
    RenderSession session(s);
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f);
    r.params.set("vct.bounces", "8");
    r.params.set("reference.bounces", "64");
    auto o = runMethods(session, r, allMethodColumns(), "albedo 0");
    const std::string name = "albedo 0, 8/64 bounces";
    recordCaseInfo(name, "the corner scene with albedo 0 (sun 3 lux, sky 1), vct 8 bounces, reference 64.",
                   "GI: max indirect radiance over surface pixels (closed form 0); AO: vs reference.");
    for (const auto& m : allMethodColumns()) {
        const Outcome& out = o[m.label];
        std::optional<double> err;
        if (out.ok()) err = m.isGi() ? surfaceMax(out.indirect, out.depth) : *errorToReference(m, out, o);
        if (m.label == "reference AO") err = std::nullopt;
        if (m.isGi() && err) {
            EXPECT_LE(*err, 1e-6) << m.label;
        }
        recordCell(name, m.label, cellFor(out, err));
    }
}

// White furnace: albedo 1 under a uniform sky L and no lights. Every surface's radiance is
// exactly L at equilibrium and at most L after any number of bounces: indirect <= L.
TEST(StabilityParams, AlbedoOneWhiteFurnace) {
    Scene s = cornerScene(1.f, glm::vec3(1.f), false);
    RenderSession session(s);
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f);
    r.params.set("vct.bounces", "8");
    r.params.set("reference.bounces", "64");
    auto o = runMethods(session, r, giMethodColumns(), "white furnace");
    const std::string name = "albedo 1 furnace, sky 1";
    recordCaseInfo(name, "the corner scene with albedo 1 under sky 1, no lights, vct 8 bounces, reference 64.",
                   "max indirect / L_sky (bound: 1; converged: 1 everywhere), then mean |L - 1|.");
    for (const auto& m : giMethodColumns()) {
        const Outcome& out = o[m.label];
        Cell c = cellFor(out);
        if (out.ok()) {
            const double mx = surfaceMax(out.indirect, out.depth);
            const double err = meanAbsErrorTo(out.indirect, out.depth, 1.0);
            c.text = "max " + fmt(mx) + ", err " + fmt(err);
            // The reference is a mean of 16 paths per pixel, each <= L: its mean is <= L exactly.
            const double bound = 1.0 + 1e-3;
            if (mx > bound) c.ok = false;
            EXPECT_LE(mx, bound) << m.label << ": energy grows past the sky";
        }
        recordCell(name, m.label, c);
    }
    EXPECT_LT(meanAbsErrorTo(o["reference GI"].indirect, o["reference GI"].depth, 1.0), 0.05);
}

// Inside a closed box whose walls all emit Le with albedo rho: L = Le / (1 - rho), so the
// indirect part is Le rho / (1 - rho) everywhere; with N bounces it is Le (rho - rho^(N+1)) / (1 - rho).
TEST(StabilityParams, ClosedEmissiveBoxConverges) {
    const double rho = 0.8, Le = 1.0;
    Scene s;
    uint32_t mat = vcttest::addMaterial(s, glm::vec3(float(rho)), glm::vec3(float(Le)));
    vcttest::addBox(s, {0, 0, 0}, {2, 2, 2}, mat);
    vcttest::finish(s);
    Camera c;
    c.eye = {1.f, 1.f, 1.8f};
    c.target = {1.f, 0.8f, 0.f};
    c.yfov = 1.3f;
    c.znear = 0.01f;
    RenderSession session(s);
    RenderRequest r = requestFor(c, 0.5f);
    r.sky = 0.f;
    r.params.set("vct.bounces", "8");
    r.params.set("reference.bounces", "64");
    r.params.set("reference.roulette-bounce", "64");  // no roulette: the closed form is exact per path
    auto o = runMethods(session, r, giMethodColumns(), "emissive box");
    // Judged on beauty = Le + direct + indirect (the reference counts one reflection of an
    // emitter as direct, vct as indirect; the sum is the same quantity).
    const double limit = Le / (1 - rho);
    const std::string name = "closed box, rho 0.8, all emit";
    recordCaseInfo(name, "inside a closed 2^3 box, every wall Le = 1 and rho = 0.8, sky 0; vct 8 bounces, reference 64. "
                         "The walls are wound outwards with doubleSided materials: both renderers light and see both "
                         "faces. vct's two-sided voxels emit from both faces alike, and a voxel whose faces are equally "
                         "bright gathers its bounces on its front (here the outside), so inside the box vct sees the "
                         "walls' emission and one reflection of it, not the bounces (0.23 when every surface was "
                         "one-sided by its winding).",
                   "beauty (Le + direct + indirect) / the infinite-bounce limit Le / (1 - rho) = 5: max over pixels "
                   "(must stay <= 1; the reference's per-pixel max carries its noise) and mean (1 when converged).");
    for (const auto& m : giMethodColumns()) {
        const Outcome& out = o[m.label];
        Cell cell = cellFor(out);
        if (out.ok()) {
            const double mx = surfaceMax(out.beauty, out.depth) / limit;
            const double mean = surfaceMean(out.beauty, out.depth) / limit;
            cell.text = "max " + fmt(mx) + ", mean " + fmt(mean);
            if (m.gi == "reference") {
                // 64 bounces: 1 - 0.8^65 = 1 - 5e-7 of the limit; the mean of 1600 pixels x 16 paths.
                EXPECT_NEAR(mean, 1.0, 0.05) << m.label;
                if (std::abs(mean - 1.0) > 0.05) cell.ok = false;
            } else {
                // Deterministic: every pixel must stay under the limit (8 bounces: 1 - 0.8^10 = 0.89).
                EXPECT_LE(mx, 1.0 + 1e-3) << m.label << ": energy grows past Le / (1 - rho)";
                if (mx > 1.0 + 1e-3) cell.ok = false;
            }
        }
        recordCell(name, m.label, cell);
    }
}

// Emission 1e6 on a small panel in the corner scene: everything stays finite (half-float
// voxel storage tops out at 65504).
TEST(StabilityParams, Emission1e6) {
    Scene s = cornerScene(1.f);
    uint32_t hot = vcttest::addMaterial(s, glm::vec3(0.5f), glm::vec3(1e6f));
    vcttest::addQuad(s, {1.f, 0.01f, 0.5f}, {0, 0, 0.5f}, {0.5f, 0, 0}, hot);
    vcttest::finish(s);
    RenderSession session(s);
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f);
    auto o = runMethods(session, r, allMethodColumns(), "emission 1e6");
    const std::string name = "emission 1e6";
    recordCaseInfo(name, "the corner scene with a 0.5 x 0.5 panel emitting 1e6 on the floor.",
                   "AO: vs reference AO; GI: mean |L - L_ref| / mean L_ref.");
    for (const auto& m : allMethodColumns()) recordCell(name, m.label, cellFor(o[m.label], errorToReference(m, o[m.label], o)));
    // Emission is not occlusion: with the panel's emission set to 0 (the same geometry) every AO
    // method's image is the same, bit for bit (deterministic for a seed).
    s.materials[hot].emissiveFactor = glm::vec3(0.f);
    vcttest::finish(s);
    RenderSession dark(s);
    const Outcomes d = runMethods(dark, r, aoMethodColumns(), "emission 0");
    for (const auto& m : aoMethodColumns()) {
        ASSERT_TRUE(o[m.label].ok() && d.at(m.label).ok()) << m.label;
        EXPECT_EQ(o[m.label].ao.pixels, d.at(m.label).ao.pixels) << m.label << ": the emitter changed AO";
    }
    // The emitter lights the scene: the indirect light grows by orders of magnitude over the
    // sun's bounce alone (measured: the reference x 4246). VCT's grows less (x 970: the table's
    // 0.88): the panel lies 0.01 above the floor, inside the floor's voxels.
    const auto darkGi = runMethods(dark, r, giMethodColumns(), "emission 0 GI");
    for (const auto& m : giMethodColumns()) {
        ASSERT_TRUE(o[m.label].ok() && darkGi.at(m.label).ok()) << m.label;
        const double ratio = surfaceMean(o[m.label].indirect, o[m.label].depth) /
                             surfaceMean(darkGi.at(m.label).indirect, darkGi.at(m.label).depth);
        EXPECT_GT(ratio, m.label == "vct GI" ? 300.0 : 2000.0) << m.label;
    }
}

// Sky 0 and no lights: no light anywhere; AO is unaffected.
TEST(StabilityParams, SkyZeroNoLights) {
    Scene s = cornerScene(1.f, glm::vec3(0.6f), false);
    RenderSession session(s);
    RenderRequest r = requestFor(cornerCamera(1.f), 0.5f);
    r.sky = 0.f;
    auto o = runMethods(session, r, allMethodColumns(), "sky 0");
    const std::string name = "sky 0, no lights";
    recordCaseInfo(name, "the corner scene with sky 0 and no lights.",
                   "GI: max indirect (closed form 0); AO: vs reference AO.");
    for (const auto& m : allMethodColumns()) {
        const Outcome& out = o[m.label];
        std::optional<double> err;
        if (out.ok()) err = m.isGi() ? std::optional<double>(surfaceMax(out.indirect, out.depth))
                                     : errorToReference(m, out, o);
        if (m.isGi() && err) {
            EXPECT_EQ(*err, 0.0) << m.label;
        }
        recordCell(name, m.label, cellFor(out, err));
    }
}

// Invalid input handed to the renderer in code (not through a file): refused with an
// error naming it, never rendered.
TEST(StabilityParams, NonFiniteInputInCodeIsRefused) {
    const std::string name = "NaN/Inf in code";
    recordCaseInfo(name, "a Scene built in code with a NaN vertex, and a camera with an infinite eye / zero znear.",
                   "");
    {
        Scene s = cornerScene(1.f);
        s.positions[5].y = std::nanf("");
        std::string msg;
        try {
            RenderSession session(s);
            session.render(requestFor(cornerCamera(1.f), 0.5f));
        } catch (const std::exception& e) {
            msg = e.what();
        }
        EXPECT_NE(msg.find("vertex 5"), std::string::npos) << "got: '" << msg << "'";
        recordCell(name, "renderer", {msg.empty() ? "NaN vertex rendered" : "refused: " + msg, !msg.empty()});
    }
    {
        Scene s = cornerScene(1.f);
        RenderSession session(s);
        Camera c = cornerCamera(1.f);
        c.eye.x = INFINITY;
        std::string msg;
        try {
            session.render(requestFor(c, 0.5f));
        } catch (const std::exception& e) {
            msg = e.what();
        }
        EXPECT_NE(msg.find("camera"), std::string::npos) << "got: '" << msg << "'";
        c = cornerCamera(1.f);
        c.znear = 0.f;
        std::string msg2;
        try {
            session.render(requestFor(c, 0.5f));
        } catch (const std::exception& e) {
            msg2 = e.what();
        }
        EXPECT_NE(msg2.find("znear"), std::string::npos) << "got: '" << msg2 << "'";
        recordNote("in-code camera checks: infinite eye -> '" + msg + "'; znear 0 -> '" + msg2 + "'");
    }
}
