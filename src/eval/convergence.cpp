#include "eval/convergence.h"

#include "cone/cone_set.h"
#include "cone/cone_shared.h"
#include "cone/cone_settings.h"
#include "core/errors.h"
#include "core/method.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "methods/registry.h"
#include "render/plan.h"
#include "scene/camera.h"
#include "scene/scene_builder.h"
#include "vct/sparse_vct.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace vct {

namespace {

std::string fmt(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// The floor: a square of side `size` at y = 0 facing up, under everything.
void addFloor(SceneBuilder& b, int material, float size) {
    b.addPlane("floor", glm::vec3(0.f), glm::vec2(size), material);
}

void addRect(SceneBuilder& b, AnalyticOccluders& occ, const std::string& name, const AnalyticRect& r, int material) {
    // A parallelogram (two triangles); both faces occlude.
    b.addQuad(name, r.center - r.u - r.v, 2.f * r.u, 2.f * r.v, material);
    occ.rects.push_back(r);
}

void addDisc(SceneBuilder& b, AnalyticOccluders& occ, const std::string& name, const AnalyticDisc& d, int material) {
    // A fan fine enough that the polygon's area is within 0.01% of the disc's.
    const int segments = 192;
    const glm::vec3 n = glm::normalize(d.normal);
    const glm::vec3 t = glm::normalize(std::abs(n.y) < 0.9f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
    const glm::vec3 s = glm::cross(n, t);
    std::vector<glm::vec3> pos{d.center};
    std::vector<uint32_t> idx;
    for (int i = 0; i < segments; ++i) {
        const float a = 2.f * float(M_PI) * float(i) / float(segments);
        pos.push_back(d.center + d.radius * (std::cos(a) * t + std::sin(a) * s));
        idx.insert(idx.end(), {0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % segments)});
    }
    b.addNode(name, b.addMesh(name, pos, {}, idx, material));
    occ.discs.push_back(d);
}

void addSphere(SceneBuilder& b, AnalyticOccluders& occ, const std::string& name, const AnalyticSphere& sp,
               int material) {
    const int rings = 64, sectors = 128;
    std::vector<glm::vec3> pos, nrm;
    std::vector<uint32_t> idx;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= sectors; ++j) {
            const float th = float(M_PI) * float(i) / float(rings), ph = 2.f * float(M_PI) * float(j) / float(sectors);
            const glm::vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
            pos.push_back(sp.center + sp.radius * n);
            nrm.push_back(n);
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sectors; ++j) {
            const uint32_t a = uint32_t(i * (sectors + 1) + j), b2 = a + uint32_t(sectors + 1);
            idx.insert(idx.end(), {a, a + 1, b2, a + 1, b2 + 1, b2});
        }
    b.addNode(name, b.addMesh(name, pos, nrm, idx, material));
    occ.spheres.push_back(sp);
}

// An axis-aligned box [lo, hi] as six rectangles.
void addBox(SceneBuilder& b, AnalyticOccluders& occ, const std::string& name, const glm::vec3& lo, const glm::vec3& hi,
            int material) {
    b.addBox(name, lo, hi, material);
    const glm::vec3 c = 0.5f * (lo + hi), e = 0.5f * (hi - lo);
    for (int a = 0; a < 3; ++a)
        for (float side : {-1.f, 1.f}) {
            glm::vec3 center = c, u(0.f), v(0.f);
            center[a] += side * e[a];
            u[(a + 1) % 3] = e[(a + 1) % 3];
            v[(a + 2) % 3] = e[(a + 2) % 3];
            occ.rects.push_back({center, u, v});
        }
}

// A 5 x 5 grid of floor points, x and z in [lo, hi].
std::vector<glm::vec3> floorGrid(float lo, float hi) {
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            pts.emplace_back(lo + (hi - lo) * float(j) / 4.f, 0.f, lo + (hi - lo) * float(i) / 4.f);
    return pts;
}

struct CaseBuilder {
    AoConvergenceCase c;
    SceneBuilder b{"convergence"};
    int floorMaterial, occluderMaterial;
    explicit CaseBuilder(const std::string& family, const std::string& name) {
        c.family = family;
        c.name = name;
        floorMaterial = b.addMaterial("floor", glm::vec3(0.7f));
        occluderMaterial = b.addMaterial("occluder", glm::vec3(0.5f));
    }
    AoConvergenceCase finish(float floorSize) {
        addFloor(b, floorMaterial, floorSize);
        c.scene = b.toScene();
        return c;
    }
};

// The same case with its occluder on screen: a few points on the occluder's surface join the
// G-buffer (their AO is not scored).
AoConvergenceCase onScreen(AoConvergenceCase c, std::vector<glm::vec3> points, glm::vec3 normal) {
    c.onScreen = true;
    c.name.replace(c.name.size() - 3, 3, "on");
    c.visiblePoints = std::move(points);
    c.visibleNormals.assign(c.visiblePoints.size(), normal);
    return c;
}

}  // namespace

