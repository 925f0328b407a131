#include "render/request.h"

namespace vct {

const std::vector<AovInfo>& knownAovs() {
    static const std::vector<AovInfo> table = {
        {"beauty", 3, "final linear radiance: emission + direct + ambient or GI"},
        {"ao", 1, "ambient occlusion A_R in [0, 1] (1 = open)"},
        {"direct", 3, "direct light from punctual lights (shadowed)"},
        {"indirect", 3, "indirect diffuse radiance (GI, or sky * albedo * AO)"},
        {"normal", 3, "world shading normal"},
        {"depth", 1, "linear view depth (0 = sky)"},
        {"albedo", 3, "linear base colour"},
        {"position", 3, "world position"},
        {"emission", 3, "emitted radiance"},
        {"ao_stderr", 1, "reference AO: per-pixel standard error"},
        {"indirect_stderr", 1, "reference GI: per-pixel standard error of indirect"},
        {"voxel_albedo", 3, "voxel grid albedo, ray-marched from the camera"},
        {"voxel_radiance", 3, "voxel grid radiance, ray-marched from the camera"},
        {"voxel_opacity", 1, "voxel grid opacity, ray-marched from the camera"},
    };
    return table;
}

const AovInfo* findAov(const std::string& name) {
    for (const auto& a : knownAovs())
        if (name == a.name) return &a;
    return nullptr;
}

const std::vector<std::string>& aoMethods() {
    static const std::vector<std::string> m = {"none", "ssao-crytek", "ssao-hemisphere", "ssao-horizon",
                                               "alchemy", "hbao", "gtao", "vct", "reference"};
    return m;
}

const std::vector<std::string>& giMethods() {
    static const std::vector<std::string> m = {"none", "vct", "reference"};
    return m;
}

}  // namespace vct
