// Settings of voxel cone tracing (BRIEF section 3), read from `--param vct.*`. Defaults and
// their reasons live in shaders/cone/cone_shared.h (CONE_DEFAULT_*).
//
// | key             | default       | range          | meaning                                         |
// |-----------------|---------------|----------------|-------------------------------------------------|
// | vct.cones       | 6             | 6 or 16        | diffuse cone set (6 x 60 deg Villegas; 16 x 50) |
// | vct.aperture    | 60 (6) 50 (16)| (1, 179) deg   | full apex angle of every cone                   |
// | vct.step        | 0.5           | [0.05, 2]      | step = beta * footprint diameter                |
// | vct.offset      | 1.5           | [0, 8] voxels  | start offset along the geometric normal         |
// | vct.max-alpha   | 0.99          | [0.5, 1]       | a cone stops (and counts as closed) past this   |
// | vct.aniso       | 1             | 0 or 1         | six directional mips (d^2 weights) if the grid has them |
// | vct.ao-mapping  | linear        | linear|falloff | how cone opacity becomes AO (see below)         |
// | vct.plane-limit | 1             | 0 or 1         | footprint <= height above the tangent plane / 1.5 |
//
// AO mappings: `linear` A = 1 - sum_c w_c alpha_c, where alpha_c is cone c's opacity
// accumulated within R; with cosine-lobe weights w_c this estimates A_R of BRIEF section 1
// (binary visibility, no falloff), so it is the one to score against the reference.
// `falloff` weights each sample's opacity by 1 / (1 + lambda t), lambda = 4 / R (Crassin
// 2011's smooth AO); it is brighter than A_R by design and not an estimator of it.
#pragma once

#include "render/params.h"

#include <string>

namespace vct {

enum class ConeAoMapping { Linear, Falloff };

struct ConeSettings {
    int coneCount = 6;              // 6 or 16
    float apertureDeg = 60.f;       // full apex angle, degrees, (1, 179)
    float stepFactor = 0.5f;        // beta: step / footprint diameter, [0.05, 2]
    float offsetVoxels = 1.5f;      // start offset along the geometric normal, voxels, [0, 8]
    float maxAlpha = 0.99f;         // early exit, [0.5, 1]
    bool anisotropic = true;        // use grid.anisoRadiance when present
    ConeAoMapping aoMapping = ConeAoMapping::Linear;
    bool planeLimit = true;         // limit the footprint by the height above the tangent plane

    // Throws std::invalid_argument naming the field if a value is outside its range.
    void validate() const;
};

// The set's own aperture: 60 degrees for 6 cones, 50 for 16.
float defaultConeAperture(int coneCount);

// Reads the vct.* keys above (each documented for --help-params).
ConeSettings readConeSettings(const ParamMap& params);

std::string toString(ConeAoMapping m);

}  // namespace vct
