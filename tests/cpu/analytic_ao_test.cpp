// The analytic AO quadrature (eval/analytic_ao.h) that scores VCT's convergence, checked
// against closed forms and against the Embree reference (an independent path), and the
// cone model: its Monte Carlo form in the reference (AO, and GI's paths) agrees with its
// quadrature, and refining the cone set drives it toward the exact AO.
#include "cone/cone_set.h"
#include "cone/cone_settings.h"
#include "eval/analytic_ao.h"
#include "eval/convergence.h"
#include "reference/reference_ao.h"
#include "reference/camera_rays.h"
#include "reference/reference_gi.h"
#include "core/view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

using namespace vct;

namespace {

const glm::vec3 kUp(0.f, 1.f, 0.f);

// The path tracer's AO at a case's points (floor points, normal up) with its radius, `spp`
// samples a point, estimating the cone model of `cones` when it is not empty.
ReferenceAO referenceAtPoints(const AoConvergenceCase& c, int spp, const ConeModelSampler& cones = {}) {
    std::vector<SurfacePoint> pts;
    for (const glm::vec3& p : c.points) pts.push_back({p, kUp, kUp, true});
    ReferenceSettings s;
    s.radius = c.radius;
    s.spp = spp;
    s.progress = false;
    return referenceAO(c.scene, pts, s, cones);
}

}  // namespace

TEST(AnalyticAo, MatchesClosedForms) {
    // An unbounded plate at height h with R = 1 occludes cos(theta) >= h: A = 1 - (1 - h^2) = h^2.
    AnalyticOccluders plate;
    plate.rects.push_back({glm::vec3(0.f, 0.5f, 0.f), glm::vec3(100.f, 0.f, 0.f), glm::vec3(0.f, 0.f, 100.f)});
    EXPECT_NEAR(analyticAo(plate, glm::vec3(0.f), kUp, 1.f), 0.25, 2e-3);
    // A sphere of radius r at distance d on the normal, R >= d: A = 1 - (r / d)^2.
    AnalyticOccluders sphere;
    sphere.spheres.push_back({glm::vec3(0.f, 0.6f, 0.f), 0.25f});
    EXPECT_NEAR(analyticAo(sphere, glm::vec3(0.f), kUp, 1.f), 1.0 - std::pow(0.25 / 0.6, 2), 2e-3);
    // A disc of radius a at height h on the normal, R beyond it: A = 1 - a^2 / (a^2 + h^2).
    AnalyticOccluders disc;
    disc.discs.push_back({glm::vec3(0.f, 0.7f, 0.f), kUp, 0.3f});
    EXPECT_NEAR(analyticAo(disc, glm::vec3(0.f), kUp, 10.f), 1.0 - 0.09 / (0.09 + 0.49), 2e-3);
    // Nothing above: open.
    EXPECT_DOUBLE_EQ(analyticAo(AnalyticOccluders{}, glm::vec3(0.f), kUp, 1.f), 1.0);
}

TEST(AnalyticAo, AgreesWithTheReferenceOnEveryFamily) {
    // One case per family, its points through Embree: within 4 standard errors plus the
    // two integrators' resolution (the quadrature's 1/1024 on a silhouette; scrambled Sobol at
    // 1024 spp can err beyond its replicates' spread where they happen to agree).
    std::set<std::string> families;
    for (const AoConvergenceCase& c : aoConvergenceCases()) {
        if (c.onScreen || !families.insert(c.family).second) continue;
        const ReferenceAO ref = referenceAtPoints(c, 1024);
        const std::vector<double> exact = exactAoAt(c);
        for (size_t i = 0; i < c.points.size(); ++i)
            EXPECT_NEAR(ref.ao[i], exact[i], 4.0 * ref.standardError[i] + 8e-3) << c.name << " point " << i;
    }
    EXPECT_GE(families.size(), 6u);
}

