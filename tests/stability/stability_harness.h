// The stability suite's harness (BRIEF section 6): runs every AO and GI method over one
// extreme scene, checks the invariants every output must keep (finite, AO in [0, 1],
// radiance >= 0), measures an error where a closed form or the reference applies, and
// records one cell per case x method for docs/stability.md.
//
// The report is written at the end of the run when VCT_STABILITY_REPORT=path is set:
//   VCT_STABILITY_REPORT=docs/stability.md build/vct_tests_stability
#pragma once

#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace stab {

// One column of the report: an AO method (aovs ao, depth) or a GI method (aovs indirect,
// beauty, depth).
struct Method {
    std::string label;  // column name
    std::string ao = "none";
    std::string gi = "none";
    bool isGi() const { return gi != "none"; }
};
const std::vector<Method>& aoMethodColumns();  // the 8 AO estimators
const std::vector<Method>& giMethodColumns();  // vct, reference
std::vector<Method> allMethodColumns();

// What one render of one method produced.
struct Outcome {
    bool refused = false;        // the renderer threw: message holds why
    std::string message;
    vct::Image ao;               // 1 channel (AO methods)
    vct::Image indirect;         // 3 channels (GI methods)
    vct::Image beauty;           // 3 channels (GI methods)
    vct::Image depth;            // 1 channel; > 0 on surface pixels
    // Invariant violations found by checkInvariants (empty = none).
    std::vector<std::string> violations;
    double ms = 0.0;
    bool ok() const { return !refused && violations.empty(); }
};

// Renders `method` with `base` (its ao/gi/aovs are overwritten). Catches exceptions as a
// refusal. Checks every returned AOV: finite; AO in [0, 1]; radiance >= 0.
Outcome runMethod(vct::RenderSession& session, vct::RenderRequest base, const Method& method);

// Means over surface pixels (depth > 0); for 3-channel images the mean of the channels.
double surfaceMean(const vct::Image& img, const vct::Image& depth);
double surfaceMax(const vct::Image& img, const vct::Image& depth);
// Mean |a - b| over pixels that are surface in both depth maps.
double meanAbsDiff(const vct::Image& a, const vct::Image& b, const vct::Image& depth);
// Mean |img - value| over surface pixels.
double meanAbsErrorTo(const vct::Image& img, const vct::Image& depth, double value);
// The AOV a method is judged on: ao for AO methods, indirect for GI methods.
const vct::Image& primary(const Outcome& o, const Method& m);

// The report. Cells are keyed by case and column; notes are free text per case.
struct Cell {
    std::string text;  // "pass", "0.031", "refused: ...", "FAIL: NaN in ao"
    bool ok = true;
};
// Records a cell of the report and fails the current test if the cell is not ok.
void recordCell(const std::string& caseName, const std::string& column, const Cell& cell);
void recordCaseInfo(const std::string& caseName, const std::string& what, const std::string& errorMeaning);
void recordNote(const std::string& text);
// The standard cell for an outcome: violations and refusals first, else the error value
// (formatted) or "pass".
Cell cellFor(const Outcome& o, std::optional<double> error = std::nullopt, int digits = 3);
std::string fmt(double v, int digits = 3);

// The scenes (every length times `scale`).
// Floor 4 x 4, a unit box on it, a back wall 2 high: a bit of every kind of occlusion.
vct::Scene cornerScene(float scale, glm::vec3 albedo = glm::vec3(0.6f), bool directionalLight = true);
vct::Camera cornerCamera(float scale);

// The cases' common request: size^2 pixels, 16 reference spp with one replicate, 48^3 voxels,
// sky 1, the given seed.
vct::RenderRequest baseRequest(const vct::Camera& camera, float radius, int size, uint32_t seed);

}  // namespace stab
