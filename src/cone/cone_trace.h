// Voxel cone tracing over a VoxelGrid (src/voxelize/voxel_grid.h) at the surface points of a
// G-buffer (render/gbuffer.h): ambient occlusion, indirect diffuse, and an inspection view of
// the grid. OpenGL 4.5 compute passes; each runs in its own PassTimer scope.
#pragma once

#include "cone/cone_cost.h"
#include "cone/cone_settings.h"
#include "gl/handles.h"
#include "core/gbuffer.h"
#include "core/timing.h"
#include "core/view.h"
#include "voxelize/voxel_grid.h"

#include <string>

namespace vct {

// AO in [0, 1] per pixel (GL_R32F, view size; sky pixels 1): cones over the hemisphere of the
// shading normal, weighted to integrate the cosine lobe, each limited to distance `radius`
// (world units: the AO radius R, beyond which nothing occludes). Reads grid.opacity (and,
// when settings.anisotropic, the directional levels the grid has: an AO grid's anisoOpacity,
// or a lit grid's anisoRadiance alpha). Timer scope "cone_ao".
GlTexture coneTraceAO(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float radius,
                      const ConeSettings& settings, PassTimer& timer, ConeCost* cost = nullptr);

// Outgoing indirect diffuse radiance per pixel (GL_RGBA32F, view size; sky pixels 0):
// albedo / pi * integral of L_in cos over the hemisphere, where each cone gathers the grid's
// premultiplied radiance front to back until it leaves the grid or saturates, and what it
// leaves unoccluded sees the uniform sky radiance `sky`. Includes sky light; excludes direct
// light and the pixel's own emission. Requires grid.radiance. Timer scope "cone_gi".
GlTexture coneTraceGI(const VoxelGrid& grid, const GBuffer& gbuffer, const View& view, float sky,
                      const ConeSettings& settings, PassTimer& timer, ConeCost* cost = nullptr);

// Ray-marches the grid from the camera through each pixel centre, compositing `what`
// ("albedo" | "radiance" | "opacity") front to back at mip `level` (albedo: level 0 only).
// GL_RGBA32F: rgb = composited colour, a = accumulated opacity. Timer scope "cone_view".
GlTexture rayMarchVoxels(const VoxelGrid& grid, const View& view, const std::string& what, int level,
                         PassTimer& timer);

}  // namespace vct