TEST(AnalyticAo, TheReferencesConeModelIsTheQuadraturesConeModel) {
    for (int cones : {6, 16}) {
        const std::vector<glm::vec4> set = diffuseConeSet(cones);
        const float aperture = defaultConeAperture(cones);
        for (const AoConvergenceCase& c : aoConvergenceCases()) {
            if (c.name != "plate h=0.5R a=2R off" && c.name != "sphere r=0.5R d=0.8R off") continue;
            const ReferenceAO mc = referenceAtPoints(c, 2048, ConeModelSampler(set, aperture));
            for (size_t i = 0; i < c.points.size(); ++i) {
                const double model = analyticConeModelAo(c.occluders, c.points[i], kUp, c.radius, set, aperture);
                EXPECT_NEAR(mc.ao[i], model, 4.0 * mc.standardError[i] + 5e-3) << c.name << " " << cones << " point " << i;
            }
        }
    }
}

// vct.below-plane=mirror: the parts of the caps below the floor's plane reflected above it,
// in the path tracer's cone model (ConeModelSampler) and the quadrature's alike. The Vogel
// sets' outer caps reach below the plane, and counted open that weight reads as light in the
// small closed room (exact AO 0 everywhere): the open model there is the set's below-plane
// weight, about 2.2% with 16 cones. Mirrored, the model of a room closed above the plane is 0,
// on an open plate case it moves by less than that weight, and the path tracer agrees with the
// quadrature within its error bar either way.
TEST(AnalyticAo, MirroredCapsKeepTheConeModelOnTheHemisphere) {
    const std::vector<glm::vec4> set = diffuseConeSet(16);
    const float aperture = defaultConeAperture(16);
    int rooms = 0;
    for (const AoConvergenceCase& c : aoConvergenceCases()) {
        if (c.onScreen || (c.family != "room" && c.name != "plate h=0.2R a=2R off")) continue;
        const std::vector<double> exact = exactAoAt(c);
        const bool closed = std::all_of(exact.begin(), exact.end(), [](double e) { return e == 0.0; });
        const ReferenceAO mc = referenceAtPoints(c, 1024, ConeModelSampler(set, aperture, true));
        double openMean = 0.0;
        for (size_t i = 0; i < c.points.size(); ++i) {
            const double open = analyticConeModelAo(c.occluders, c.points[i], kUp, c.radius, set, aperture);
            const double mirrored =
                analyticConeModelAo(c.occluders, c.points[i], kUp, c.radius, set, aperture, kAnalyticConeSamples, true);
            openMean += open / double(c.points.size());
            EXPECT_NEAR(mc.ao[i], mirrored, 4.0 * mc.standardError[i] + 5e-3) << c.name << " point " << i;
            EXPECT_LE(mirrored, open + 1e-9) << c.name << " point " << i << ": reflected directions can only close";
            EXPECT_LT(open - mirrored, 0.03) << c.name << " point " << i;
            if (closed) {
                EXPECT_EQ(mirrored, 0.0) << c.name << " point " << i;
                EXPECT_LT(mc.ao[i], 1e-3) << c.name << " point " << i;
            }
        }
        std::printf("[ %s ] open cone model, mean %.4f\n", c.name.c_str(), openMean);
        if (closed) {
            ++rooms;
            EXPECT_GT(openMean, 0.015) << c.name << ": the open model reads the set's weight below the plane";
        }
    }
    EXPECT_EQ(rooms, 1);
}

