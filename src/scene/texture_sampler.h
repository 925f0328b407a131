// CPU texture lookups (the reference path tracer, the sparse voxelizer): bilinear filtering of the base level
// with the texture's wrap modes (repeat, clamp-to-edge, mirrored repeat), texel centres at (i + 0.5) / size,
// row 0 at v = 0 (glTF's uv origin is the top-left of the image). Colour channels of base
// colour and emissive textures are sRGB-encoded (glTF 2.0 spec, section 3.9.2): texels are
// decoded to linear first, then filtered, as GL does for SRGB8_ALPHA8 textures. Alpha is
// linear.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace vct {

// IEC 61966-2-1 sRGB decode of an 8-bit value.
float srgbToLinear(uint8_t encoded);

// Bilinear lookup; rgb decoded from sRGB when `srgb`, alpha always linear in [0, 1].
// An empty texture reads as (1, 1, 1, 1).
glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv, bool srgb = true);

// The vertex colour (Scene::colors) of triangle `tri` at barycentric weights b of its three
// vertices; (1, 1, 1, 1) for a scene without vertex colours.
glm::vec4 vertexColorAt(const Scene& scene, uint32_t tri, glm::vec3 b);
// Lambertian albedo: baseColorFactor.rgb x base colour texture x vertex colour, clamped to [0, 1].
glm::vec3 materialAlbedo(const Scene& scene, uint32_t material, glm::vec2 uv, glm::vec4 vertexColor);
// glTF coverage alpha: baseColorFactor.a x texture alpha x vertex colour alpha.
float materialAlpha(const Scene& scene, uint32_t material, glm::vec2 uv, glm::vec4 vertexColor);
// Emitted radiance: emissiveFactor (already x emissive_strength) x emissive texture.
glm::vec3 materialEmission(const Scene& scene, uint32_t material, glm::vec2 uv);

}  // namespace vct
