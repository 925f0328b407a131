// The G-buffer every estimator reads (screen-space AO, cone tracing, the reference):
// the surface point at each pixel centre. Positions, albedo and emission are RGBA32F so
// positions keep full precision at every scene scale and emission any strength; the two unit
// normals are RGBA16F (each component to 2^-11, an angle below 0.1 degree), which halves their
// bytes written and cleared per pixel: on Sponza at 512^2 under llvmpipe the pass went from
// 28.5 to 23 ms, a cost every method pays. Pixel (0,0) is the bottom-left (GL convention);
// images are flipped to top-down only when written to files.
#pragma once

#include "gl/handles.h"
#include "core/view.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace vct {

struct GBuffer {
    int width = 0;
    int height = 0;
    GlTexture position;    // xyz world position; w = linear view depth (> 0), 0 = no surface (sky)
    GlTexture normal;      // xyz world shading normal, flipped to face the camera; w = 1 on surface
    GlTexture geomNormal;  // xyz world geometric normal, facing the camera; w = 1 on surface
    GlTexture albedo;      // rgb linear base colour (texture x factor); a = 1 on surface
    GlTexture emission;    // rgb linear emitted radiance
    GlTexture depth;       // GL_DEPTH_COMPONENT32F, reversed-Z (1 at near, 0 at infinity)
    GlFramebuffer fbo;
    // False where the render reads no material (RenderPlan::gbufferMaterials): albedo and
    // emission are then not drawn (null textures).
    bool hasMaterials() const { return bool(albedo); }
};

// Throws InternalError naming `pass` unless g has a size and the surface textures (position,
// normal, geomNormal), and albedo when `albedo` is true.
void requireGBuffer(const GBuffer& g, const std::string& pass, bool albedo);

// Texture units / image units by convention, so shaders and C++ agree.
// Shaders that read the G-buffer bind position=0, normal=1, geomNormal=2, albedo=3,
// emission=4, depth=5 as sampler2D (texelFetch).
enum GBufferUnit : int { kUnitPosition = 0, kUnitNormal = 1, kUnitGeomNormal = 2, kUnitAlbedo = 3,
                         kUnitEmission = 4, kUnitDepth = 5 };

void bindGBufferTextures(const GBuffer& g);  // binds the six textures to the units above

// The surface at one pixel centre, for the methods that work on the CPU (the reference, the
// sparse voxels).
struct GBufferPoint {
    glm::vec3 position{0.f};
    glm::vec3 normal{0.f, 0.f, 1.f};      // shading normal, facing the camera
    glm::vec3 geomNormal{0.f, 0.f, 1.f};  // geometric normal, facing the camera
    glm::vec3 albedo{0.f};                // only with `albedo` below
    bool valid = false;                   // false: sky
};
// Every pixel's point, top row first (element y * width + x).
std::vector<GBufferPoint> readGBufferPoints(const GBuffer& g, bool albedo = false);
// A G-buffer holding given points (top row first, width * height of them; invalid ones are
// sky), for running the estimators at chosen surface points instead of a camera's pixels.
GBuffer makeGBufferFromPoints(const std::vector<GBufferPoint>& points, int width, int height);

}  // namespace vct
