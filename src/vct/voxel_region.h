// Which part of the scene the voxels cover (vct.region) and how (vct.clipmap.levels).
//
// AO region fitting: with --ao vct alone, only geometry within R of a visible surface point
// can change the image (A_R counts occluders within R only). The grid is fitted
// to the bounds of the G-buffer's visible positions grown by the cones' reach, clipped to the
// scene bounds, and --voxel-res is spent there. The reach is R plus the radius of a cone's
// footprint at distance R (R tan(aperture / 2): the cones see that far sideways, and cropping
// it changed the estimate - the off-screen overhang's ROI error rose from 0.14 to 0.23 with
// R alone) plus the start offset and one voxel of trilinear support. Marched as lanes
// (vct.lanes), each cone is many narrower ones: vct.fit-reach=lanes takes their footprint at
// R, at the level bias (vct.level-bias), instead, so the voxels cover only what a lane samples.
// GI needs the whole scene (light travels far), so `auto` keeps the scene for --gi vct; an
// explicit vct.region=fit with GI crops what the cones can gather light from.
//
// Grid shape (vct.grid): `fit` gives each axis the voxels the region needs, so a flat region
// makes a flat grid (64 x 11 x 64 at 64^3 for a floor under a plate). Mip level l then has
// floor(n / 2^l) texels along an axis of n voxels: the short axis reaches one texel spanning
// the whole grid while the long ones still halve, and a coarse sample's footprint is a slab
// reaching from the floor to an occluder on the grid's top face. `cube` grows the region to a
// cube around its centre, so every axis has the same count and every level cubic texels.
//
// Keys: vct.region, vct.fit-reach, vct.grid and vct.clipmap.levels (vct/vct_settings.h).
#pragma once

#include "image/image.h"
#include "core/gbuffer.h"
#include "core/request.h"
#include "cone/cone_settings.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace vct {

// "scene" or "fit" (auto resolved: fit when --ao vct and not --gi vct).
std::string voxelRegionMode(const RenderRequest& request);
// vct.clipmap.levels (0 = one dense grid).
int clipmapLevelCount(const RenderRequest& request);
// One line for --explain: the region and levels this request will use, and why.
std::string voxelRegionExplanation(const RenderRequest& request);

// Bounds of the xyz of pixels whose w > 0 (G-buffer position convention) and finite; empty if none.
Bounds3 visibleBounds(const Image& position);

// The cube with `b`'s centre whose edge is b's longest extent.
Bounds3 cubeAround(const Bounds3& b);

// `visible` grown by `reach` (world) + marginVoxels voxels, clipped to `scene`, where the voxel is the
// one a grid of `voxelRes` along the grown box's longest axis will have (makeGridLayout).
Bounds3 fitAoRegion(const Bounds3& visible, const Bounds3& scene, float reach, float marginVoxels, int voxelRes);

// vct.grid-shift: `b` moved by `shiftVoxels` of the voxel makeGridLayout(b, voxelRes) has
// (its longest extent / (voxelRes - 2)) towards -x, -y, -z, so that every
// world point's voxel coordinates grow by shiftVoxels: the same voxel size and counts, the
// lattice moved. |shiftVoxels| < 1: makeGridLayout's padding voxel on each side holds what the
// move carries past b.
Bounds3 shiftedGridRegion(const Bounds3& b, float shiftVoxels, int voxelRes);

struct VoxelRegion {
    std::string mode;   // "scene" | "fit"
    std::string why;
    Bounds3 bounds;     // what the voxels (or the clipmap's coarsest level) cover
    Bounds3 visible;    // fit: bounds of the visible points
    // fit, cropped inside the scene: a moved camera sees other points and fits other bounds,
    // so these voxels are built anew for the next frame and count in its cost (frame_ms). A fit
    // that covers the whole scene is the scene's grid, kept while the view still reaches its
    // bounds.
    bool followsView = false;
    nlohmann::json toJson() const;
};

// The region of this request. `gbuffer` may be null (no G-buffer in the plan): then the scene.
// A fit grows the visible points by R plus a footprint's radius at R (the cone set's, or with
// vct.fit-reach=lanes that of the lanes `cone` marches), and by its start offset.
VoxelRegion chooseVoxelRegion(const RenderRequest& request, const Scene& scene, const GBuffer* gbuffer,
                              const ConeSettings& cone);

}  // namespace vct