// ConeModelSampler::density is the distribution of sample()'s open directions, mirrored or not:
// over a fine grid of directions its integral is the share of samples that are open and above
// the plane (16 cones: 1 less the caps' weight below it; mirrored: 1), and its integral over the
// band within 15 degrees of the horizon, where the mirrored caps land, is the share of samples
// that fall there.
TEST(AnalyticAo, TheConeModelsDensityIsItsSamplesDistribution) {
    const glm::vec3 n(0.f, 0.f, 1.f);
    const float band = std::sin(15.f * 3.14159265f / 180.f);
    for (bool mirror : {false, true}) {
        const ConeModelSampler cones(diffuseConeSet(16), defaultConeAperture(16), mirror);
        // The integrals: theta in [0, pi], phi in [0, 2 pi), midpoints.
        const int nt = 720, np = 720;
        double total = 0.0, inBand = 0.0;
        for (int i = 0; i < nt; ++i) {
            const double theta = M_PI * (i + 0.5) / nt, dOmega = std::sin(theta) * (M_PI / nt) * (2.0 * M_PI / np);
            for (int j = 0; j < np; ++j) {
                const double phi = 2.0 * M_PI * (j + 0.5) / np;
                const glm::vec3 w(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                  float(std::cos(theta)));
                const double d = cones.density(w, n, n) * dOmega;
                total += d;
                if (w.z > 0.f && w.z < band) inBand += d;
            }
        }
        // The samples: a stratified grid of u.
        const int m = 400;
        int open = 0, below = 0, bandHits = 0;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const ConeModelSample c = cones.sample(glm::vec2((i + 0.5f) / m, (j + 0.5f) / m), n, n);
                if (c.closed) continue;
                if (c.belowPlane) {
                    ++below;
                    continue;
                }
                ++open;
                if (c.direction.z < band) ++bandHits;
            }
        const double samples = double(m) * m, openShare = open / samples, bandShare = bandHits / samples;
        std::printf("[ 16 cones%s ] density integral %.4f, open share %.4f; near the horizon %.4f, samples %.4f\n",
                    mirror ? " mirrored" : "", total, openShare, inBand, bandShare);
        EXPECT_NEAR(total, openShare, 3e-3);
        EXPECT_NEAR(inBand, bandShare, 2e-3);
        if (mirror) {
            EXPECT_EQ(below, 0);
            EXPECT_NEAR(total, 1.0, 3e-3);
        } else {
            EXPECT_GT(below / samples, 0.015) << "the 16 cones' caps reach below the plane";
        }
    }
}

// GI's cone model in the path tracer (reference.cone-model on --gi reference) against the
// quadrature's: with the occluders emitting 1 from both faces, a floor of albedo 1, a black
// sky and one reflection, a floor point's indirect light is 1 minus the cone model's AO with
// an unbounded radius. The floor points are the pixels of a low camera that sees them under
// the occluder. The same pixels' exact values differ from the cone model by the cone set's own
// error, which the path tracer must not reproduce.
TEST(AnalyticAo, TheGiReferencesConeModelIsTheQuadraturesConeModel) {
    constexpr float kUnbounded = 1.0e3f;
    int scored = 0;
    // 16 cones a second time with the caps' parts below the plane mirrored (vct.below-plane),
    // which the path tracer's MIS weighs by the sampler's density, reflected part included.
    for (const auto& [cones, mirror] : {std::pair{6, false}, std::pair{16, false}, std::pair{16, true}}) {
        const std::vector<glm::vec4> set = diffuseConeSet(cones);
        const float aperture = defaultConeAperture(cones);
        for (AoConvergenceCase c : giConvergenceCases()) {
            if (c.name != "plate h=0.5R a=2R gi" && c.name != "disc h=0.7R r=0.3R gi") continue;
            for (Material& m : c.scene.materials)
                if (m.name != "occluder") m.baseColorFactor = glm::vec4(1.f);
            Camera cam;
            cam.eye = {0.f, 0.2f * c.radius, 3.f * c.radius};
            cam.target = {0.f, 0.f, 0.f};
            cam.yfov = 0.35f;
            const View view = makeView(cam, 12, 12);
            ReferenceSettings s;
            s.spp = 1024;
            s.bounces = 1;
            s.sky = 0.f;
            s.progress = false;
            const ReferenceGI gi = referenceGI(c.scene, view, s, false, ConeModelSampler(set, aperture, mirror));
            double modelErr2 = 0.0, exactErr2 = 0.0;
            int n = 0;
            for (int y = 0; y < view.height; ++y)
                for (int x = 0; x < view.width; ++x) {
                    const CameraRay ray = cameraRay(view, float(x) + 0.5f, float(y) + 0.5f);
                    if (ray.direction.y >= -1e-3f) continue;
                    const float t = -ray.origin.y / ray.direction.y;
                    const glm::vec3 p = ray.origin + t * ray.direction;
                    if (c.occluders.occludes(ray.origin, ray.direction, t * 0.999f)) continue;
                    if (std::abs(p.x) > 2.f * c.radius || std::abs(p.z) > 2.f * c.radius) continue;
                    const double model =
                        kGiEmission *
                        (1.0 - analyticConeModelAo(c.occluders, p, kUp, kUnbounded, set, aperture, 96, mirror));
                    const double exact = kGiEmission * (1.0 - analyticAo(c.occluders, p, kUp, kUnbounded, 256));
                    const double mc = gi.indirect.at(x, y, 0), se = gi.indirectStderr.at(x, y, 0);
                    EXPECT_NEAR(mc, model, 4.0 * se + 5e-3)
                        << c.name << " " << cones << (mirror ? " mirrored" : "") << " pixel " << x << "," << y;
                    modelErr2 += (mc - model) * (mc - model);
                    exactErr2 += (mc - exact) * (mc - exact);
                    ++n;
                }
            ASSERT_GT(n, 20) << c.name;
            scored += n;
            const double toModel = std::sqrt(modelErr2 / n), toExact = std::sqrt(exactErr2 / n);
            std::printf("[ %s, %d cones%s ] %d floor pixels: RMS to the cone model %.4f, to the exact %.4f\n",
                        c.name.c_str(), cones, mirror ? " mirrored" : "", n, toModel, toExact);
            if (cones == 6 && c.name == "plate h=0.5R a=2R gi") {
                EXPECT_LT(2.0 * toModel, toExact);
            }
        }
    }
    EXPECT_GT(scored, 80);
}

