#include "core/request.h"

namespace vct {

const std::vector<AovInfo>& rendererAovs() {
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
    };
    return table;
}

}  // namespace vct