std::vector<AoConvergenceCase> aoConvergenceCases() {
    const float R = 1.f;
    std::vector<AoConvergenceCase> cases;
    auto add = [&](AoConvergenceCase off, std::vector<glm::vec3> visible, glm::vec3 normal) {
        off.radius = R;
        cases.push_back(off);
        cases.push_back(onScreen(off, std::move(visible), normal));
    };
    // Square plates: heights 0.2R..0.9R, sides smaller and larger than R; points under the
    // plate and out to R/2 past its edge.
    for (float h : {0.2f, 0.5f, 0.9f})
        for (float side : {0.5f, 2.f}) {
            CaseBuilder cb("plate", "plate h=" + fmt(h) + "R a=" + fmt(side) + "R off");
            const AnalyticRect r{glm::vec3(0.f, h, 0.f), glm::vec3(side / 2, 0.f, 0.f), glm::vec3(0.f, 0.f, side / 2)};
            addRect(cb.b, cb.c.occluders, "plate", r, cb.occluderMaterial);
            cb.c.points = floorGrid(-(side / 2 + 0.5f * R), side / 2 + 0.5f * R);
            add(cb.finish(8.f * R), {glm::vec3(0.f, h, 0.f), glm::vec3(side / 4, h, 0.f)}, glm::vec3(0, -1, 0));
        }
    // A thick slab (a tenth of R) over a wide area, as a shelf or an overhang above the view.
    for (float h : {0.3f, 0.56f}) {
        CaseBuilder cb("slab", "slab h=" + fmt(h) + "R t=0.1R off");
        addBox(cb.b, cb.c.occluders, "slab", glm::vec3(-3.f, h, -2.f), glm::vec3(3.f, h + 0.1f, 2.f), cb.occluderMaterial);
        cb.c.points = floorGrid(-1.5f * R, 1.5f * R);
        add(cb.finish(10.f * R), {glm::vec3(0.f, h, 0.f), glm::vec3(1.f, h, 0.f)}, glm::vec3(0, -1, 0));
    }
    // Discs.
    for (float h : {0.3f, 0.7f})
        for (float radius : {0.3f, 1.5f}) {
            CaseBuilder cb("disc", "disc h=" + fmt(h) + "R r=" + fmt(radius) + "R off");
            addDisc(cb.b, cb.c.occluders, "disc", AnalyticDisc{glm::vec3(0.f, h, 0.f), glm::vec3(0, 1, 0), radius},
                    cb.occluderMaterial);
            cb.c.points = floorGrid(-(radius + 0.5f * R), radius + 0.5f * R);
            add(cb.finish(8.f * R), {glm::vec3(0.f, h, 0.f), glm::vec3(radius / 2, h, 0.f)}, glm::vec3(0, -1, 0));
        }
    // A wall (the plane x = 0, 4R tall and 8R wide) and points at distances 0.02R..1.2R.
    {
        CaseBuilder cb("wall", "wall off");
        addRect(cb.b, cb.c.occluders, "wall",
                AnalyticRect{glm::vec3(0.f, 2.f * R, 0.f), glm::vec3(0.f, 2.f * R, 0.f), glm::vec3(0.f, 0.f, 4.f * R)},
                cb.occluderMaterial);
        for (int i = 0; i < 25; ++i) {
            const float d = 0.02f * R * std::pow(60.f, float(i) / 24.f);  // 0.02R .. 1.2R, log-spaced
            cb.c.points.emplace_back(d, 0.f, 0.4f * R * float(i % 5 - 2));
        }
        add(cb.finish(8.f * R), {glm::vec3(0.f, 0.5f, 0.f), glm::vec3(0.f, 1.f, 0.5f)}, glm::vec3(1, 0, 0));
    }
    // A right-angle corner: walls x = 0 and z = 0; points at 0.05R..1.1R from both.
    {
        CaseBuilder cb("corner", "corner off");
        addRect(cb.b, cb.c.occluders, "wall_x",
                AnalyticRect{glm::vec3(0.f, 2.f * R, 2.f * R), glm::vec3(0.f, 2.f * R, 0.f), glm::vec3(0.f, 0.f, 2.f * R)},
                cb.occluderMaterial);
        addRect(cb.b, cb.c.occluders, "wall_z",
                AnalyticRect{glm::vec3(2.f * R, 2.f * R, 0.f), glm::vec3(2.f * R, 0.f, 0.f), glm::vec3(0.f, 2.f * R, 0.f)},
                cb.occluderMaterial);
        for (float x : {0.05f, 0.15f, 0.3f, 0.6f, 1.1f})
            for (float z : {0.05f, 0.15f, 0.3f, 0.6f, 1.1f}) cb.c.points.emplace_back(x * R, 0.f, z * R);
        add(cb.finish(8.f * R), {glm::vec3(0.f, 0.5f, 0.5f), glm::vec3(0.5f, 0.5f, 0.f)}, glm::vec3(1, 0, 0));
    }
    // Closed rooms: four walls and a ceiling on the floor, each one sheet. In a room whose
    // diagonal is shorter than R nothing is open (exact AO 0 at every point): all VCT reports
    // there crossed a wall. A room taller and wider than R is open only where R falls short of
    // its walls.
    for (auto [side, height] : {std::pair<float, float>{0.6f, 0.4f}, {1.6f, 1.2f}}) {
        CaseBuilder cb("room", "room " + fmt(side) + "R x " + fmt(height) + "R off");
        const float h = side / 2, y = height / 2;
        for (float sx : {-1.f, 1.f}) {
            addRect(cb.b, cb.c.occluders, "wall_x",
                    AnalyticRect{glm::vec3(sx * h, y, 0.f), glm::vec3(0.f, y, 0.f), glm::vec3(0.f, 0.f, h)},
                    cb.occluderMaterial);
            addRect(cb.b, cb.c.occluders, "wall_z",
                    AnalyticRect{glm::vec3(0.f, y, sx * h), glm::vec3(h, 0.f, 0.f), glm::vec3(0.f, y, 0.f)},
                    cb.occluderMaterial);
        }
        addRect(cb.b, cb.c.occluders, "ceiling",
                AnalyticRect{glm::vec3(0.f, height, 0.f), glm::vec3(h, 0.f, 0.f), glm::vec3(0.f, 0.f, h)},
                cb.occluderMaterial);
        cb.c.points = floorGrid(-0.9f * h, 0.9f * h);
        add(cb.finish(8.f * R), {glm::vec3(0.f, height, 0.f), glm::vec3(h / 2, height, 0.f)}, glm::vec3(0, -1, 0));
    }
    // Spheres above the floor (on the axis, AO = 1 - (r/d)^2 once R >= d).
    for (auto [radius, height] : {std::pair<float, float>{0.25f, 0.6f}, {0.5f, 0.8f}}) {
        CaseBuilder cb("sphere", "sphere r=" + fmt(radius) + "R d=" + fmt(height) + "R off");
        addSphere(cb.b, cb.c.occluders, "sphere", AnalyticSphere{glm::vec3(0.f, height, 0.f), radius},
                  cb.occluderMaterial);
        cb.c.points = floorGrid(-1.f * R, 1.f * R);
        add(cb.finish(8.f * R), {glm::vec3(0.f, height + radius, 0.f), glm::vec3(0.f, height - radius, 0.f)},
            glm::vec3(0, 1, 0));
    }
    return cases;
}

