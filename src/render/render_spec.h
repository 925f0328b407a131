// A render as a user asks for it, typed but not yet checked: the command line parses its
// option strings into it, the Python module fills it from keyword arguments. Both turn it
// into a request through makeRenderRequest and check the outcome with checkRenderResult,
// so a bad value gets the same message (naming the command line's option) from either.
#pragma once

#include "core/request.h"
#include "render/renderer.h"
#include "scene/camera.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

struct RenderSpec {
    int width = 256;                     // --size W or WxH
    int height = 256;
    CameraRequest camera;                // --camera NAME|INDEX, or --eye/--target/--fov
    std::string ao = kNoMethod;          // --ao
    std::string gi = kNoMethod;          // --gi
    float radius = 1.f;                  // --radius
    int spp = 64;                        // --spp
    uint64_t seed = 0;                   // --seed
    int voxelRes = 128;                  // --voxel-res
    std::string backend = "gl";          // --backend
    std::vector<std::string> aovs;       // --aov; empty: beauty
    std::vector<std::string> params;     // --param KEY=VALUE
    float sky = 1.f;                     // --sky
    bool prune = true;                   // false: --no-prune
};

// Checks every field against the renderer's registry and ranges and resolves the camera;
// throws std::invalid_argument naming the option (the command line's exit code 2).
RenderRequest makeRenderRequest(const RenderSpec& spec, const Scene& scene);

// What a finished render must satisfy before anyone sees it: every --param key was read by
// the renderer or a method (RenderResult::unusedParams is empty: a misspelt key is an error,
// never silently nothing), and every pixel is finite. Throws std::invalid_argument for the
// first, std::runtime_error for the second.
void checkRenderResult(const RenderResult& result);

}  // namespace vct
