#include "vct/vct_settings.h"

#include "cone/cone_bounce.h"
#include "cone/cone_settings.h"
#include "voxelize/voxel_settings.h"

namespace vct {

const SettingsTable<VctSettings>& vctSettings() {
    static const auto table =
        SettingsTable<VctSettings>()
            .choice("vct.region", &VctSettings::region,
                    {{"auto", "auto"}, {"scene", "scene"}, {"fit", "fit"}},
                    "voxel region: scene = whole scene bounds; fit = visible points grown by R (AO); auto = fit "
                    "for --ao vct without --gi vct, else scene (GI light travels far)")
            .choice("vct.grid", &VctSettings::grid, {{"fit", "fit"}, {"cube", "cube"}},
                    "grid shape: fit = each axis as long as the region needs; cube = every axis as long as the "
                    "longest, the region centred, so every mip level has cubic texels (costs memory on flat regions)")
            .integer("vct.clipmap.levels", &VctSettings::clipmapLevels, 0, 8,
                     "clipmap: nested voxel levels of --voxel-res^3 around the camera, each twice the previous "
                     "extent (0 = one dense grid over the region)")
            .integer("vct.view.level", &VctSettings::viewLevel, 0, 16, "mip level shown by voxel_* AOVs");
    return table;
}

std::vector<SettingDoc> vctSettingDocs() {
    std::vector<SettingDoc> docs;
    for (const auto* table : {&coneSettings().docs(), &bounceSettings().docs(), &voxelSettings().docs(),
                              &vctSettings().docs()})
        docs.insert(docs.end(), table->begin(), table->end());
    return docs;
}

}  // namespace vct
