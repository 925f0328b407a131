// What a render is asked for: the camera, the image, the methods, their shared settings
// and the outputs. Filled by the CLI (src/app) or by code (tests, compare, sweeps).
#pragma once

#include "core/params.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

// The voxel resolutions a render accepts (--voxel-res): every grid, directional mip and
// clipmap level then stays within the 2048 texels per axis of a 3D texture that GL guarantees.
constexpr int kMinVoxelRes = 4;
constexpr int kMaxVoxelRes = 1024;

struct RenderRequest {
    Camera camera;
    int width = 256;                         // pixels, [1, 16384]
    int height = 256;
    std::string ao = "none";                 // an AO method of the registry (src/methods), or none
    std::string gi = "none";                 // a GI method of the registry, or none
    float radius = 1.f;                      // AO radius R, world units, shared by every AO method
    int spp = 64;                            // reference samples per pixel
    uint64_t seed = 0;                       // every random choice derives from it
    int voxelRes = 128;                      // voxels along the grid's longest axis, [kMinVoxelRes, kMaxVoxelRes]
    std::string backend = "gl";              // gl (dense 3D texture) | vdb (sparse, CPU)
    std::vector<std::string> aovs{"beauty"}; // requested outputs
    float sky = 1.f;                         // uniform sky radiance
    ParamMap params;                         // --param KEY=VALUE
    bool prune = true;                       // false: run every applicable pass (for tests)
    // false: build everything anew, as the first frame does: the scene's static data (voxels,
    // the reference's BVH) and the view's G-buffer. Times a method's whole, cold cost
    // (compare's time_ms), and its frame_ms includes the G-buffer a moved camera draws again
    // (the reference pays for its primary rays the same way).
    bool reuseSceneData = true;
};

// An output a render can write, with its channel count.
struct AovInfo {
    std::string name;
    int channels = 1;
    std::string doc;
};
// The renderer's own AOVs (the methods add theirs: see core/method.h).
const std::vector<AovInfo>& rendererAovs();

// The name of "no method" for --ao and --gi.
inline constexpr const char* kNoMethod = "none";

}  // namespace vct
