// The project's own scenes, built in code (metres, Y up) and written to scenes/ by
// vct-scenegen. Each comes with at least one camera.
//
//   cornell_box            the classic box [-1,1]x[0,2]x[-1,1], open at +Z: red left wall, green right
//                          wall, two rotated boxes, an emissive quad under the ceiling and a point
//                          light below it; camera "front" looks in through the opening
//   cornell_moving_box     the same box, its short box slid across the floor by the animation
//                          box_slide (0..2 s), in front of the tall one
//   cornell_moving_light   the same box, its point light moved by the animation light_sweep (0..2 s)
//   default                what `make render` renders: a sunlit courtyard corner with an arch, a table,
//                          stacked boxes, a pillar, an emissive panel, a sun and a point light
//   offscreen_overhang     a slab above and behind the camera over floor that is in view
//   offscreen_wall_behind  a wall 5 cm behind the camera, which looks down at the floor before it
//   offscreen_side         a pillar against the back wall just outside the right frustum plane
//                          (outside for any aspect <= 16:9; the visible wall ends ~0.6 m from it at 1:1)
//   offscreen_hidden       a box hidden (from the camera) behind a nearer box, against a visible wall
//   offscreen_thin         a 1 cm shelf and a 1 cm fin in planes through the eye: seen edge-on
//   open_plane             a 100 m x 100 m plane, a camera looking down at it, a sun straight down
//   wall_base              a 40 m floor meeting a 20 m tall wall along z = 0 (wall faces +Z)
//
// Off-screen occluders (what the ROI of a comparison is made from) are nodes named "offscreen_*" that also carry extras
// {"offscreen_occluder": true}; the loader marks their triangles in Scene::triangleOffscreen.
// Their cameras are designed for aspect ratios 1 to 16/9.
#pragma once

#include "scene/scene_builder.h"

#include <string>
#include <vector>

namespace vct {

std::vector<std::string> projectSceneNames();

// Throws UsageError listing the known names when `name` is not one of them.
SceneBuilder makeProjectScene(const std::string& name);

}  // namespace vct
