#include "vct/vct_settings.h"

#include "cone/cone_bounce.h"
#include "cone/cone_settings.h"
#include "core/errors.h"
#include "voxelize/voxel_settings.h"

#include <sstream>

namespace vct {

const SettingsTable<VctSettings>& vctSettings() {
    static const auto table =
        SettingsTable<VctSettings>()
            .choice(kVctPresetKey, &VctSettings::preset,
                    {{"default", VctPreset::Default}, {"converge", VctPreset::Converge}},
                    "named VCT settings: default = each key's own default (every cone marched whole, Crassin "
                    "2011); converge = the march whose voxel error falls as the voxels refine on the closed-form "
                    "families (docs/convergence.md): vct.lanes=0 with vct.lanes-base=16, vct.sharpen=4, "
                    "vct.aim=1, vct.level-bias=-2, vct.grid=cube, vct.fit-reach=lanes (a fitted region) and "
                    "vct.voxel.edges=sheet. A key given on its own overrides the preset's value. It marches "
                    "(res / 16)^2 lanes a cone, so it costs far more than default (AO on the overhang scene at "
                    "128^3, sparse, 96 px: 146 times the samples, 107 -> 15675 a pixel, and about 400 times the "
                    "cone pass's time); needs directional levels on one dense grid or the sparse backend, not "
                    "clipmaps")
            .choice("vct.region", &VctSettings::region,
                    {{"auto", "auto"}, {"scene", "scene"}, {"fit", "fit"}},
                    "voxel region: scene = whole scene bounds; fit = visible points grown by R (AO); auto = fit "
                    "for --ao vct without --gi vct, else scene (GI light travels far)")
            .derive([](VctSettings& s, const ParamMap&) {
                // vct.preset=converge: cubic texels at every level, and a fitted region that
                // reaches as far as the lanes do (a whole-scene region has nothing to fit).
                if (s.preset != VctPreset::Converge) return;
                s.grid = "cube";
                if (s.region != "scene") s.fitReach = "lanes";
            })
            .choice("vct.grid", &VctSettings::grid, {{"fit", "fit"}, {"cube", "cube"}},
                    "grid shape: fit = each axis as long as the region needs; cube = every axis as long as the "
                    "longest, the region centred, so every mip level has cubic texels (costs memory on flat regions)")
            .choice("vct.fit-reach", &VctSettings::fitReach, {{"cones", "cones"}, {"lanes", "lanes"}},
                    "how far past the visible points a fitted region (vct.region=fit) reaches: cones = R plus the "
                    "cone set's footprint radius at R (R tan(aperture / 2)); lanes = R plus the footprint radius at R "
                    "of what the march traces, its lanes (vct.lanes) at the level bias (vct.level-bias): the same "
                    "voxels over less space when the lanes are narrower than their cones. Equal for one lane a cone "
                    "at bias 0; cones is the default every table of docs/convergence*.md was generated with")
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
                if (s.preset == VctPreset::Converge && s.clipmapLevels > 0)
                    throw UsageError("--param vct.preset=converge: its sharpened directional levels need one dense "
                                     "grid or the sparse backend, and clipmaps keep isotropic levels only "
                                     "(vct.clipmap.levels=" + std::to_string(s.clipmapLevels) + ")");
                if (s.fitReach == "lanes" && (s.region == "scene" || s.clipmapLevels > 0))
                    throw UsageError("--param vct.fit-reach=lanes: it sets how far a fitted region reaches, and " +
                                     std::string(s.clipmapLevels > 0 ? "a clipmap's levels cover the scene"
                                                                     : "vct.region=scene fits none") +
                                     "; use vct.region=fit or auto");
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

std::map<std::string, std::string> vctPresetValues(const ParamMap& params) {
    if (readVctPreset(params) == VctPreset::Default) return {};
    const ConeSettings cone = readConeSettings(params);
    const VctSettings vs = vctSettings().read(params);
    const VoxelEdges edges = voxelSettings().read(params).edges;
    auto text = [](float v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    return {{"vct.lanes", std::to_string(cone.lanes)},
            {"vct.lanes-base", std::to_string(cone.lanesBase)},
            {"vct.sharpen", text(cone.sharpen)},
            {"vct.aim", cone.aim ? "1" : "0"},
            {"vct.level-bias", text(cone.levelBias)},
            {"vct.grid", vs.grid},
            {"vct.fit-reach", vs.fitReach},
            {"vct.voxel.edges", edges == VoxelEdges::Sheet      ? "sheet"
                                : edges == VoxelEdges::Coverage ? "coverage"
                                                                : "occupied"}};
}

}  // namespace vct