namespace {

// Exact AO and cone-model AO at a case's points for radius R (the case's own for AO, an
// unbounded one for GI).
std::vector<double> exactAo(const AoConvergenceCase& c, float radius) {
    std::vector<double> out;
    for (const glm::vec3& p : c.points) out.push_back(analyticAo(c.occluders, p, glm::vec3(0, 1, 0), radius));
    return out;
}

std::vector<double> coneModelAo(const AoConvergenceCase& c, const ParamMap& params, float radius) {
    const ConeSettings cone = readConeSettings(params);
    const std::vector<glm::vec4> set = diffuseConeSet(cone.coneCount);
    std::vector<double> out;
    for (const glm::vec3& p : c.points)
        out.push_back(analyticConeModelAo(c.occluders, p, glm::vec3(0, 1, 0), radius, set, cone.apertureDeg,
                                          kAnalyticConeSamples, cone.belowPlane == ConeBelowPlane::Mirror));
    return out;
}

// The AO radius that stands for an unbounded one: every case's occluders lie within 10 R.
constexpr float kGiRadius = 1.0e3f;

// The light a point gathers from emitters of kGiEmission that cover 1 - ao of its hemisphere.
std::vector<double> gatheredFromAo(std::vector<double> ao) {
    for (double& v : ao) v = kGiEmission * (1.0 - v);
    return ao;
}

// The registry's VCT method (--ao vct or --gi vct) at a case's points, on a G-buffer of the
// points (and, on screen, the visible occluder points): the AO, or the indirect light's first
// channel, at the scored points.
// `inspect`, when given, sees the method's context once it has run.
std::vector<double> vctAt(const AoConvergenceCase& c, int voxelRes, const std::string& backend, const ParamMap& params,
                          bool gi, const std::function<void(MethodContext&)>& inspect = {}) {
    GlContext& gl = GlContext::shared();
    const Scene& scene = c.scene;
    const GpuScene gpu = uploadScene(scene);
    // GI's points have albedo 1: their indirect light is the light they gather.
    const glm::vec3 albedo = gi ? glm::vec3(1.f) : glm::vec3(0.7f);
    std::vector<GBufferPoint> pts;
    for (const glm::vec3& p : c.points) pts.push_back({p, c.shadingNormal, glm::vec3(0, 1, 0), albedo, true});
    for (size_t i = 0; i < c.visiblePoints.size(); ++i)
        pts.push_back({c.visiblePoints[i], c.visibleNormals[i], c.visibleNormals[i], glm::vec3(0.5f), true});
    const int width = int(pts.size());
    const GBuffer gbuffer = makeGBufferFromPoints(pts, width, 1);

    RenderRequest r;
    r.width = width;
    r.height = 1;
    r.params = params;
    if (gi) {
        r.gi = "vct";
        r.aovs = {"indirect"};
        r.sky = 0.f;
        // Nothing reflects, so every bounce between voxels gathers and re-injects zero: the
        // images are those of any vct.bounces, without the bounces' gathers at every voxel.
        if (!r.params.has("vct.bounces")) r.params.set("vct.bounces", "0");
    } else {
        r.ao = "vct";
        r.aovs = {"ao"};
    }
    r.radius = c.radius;
    r.voxelRes = voxelRes;
    r.backend = backend;
    r.camera = defaultCamera(scene.bounds, float(width), 0.8f);
    const SceneFeatures features = analyzeScene(scene);
    const RenderPlan plan = planRender(features, r);
    const View view = makeView(r.camera, width, 1);
    PassTimer timer;
    StateStore session, frame;
    FrameOutputs outputs;
    std::map<std::string, int> runCounts;
    nlohmann::json extra;
    MethodContext ctx{plan, r, scene, features, gpu, &gbuffer, view, timer, session, frame, outputs, runCounts, extra};
    if (gi)
        requireMethod(MethodKind::GI, "vct", "--gi")->execute(ctx);
    else
        requireMethod(MethodKind::AO, "vct", "--ao")->execute(ctx);
    gl.checkErrors("convergence " + c.name);
    if (inspect) inspect(ctx);
    const ResourceId id = gi ? kGiIndirect : kAo;
    const FrameResource* res = outputs.find(id);
    if (!res) throw InternalError("vctAt", "the VCT method wrote no " + std::string(gi ? "indirect light" : "AO"));
    const int channels = gi ? 4 : 1;
    const Image img = res->image.empty() ? readTexture2D(res->texture.id(), width, 1, channels) : res->image;
    std::vector<double> out;
    for (size_t i = 0; i < c.points.size(); ++i) out.push_back(img.pixels[i * size_t(img.channels)]);
    return out;
}

}  // namespace

