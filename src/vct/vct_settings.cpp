#include "vct/vct_settings.h"

#include "cone/cone_bounce.h"
#include "cone/cone_settings.h"
#include "core/errors.h"
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
            .real("vct.grid-shift", &VctSettings::gridShift, -0.99f, 0.99f,
                  "move the voxel grid by this fraction of a voxel towards -x, -y, -z (every point's voxel "
                  "coordinates grow by it; voxel size and counts unchanged, the grid's padding voxel holds what "
                  "moves past the region): the same scene on another alignment of the voxels. Where a sheet or a "
                  "wall falls inside its voxel, and whether a move across a voxel face also moves it across a "
                  "coarse level's texel face, changes a case's error at one resolution by more than a doubling "
                  "of the resolution does; a few shifts separate that from the trend (docs/convergence.md). One "
                  "dense grid or sparse backend, not clipmaps")
            .integer("vct.clipmap.levels", &VctSettings::clipmapLevels, 0, 8,
                     "clipmap: nested voxel levels of --voxel-res^3 around the camera, each twice the previous "
                     "extent (0 = one dense grid over the region)")
            .integer("vct.view.level", &VctSettings::viewLevel, 0, 16, "mip level shown by voxel_* AOVs")
            .check([](const VctSettings& s) {
                if (s.gridShift != 0.f && s.clipmapLevels > 0)
                    throw UsageError("--param vct.grid-shift: a clipmap's lattice is the scene's, moved with the "
                                     "camera; it needs one dense grid (vct.clipmap.levels=0)");
            });
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
