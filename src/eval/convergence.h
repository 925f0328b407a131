// The convergence harness of voxel cone tracing: families of closed-form AO cases (plates
// and discs above a floor at heights and sizes around R, a wall, a right-angle corner, a
// sphere above a plane, closed rooms), each scored at 25 fixed floor points, some within R of
// an occluder's edge, and GI on the same geometry with the occluders emitting. Every point has
// three values: the exact value and the cone model of VCT's cone set, both by analytic
// quadrature (eval/analytic_ao.h), and what VCT computes there through the registry's method
// (dense or sparse, any resolution and --param), on a G-buffer made of the points. VCT's
// error splits into
//   cone error  = cone model - exact   (the cone set's, whatever the voxels),
//   voxel error = VCT - cone model     (what finer voxels must drive to zero).
// An occluder is off screen (only the floor points are in the G-buffer, as when the camera
// looks down under a shelf) or on screen (points on the occluder join the G-buffer), which
// changes the region an AO-only render voxelizes.
#pragma once

#include "core/params.h"
#include "eval/analytic_ao.h"
#include "scene/scene.h"
#include "vdb/sparse_cone.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vct {

struct AoConvergenceCase {
    std::string family;  // plate, slab, disc, wall, corner, room, sphere
    std::string name;    // e.g. "plate h=0.5R a=2R off"
    float radius = 1.f;  // R
    Scene scene;         // the floor and the occluders as triangles
    AnalyticOccluders occluders;          // the same occluders, exactly
    // Scored points on the floor (geometric normal +Y); exactAoAt and coneModelAoAt score them
    // with the shading normal +Y too.
    std::vector<glm::vec3> points;
    glm::vec3 shadingNormal{0.f, 1.f, 0.f};  // the points' shading normal (the harness's cases: +Y)
    std::vector<glm::vec3> visiblePoints; // on screen: points on the occluders' surfaces (not scored)
    std::vector<glm::vec3> visibleNormals;
    bool onScreen = false;
};

// Every case of every family, off and on screen.
std::vector<AoConvergenceCase> aoConvergenceCases();

// Exact AO and cone-model AO at a case's points (the cone set and aperture of `params`'
// vct.cones / vct.aperture).
std::vector<double> exactAoAt(const AoConvergenceCase& c);
std::vector<double> coneModelAoAt(const AoConvergenceCase& c, const ParamMap& params);

// VCT's AO at a case's points: --ao vct at `voxelRes` on `backend` (gl or vdb) with `params`,
// through the registry's method on a G-buffer of the points (and, on screen, the visible
// occluder points). Needs the GL context.
std::vector<double> vctAoAt(const AoConvergenceCase& c, int voxelRes, const std::string& backend,
                            const ParamMap& params);

// GI on the same families: the case's occluders emit kGiEmission from both faces and reflect
// nothing, the floor reflects nothing, the sky is black. A floor point's gathered light (its
// indirect light over its albedo) is then kGiEmission times the cosine-weighted share of its
// hemisphere the occluders cover, whatever the distance: exactly 1 minus the occluders' AO
// with an unbounded radius, and the cone model's gathered light is 1 minus the cone model's AO
// the same way. Every bounce in the voxels gathers black (nothing reflects), so the closed
// form holds with any vct.bounces. The closed rooms are closed emissive boxes: every point
// gathers kGiEmission. Only the off-screen cases: GI voxelizes the whole scene, so a visible
// occluder changes nothing.
inline constexpr float kGiEmission = 1.f;
std::vector<AoConvergenceCase> giConvergenceCases();
std::vector<double> exactGiAt(const AoConvergenceCase& c);
std::vector<double> coneModelGiAt(const AoConvergenceCase& c, const ParamMap& params);
// VCT's gathered light at a case's points: --gi vct (sky 0), the indirect light of points of
// albedo 1.
std::vector<double> vctGiAt(const AoConvergenceCase& c, int voxelRes, const std::string& backend,
                            const ParamMap& params);

// One lane of VCT's AO gather at a case's point (--backend vdb, the lanes as the sparse march
// runs them), beside what exact visibility says of the same lane.
struct AoLaneRecord {
    SparseLane lane;
    // The occluded fraction of the lane's own cone (its axis and the lanes' aperture, cut at R;
    // analyticConeModelAo): what the lane converges to. A lane below the surface's plane is decided
    // by the plane (cone_laneState) and carries VCT's value, or with vct.below-plane=mirror is
    // scored as the reflected lane it is marched as.
    double exactOcclusion = 0.0;
    // Where the lane's ray from the point meets an occluder (world units; infinity when not
    // within 4 R).
    float rayHit = 0.f;
};
struct AoLaneTrace {
    float voxelSize = 0.f;        // world units
    float radius = 0.f;           // R, world units
    float laneApertureDeg = 0.f;  // each lane's full apex angle
    std::vector<AoLaneRecord> lanes;
};
// The lanes of point `point` (an index into c.points) at `voxelRes`, with `params` as vctAoAt
// takes them (--backend vdb: the dense path marches the same lanes).
AoLaneTrace vctAoLanesAt(const AoConvergenceCase& c, int voxelRes, const ParamMap& params, size_t point);

// RMS and largest absolute difference of a - b.
struct PointError {
    double rms = 0.0;
    double max = 0.0;
};
PointError pointError(const std::vector<double>& a, const std::vector<double>& b);

// The two rules the tables check, on a case's RMS errors from the coarsest step to the finest.
// The voxel error (VCT - cone model) converges when each doubling of the resolution divides it
// by at least kVoxelErrorFall (a step already below kVoxelErrorFloor only has to stay below it)
// and the finest is at most kVoxelErrorFinest.
inline constexpr double kVoxelErrorFall = 1.5;
inline constexpr double kVoxelErrorFloor = 0.01;
inline constexpr double kVoxelErrorFinest = 0.02;
bool voxelErrorConverges(const std::vector<double>& voxelError);
// The total error (VCT - exact) of a schedule that refines the cone set with the voxels
// refines when it never grows from one step to the next and the finest is at most
// kTotalErrorFinest.
inline constexpr double kTotalErrorFinest = 0.05;
bool totalErrorRefines(const std::vector<double>& totalError);

// One step of such a schedule: a resolution and the cone set (vct.cones) and lanes (vct.lanes,
// 0 = auto) that march it.
struct ConeScheduleStep {
    int voxelRes = 0;
    int cones = 0;
    int lanes = 0;
};
// "RES:CONES[:LANES],..." (e.g. "64:6,128:16,256:64:64"), resolutions strictly increasing.
// Throws UsageError naming the step that is not of that form; the cone set and the
// lanes are checked by the cone settings (vct.cones, vct.lanes) when a step runs.
std::vector<ConeScheduleStep> parseConeSchedule(const std::string& text);

}  // namespace vct