std::vector<double> exactAoAt(const AoConvergenceCase& c) { return exactAo(c, c.radius); }

std::vector<double> coneModelAoAt(const AoConvergenceCase& c, const ParamMap& params) {
    return coneModelAo(c, params, c.radius);
}

std::vector<double> vctAoAt(const AoConvergenceCase& c, int voxelRes, const std::string& backend,
                            const ParamMap& params) {
    return vctAt(c, voxelRes, backend, params, false);
}

AoLaneTrace vctAoLanesAt(const AoConvergenceCase& c, int voxelRes, const ParamMap& params, size_t point) {
    if (point >= c.points.size())
        throw UsageError("point " + std::to_string(point) + ": the case '" + c.name + "' has " +
                         std::to_string(c.points.size()) + " points (0.." + std::to_string(c.points.size() - 1) + ")");
    const ConeSettings cone = readConeSettings(params);
    AoLaneTrace trace;
    trace.radius = c.radius;
    vctAt(c, voxelRes, "vdb", params, false, [&](MethodContext& ctx) {
        const SparseFrame& f = renderedSparseFrame(ctx);
        trace.voxelSize = f.voxels->voxelSize;
        const SparseLanes marched = sparseConeAOLanes(*f.voxels, f.points[point], c.radius, cone);
        trace.laneApertureDeg = marched.apertureDeg;
        for (const SparseLane& lane : marched.lanes) trace.lanes.push_back({lane, 0.0, 0.f});
    });
    const glm::vec3 p = c.points[point], n = c.shadingNormal;
    const bool mirror = cone.belowPlane == ConeBelowPlane::Mirror;
    const std::vector<glm::vec4> axes = diffuseConeSet(cone.coneCount);
    for (AoLaneRecord& r : trace.lanes) {
        r.rayHit = c.occluders.firstHit(p, r.lane.direction, 4.f * c.radius);
        // A lane below the plane of a cone above it (cone_laneState's open lane) is open, or with
        // vct.below-plane=mirror marched reflected above the plane (its record's direction is the
        // reflected one).
        const bool reflected = mirror && gpu::cone_laneState(r.lane.tangent.z, axes[size_t(r.lane.cone)].z) ==
                                             gpu::CONE_LANE_OPEN;
        const glm::vec3 tangent =
            reflected ? gpu::cone_mirrored(r.lane.tangent, glm::vec3(0.f, 0.f, 1.f)) : r.lane.tangent;
        r.exactOcclusion =
            tangent.z > 0.f ? 1.0 - analyticConeModelAo(c.occluders, p, n, c.radius, {glm::vec4(tangent, 1.f)},
                                                        trace.laneApertureDeg, kAnalyticConeSamples, mirror)
                            : double(r.lane.alpha);
    }
    return trace;
}

