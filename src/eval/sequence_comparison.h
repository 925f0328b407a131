// A comparison along a camera path: every frame, every method variant against that frame's
// reference, on one session (the scene's voxels and BVH built once, a G-buffer per frame).
// Per variant: the per-frame RMSE (mean and worst), the per-frame cost (frame_ms: the median over
// frames 1.. of what a frame of the sequence cost, whatever reran because the camera moved), the
// cold cost of its first frame (time_ms, as `vct compare` times it) and the temporal
// instability of eval/temporal.h against the reference's frames. The reference's own
// instability (its change beyond its noise) is reported beside: near zero when the
// reprojection is right, since AO and diffuse light do not depend on the camera.
//
// Seeds: the reference's frame f uses frameSeed(seed, f) (scene/camera_path.h), so its frames are
// independent estimates. The methods use the same per-frame seeds (`perFrameSeeds`, the default:
// their noise patterns change every frame, as a renderer with temporal accumulation has them) or
// keep the one seed for every frame (a fixed pattern that only moves with the screen).
#pragma once

#include "eval/comparison.h"
#include "scene/camera_path.h"

#include <nlohmann/json.hpp>

namespace vct {

struct SequenceSettings {
    ComparisonSettings comparison;  // base request (its camera lends the lens), variants, spp, runs, output
    CameraPath path;
    int frames = 2;                 // [1, 10000]
    bool perFrameSeeds = true;      // false: the methods keep comparison.base.seed on every frame
};

// --frames in range, a path with keys, and the comparison's own checks; UsageError naming the option.
void checkSequenceSettings(const SequenceSettings& settings);

// Runs the sequence and returns results.json's document: the path, the frame times, the
// reference's spp and own instability, and a record per variant (rmse_mean, rmse_worst,
// per_frame {rmse, frame_ms, instability}, frame_ms, time_ms, temporal {...}, provenance).
// With an output directory: results.json, results.csv and, with writeImages, each frame of the
// reference and of every variant as PNG under frames/<name>/NNNN.png.
nlohmann::json runSequenceComparison(const Scene& scene, const SequenceSettings& settings);

std::string sequenceResultsCsv(const nlohmann::json& results);

class RenderSession;
// One frame's pose of a sequence whose path plays `animation` (nothing without one): poses
// `scene`, the Scene `session` renders, at time t (scene/gltf_animation.h) and tells the
// session what moved: moved objects drop everything built from the geometry, moved lights
// only what they light.
void poseSequenceFrame(RenderSession& session, Scene& scene, const std::string& animation, double t);

}  // namespace vct
