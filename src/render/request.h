// What a render is asked for: the camera, the image, the methods, their shared settings
// and the outputs. Filled by the CLI (src/app) or by code (tests, compare, sweeps).
#pragma once

#include "render/params.h"
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
    std::string ao = "none";                 // none|ssao-crytek|ssao-hemisphere|ssao-horizon|alchemy|hbao|gtao|vct|reference
    std::string gi = "none";                 // none|vct|reference
    float radius = 1.f;                      // AO radius R, world units, shared by every AO method
    int spp = 64;                            // reference samples per pixel
    uint64_t seed = 0;                       // every random choice derives from it
    int voxelRes = 128;                      // voxels along the grid's longest axis, [kMinVoxelRes, kMaxVoxelRes]
    std::string backend = "gl";              // gl (dense 3D texture) | vdb (sparse, CPU)
    std::vector<std::string> aovs{"beauty"}; // requested outputs
    float sky = 1.f;                         // uniform sky radiance
    ParamMap params;                         // --param KEY=VALUE
    bool prune = true;                       // false: run every applicable pass (for tests)
    bool reuseVoxels = true;                 // false: voxelize anew (timing a method's whole cost)
};

// Every AOV name the renderer knows, with its channel count.
struct AovInfo {
    const char* name;
    int channels;
    const char* doc;
};
const std::vector<AovInfo>& knownAovs();
const AovInfo* findAov(const std::string& name);

const std::vector<std::string>& aoMethods();  // as accepted by --ao
const std::vector<std::string>& giMethods();  // as accepted by --gi

}  // namespace vct
