// What a scene contains that changes which passes and shader features a render needs.
#pragma once

#include "scene/scene.h"

#include <cstddef>

namespace vct {

struct SceneFeatures {
    size_t triangles = 0;
    size_t materials = 0;
    size_t lights = 0;
    bool hasEmission = false;   // some triangle uses an emissive material
    bool hasTextures = false;
    bool hasAlphaMask = false;
    bool hasOffscreenOccluders = false;
};

SceneFeatures analyzeScene(const Scene& scene);

}  // namespace vct