std::vector<AoConvergenceCase> giConvergenceCases() {
    std::vector<AoConvergenceCase> out;
    for (AoConvergenceCase c : aoConvergenceCases()) {
        if (c.onScreen) continue;
        c.name.replace(c.name.size() - 3, 3, "gi");
        for (Material& m : c.scene.materials) {
            const bool emitter = m.name == "occluder";
            m.baseColorFactor = glm::vec4(0.f, 0.f, 0.f, 1.f);
            m.emissiveFactor = glm::vec3(emitter ? kGiEmission : 0.f);
            m.doubleSided = emitter;
        }
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<double> exactGiAt(const AoConvergenceCase& c) { return gatheredFromAo(exactAo(c, kGiRadius)); }

std::vector<double> coneModelGiAt(const AoConvergenceCase& c, const ParamMap& params) {
    return gatheredFromAo(coneModelAo(c, params, kGiRadius));
}

std::vector<double> vctGiAt(const AoConvergenceCase& c, int voxelRes, const std::string& backend,
                            const ParamMap& params) {
    return vctAt(c, voxelRes, backend, params, true);
}

PointError pointError(const std::vector<double>& a, const std::vector<double>& b) {
    PointError e;
    if (a.size() != b.size() || a.empty()) throw InternalError("pointError", "sizes differ or are empty");
    double s = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double d = a[i] - b[i];
        s += d * d;
        e.max = std::max(e.max, std::abs(d));
    }
    e.rms = std::sqrt(s / double(a.size()));
    return e;
}

bool voxelErrorConverges(const std::vector<double>& voxelError) {
    if (voxelError.empty() || !(voxelError.back() <= kVoxelErrorFinest)) return false;
    for (size_t i = 1; i < voxelError.size(); ++i)
        if (!(voxelError[i] * kVoxelErrorFall <= voxelError[i - 1] || voxelError[i] < kVoxelErrorFloor)) return false;
    return true;
}

bool totalErrorRefines(const std::vector<double>& totalError) {
    if (totalError.empty() || !(totalError.back() <= kTotalErrorFinest)) return false;
    for (size_t i = 1; i < totalError.size(); ++i)
        if (!(totalError[i] <= totalError[i - 1])) return false;
    return true;
}

std::vector<ConeScheduleStep> parseConeSchedule(const std::string& text) {
    std::vector<ConeScheduleStep> steps;
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
        const std::string where = "schedule step " + std::to_string(steps.size() + 1) + " '" + item + "'";
        std::vector<int> fields;
        std::stringstream parts(item);
        for (std::string field; std::getline(parts, field, ':');) {
            size_t used = 0;
            int value = -1;
            try {
                value = std::stoi(field, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (field.empty() || used != field.size() || value < 0)
                throw UsageError(where + ": '" + field + "' is not a whole number >= 0 (RES:CONES[:LANES])");
            fields.push_back(value);
        }
        if (fields.size() < 2 || fields.size() > 3)
            throw UsageError(where + ": expected RES:CONES or RES:CONES:LANES");
        ConeScheduleStep step{fields[0], fields[1], fields.size() == 3 ? fields[2] : 0};
        if (!steps.empty() && step.voxelRes <= steps.back().voxelRes)
            throw UsageError(where + ": resolutions must increase from step to step");
        steps.push_back(step);
    }
    if (steps.empty()) throw UsageError("schedule '" + text + "' has no steps (RES:CONES[:LANES],...)");
    return steps;
}

}  // namespace vct
