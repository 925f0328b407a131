#include "render/method_params.h"

#include "ao/alchemy.h"
#include "ao/ao_filters.h"
#include "ao/gtao.h"
#include "ao/hbao.h"
#include "ao/horizon_ao.h"
#include "ao/ssao.h"
#include "cone/cone_settings.h"
#include "reference/reference_ao.h"
#include "render/params.h"
#include "render/plan.h"
#include "cone/cone_bounce.h"

namespace vct {

void documentAllMethodParams() {
    ParamMap empty;
    // The planner's own keys (blur, ao.half-res) and the shadow map size.
    RenderRequest r;
    r.ao = "gtao";
    planRender(SceneFeatures{}, r);
    empty.getInt("shadow.size", 1024, 16, 8192, "shadow map texels per side");
    readSsaoSettings(empty);
    readHorizonSettings(empty);
    readAlchemySettings(empty);
    readHbaoSettings(empty);
    readGtaoSettings(empty);
    readAoBlurSettings(empty, true);
    readConeSettings(empty);
    referenceSettingsFromParams(empty);
    referencePixelAreaFromParams(empty);
    readVctBounces(empty);
    readVctBounceSky(empty);
    empty.getInt("vct.view.level", 0, 0, 16, "mip level shown by voxel_* AOVs");
}

}  // namespace vct