TEST(AnalyticAo, RefiningTheConeSetDrivesTheConeErrorDown) {
    // RMS over one case per family (the points of each) of cone model - exact, for 6, 16, 32
    // and 64 cones; coarse quadratures keep it quick, well below the differences measured.
    std::vector<AoConvergenceCase> cases;
    std::set<std::string> families;
    for (const AoConvergenceCase& c : aoConvergenceCases())
        if (!c.onScreen && families.insert(c.family).second) cases.push_back(c);
    std::vector<std::vector<double>> exact;
    for (const AoConvergenceCase& c : cases) {
        exact.emplace_back();
        for (const glm::vec3& p : c.points) exact.back().push_back(analyticAo(c.occluders, p, kUp, c.radius, 384));
    }
    std::vector<double> errors;
    for (int cones : {6, 16, 32, 64}) {
        const std::vector<glm::vec4> set = diffuseConeSet(cones);
        const float aperture = defaultConeAperture(cones);
        double sum = 0.0;
        size_t n = 0;
        for (size_t k = 0; k < cases.size(); ++k) {
            const AoConvergenceCase& c = cases[k];
            for (size_t i = 0; i < c.points.size(); ++i) {
                const double d =
                    analyticConeModelAo(c.occluders, c.points[i], kUp, c.radius, set, aperture, 48) - exact[k][i];
                sum += d * d;
                ++n;
            }
        }
        errors.push_back(std::sqrt(sum / double(n)));
        std::printf("cone error, %d cones: %.4f\n", cones, errors.back());
    }
    for (size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << i;
    EXPECT_LT(errors.back(), 0.02);
}

// The GI families (eval/convergence.h): the occluders emit from both faces, nothing reflects,
// and a floor point gathers the emission times the share of its cosine-weighted hemisphere the
// emitters cover: on a disc's axis the view factor a^2 / (a^2 + h^2), on a sphere's (r / d)^2,
// in a closed room all of it.
TEST(AnalyticAo, GiCasesGatherTheClosedFormsOfTheirEmitters) {
    int checked = 0;
    for (const AoConvergenceCase& c : giConvergenceCases()) {
        EXPECT_FALSE(c.onScreen) << c.name;
        for (const Material& m : c.scene.materials) {
            EXPECT_EQ(glm::vec3(m.baseColorFactor), glm::vec3(0.f)) << c.name << ": " << m.name << " reflects";
            EXPECT_EQ(m.isEmissive(), m.doubleSided) << c.name << ": " << m.name;
        }
        const std::vector<double> gi = exactGiAt(c);
        const size_t centre = 12;  // floorGrid's middle point, (0, 0, 0)
        ASSERT_EQ(c.points.size(), 25u) << c.name;
        if (c.name == "disc h=0.7R r=0.3R gi") {
            ++checked;
            EXPECT_NEAR(gi[centre], kGiEmission * 0.09 / (0.09 + 0.49), 2e-3);
        } else if (c.name == "sphere r=0.5R d=0.8R gi") {
            ++checked;
            EXPECT_NEAR(gi[centre], kGiEmission * std::pow(0.5 / 0.8, 2), 2e-3);
        } else if (c.family == "room") {
            ++checked;
            for (double v : gi) EXPECT_NEAR(v, kGiEmission, 1e-9) << c.name;
        }
        // The cone model gathers what its cones cover: between nothing and everything.
        for (double v : coneModelGiAt(c, ParamMap())) {
            EXPECT_GE(v, 0.0) << c.name;
            EXPECT_LE(v, kGiEmission + 1e-9) << c.name;
        }
    }
    EXPECT_EQ(checked, 4) << "a case the closed forms name is missing";
}

// firstHit is the nearest occluder along the ray, in closed form: a rectangle, a disc and a
// sphere on one axis, each hit where the plane or the sphere says, the nearest winning, none
// past tMax or behind the origin.
TEST(AnalyticAo, FirstHitIsTheNearestOccluderAlongTheRay) {
    AnalyticOccluders occ;
    occ.rects.push_back({glm::vec3(0.f, 3.f, 0.f), glm::vec3(1.f, 0.f, 0.f), glm::vec3(0.f, 0.f, 1.f)});
    occ.discs.push_back({glm::vec3(0.f, 2.f, 0.f), glm::vec3(0.f, 1.f, 0.f), 0.5f});
    occ.spheres.push_back({glm::vec3(0.f, 5.f, 0.f), 1.f});
    const glm::vec3 up(0.f, 1.f, 0.f);
    EXPECT_FLOAT_EQ(occ.firstHit(glm::vec3(0.f), up, 10.f), 2.f);                   // the disc
    EXPECT_FLOAT_EQ(occ.firstHit(glm::vec3(0.7f, 0.f, 0.f), up, 10.f), 3.f);        // past the disc's rim: the rect
    EXPECT_FLOAT_EQ(occ.firstHit(glm::vec3(0.f, 3.5f, 0.f), up, 10.f), 0.5f);       // above both: the sphere at y 4
    EXPECT_FLOAT_EQ(occ.firstHit(glm::vec3(0.f, 5.f, 0.f), up, 10.f), 1.f);         // inside the sphere: its far side
    EXPECT_TRUE(std::isinf(occ.firstHit(glm::vec3(0.f), up, 1.9f)));                // all beyond tMax
    EXPECT_TRUE(std::isinf(occ.firstHit(glm::vec3(0.f), -up, 10.f)));               // all behind
    EXPECT_TRUE(std::isinf(occ.firstHit(glm::vec3(1.5f, 0.f, 0.f), up, 10.f)));     // beside all three
    // A slanted ray meets the rect's plane at 3 / cos.
    const glm::vec3 d = glm::normalize(glm::vec3(0.9f, 3.f, 0.f));  // x 0.6 at the disc: past its rim
    EXPECT_NEAR(occ.firstHit(glm::vec3(0.f), d, 10.f), 3.f / d.y, 1e-5f);
    // occludes agrees with it.
    EXPECT_TRUE(occ.occludes(glm::vec3(0.f), up, 2.f));
    EXPECT_FALSE(occ.occludes(glm::vec3(0.f), up, 1.99f));
}
