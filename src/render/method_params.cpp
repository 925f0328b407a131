#include "render/method_params.h"

#include "ao/screen_space_ao.h"
#include "render/params.h"
#include "render/plan.h"

namespace vct {

void documentAllMethodParams() {
    ParamMap empty;
    // The planner's own keys.
    RenderRequest r;
    r.ao = "gtao";
    planRender(SceneFeatures{}, r);
    empty.getInt("shadow.size", 1024, 16, 8192, "shadow map texels per side");
    for (const auto& m : screenSpaceAoMethods()) planScreenSpaceAo(m, empty);
}

}  // namespace vct
