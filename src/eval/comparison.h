// One comparison: every method variant rendered on one scene, camera and G-buffer (and
// one voxelization), scored against the ray-traced reference on valid (non-sky) pixels
// and, where the scene marks off-screen occluders, inside and outside the derived ROI
// (error where only a world-space method can be right). Used by `vct compare` and, case by case, by `vct sweep`.
#pragma once

#include "core/request.h"
#include "image/image.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vct {

struct MethodVariant {
    std::string kind = "ao";  // "ao" (scored on A) or "gi" (scored on indirect radiance)
    std::string method;       // an --ao or --gi method
    std::map<std::string, std::string> params;  // --param overrides for this variant
    // "gtao" or "gtao[gtao.preset=low;blur=0]": unique within a comparison.
    std::string label() const;
    // The label made safe for file names.
    std::string fileStem() const;
};

// Parses "gtao,hbao[hbao.steps=8;hbao.directions=4],vct" (commas inside brackets belong to
// the variant). Throws UsageError naming the bad entry.
std::vector<MethodVariant> parseMethodList(const std::string& text, const std::string& kind);

struct ComparisonSettings {
    RenderRequest base;          // camera, size, radius, seed, voxel resolution, sky, shared params
    int referenceSpp = 256;      // samples per pixel of the reference (AO and GI)
    int timingRuns = 3;          // timed runs after one warm-up; time_ms is their median
    std::vector<MethodVariant> variants;
    std::string outputDir;       // empty: write nothing (results only)
    bool writeImages = true;
    std::function<void(const std::string&)> progress;  // called with a line per step (may be empty)
};

// What a comparison needs before it starts: a variant to score, --ref-spp >= 1, --runs in
// [1, 100]. Throws std::invalid_argument naming the option (`vct compare` and the Python
// module both call it, so both report the same message).
void checkComparisonSettings(const ComparisonSettings& settings);

// Runs the comparison and returns the results document (the content of results.json):
// top-level scene/camera/resolution/radius/renderer/cores/reference, plus "records".
// Writes images, results.json and results.csv into outputDir when set.
nlohmann::json runComparison(const Scene& scene, const ComparisonSettings& settings);

// Pieces a comparison and a sequence comparison share: the valid (non-sky) pixels of a depth
// AOV, the median of timed runs, and an estimate as an 8-bit figure (AO as stored, radiance
// through sRGB).
Image validMaskFromDepth(const Image& depth);
// `base` set up to render variant `v`: its method as --ao or --gi, its parameters over the shared
// ones, and its one scored AOV (ao, or indirect).
RenderRequest variantRequest(const RenderRequest& base, const MethodVariant& v);
double medianOf(std::vector<double> values);
// The median of what `runs` timed runs measured where every one of them measured it (the
// per-frame GPU time exists only where timer queries work); empty otherwise.
std::optional<double> medianOfEveryRun(const std::vector<double>& values, size_t runs);
Image displayableEstimate(const Image& image, bool radiance);

// The CSV form of a results document's records (one line per record, header first).
std::string resultsCsv(const nlohmann::json& results);

// A record's device-independent cost from its methods' statistics: cone samples and texture
// fetches per traced pixel (cone methods), rays per image pixel (ray tracers), bytes of voxel
// data; null where the method has none.
nlohmann::json deviceIndependentCost(const nlohmann::json& extra, int pixels);

}  // namespace vct
