// Camera-path sequences on the command line: which path a --path names, and where the frames
// of `-o NAME.ext` go.
#pragma once

#include "scene/camera_path.h"
#include "scene/gltf_animation.h"  // checkPathAnimation, which the sequences call

#include <string>
#include <vector>

namespace vct {

// A path file, or gltf:NAME|INDEX for one of the scene's camera animations; UsageError naming
// --path when neither exists.
CameraPath resolveCameraPath(const std::string& spec, const Scene& scene);

// The --explain lines for a sequence whose lights move, and whose objects move.
std::string sequenceLightsExplanation(const std::string& animation);
std::string sequenceGeometryExplanation(const std::string& animation);

struct SequenceFiles {
    std::vector<std::string> frames;  // NAME_0000.ext, NAME_0001.ext, ...
    std::string manifest;             // NAME.sequence.json
    std::string video;                // NAME.mp4
    std::string framePattern;         // NAME_%04d.ext (ffmpeg's)
};
SequenceFiles sequenceFiles(const std::string& output, int frames);

}  // namespace vct
