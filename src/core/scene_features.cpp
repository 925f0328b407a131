#include "core/scene_features.h"

#include <algorithm>
#include <vector>

namespace vct {

SceneFeatures analyzeScene(const Scene& scene) {
    SceneFeatures f;
    f.triangles = scene.triangles.size();
    f.materials = scene.materials.size();
    f.lights = scene.lights.size();
    f.hasTextures = !scene.textures.empty();
    // Emission counts only if some triangle uses an emissive material.
    std::vector<bool> used(scene.materials.size(), false);
    for (uint32_t m : scene.triangleMaterial)
        if (m < used.size()) used[m] = true;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        if (!used[m]) continue;
        f.hasEmission |= scene.materials[m].isEmissive();
        f.hasAlphaMask |= scene.materials[m].alphaMask;
    }
    f.hasOffscreenOccluders =
        std::any_of(scene.triangleOffscreen.begin(), scene.triangleOffscreen.end(), [](uint8_t v) { return v != 0; });
    return f;
}

}  // namespace vct
