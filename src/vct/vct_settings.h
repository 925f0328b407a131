// The VCT methods' own settings (the cone, bounce and voxel settings are their building
// blocks': cone/cone_settings.h, cone/cone_bounce.h, voxelize/voxel_settings.h).
#pragma once

#include "core/settings.h"
#include "voxelize/voxel_settings.h"

#include <map>
#include <string>
#include <vector>

namespace vct {

struct VctSettings {
    // vct.preset (voxelize/voxel_settings.h): the values it sets are read by each table that
    // holds them; this one documents it and refuses what it cannot serve.
    VctPreset preset = VctPreset::Default;
    // Which part of the scene the voxels cover: scene, fit (the visible points grown by R),
    // or auto (fit for --ao vct without --gi vct, else scene). See vct/voxel_region.h.
    std::string region = "auto";
    // The grid's shape over the region: fit (each axis as long as the region needs) or cube
    // (every axis as long as the longest, the region centred). See vct/voxel_region.h.
    std::string grid = "fit";
    // How far a fit reaches past the visible points beyond R: the cone set's footprint radius at
    // R (cones) or that of the lanes the march traces, at its level bias (lanes).
    // See vct/voxel_region.cpp, chooseRegionBounds.
    std::string fitReach = "cones";
    // The grid moved by this fraction of a voxel on every axis (voxel_region.h, shiftedGridRegion):
    // the same region on another alignment of the voxel lattice.
    float gridShift = 0.f;
    int clipmapLevels = 0;  // nested levels around the camera (0 = one dense grid)
    int viewLevel = 0;      // mip level the voxel_* AOVs show
};
const SettingsTable<VctSettings>& vctSettings();

// Every key a VCT render reads: the cones', bounces', voxels' and the settings above.
std::vector<SettingDoc> vctSettingDocs();

// Method::presetValues of the VCT methods: the value of every key vct.preset sets, as the
// tables read it from `params` (a key given on its own keeps its own); empty without a preset.
std::map<std::string, std::string> vctPresetValues(const ParamMap& params);

}  // namespace vct
