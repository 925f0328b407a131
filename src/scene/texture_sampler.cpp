#include "scene/texture_sampler.h"

#include "common/scene_shared.h"

#include <array>
#include <cmath>

namespace vct {

namespace {

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            double c = i / 255.0;
            t[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

// Integer texel coordinate of a (possibly negative or out-of-range) index. Mirrored repeat
// has period 2 size, the second half backwards, so the edge texel neighbours itself.
int wrapIndex(int i, int size, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Repeat:
        i %= size;
        return i < 0 ? i + size : i;
    case TextureWrap::MirroredRepeat: {
        const int period = 2 * size;
        i %= period;
        if (i < 0) i += period;
        return i < size ? i : period - 1 - i;
    }
    case TextureWrap::ClampToEdge: break;
    }
    return i < 0 ? 0 : (i >= size ? size - 1 : i);
}

// Keeps the texel arithmetic in int range for any finite or non-finite uv.
float reduceCoordinate(float c, TextureWrap wrap) {
    if (!std::isfinite(c)) return 0.f;
    switch (wrap) {
    case TextureWrap::Repeat: return c - std::floor(c);
    case TextureWrap::MirroredRepeat: return gpu::scene_mirrorCoordinate(c);
    case TextureWrap::ClampToEdge: break;
    }
    return std::min(std::max(c, 0.f), 1.f);
}

glm::vec4 texel(const Texture& t, int x, int y, bool srgb) {
    const uint8_t* p = &t.rgba[(size_t(y) * size_t(t.width) + size_t(x)) * 4];
    if (srgb) {
        const auto& lut = srgbTable();
        return {lut[p[0]], lut[p[1]], lut[p[2]], p[3] / 255.f};
    }
    return {p[0] / 255.f, p[1] / 255.f, p[2] / 255.f, p[3] / 255.f};
}

}  // namespace

float srgbToLinear(uint8_t encoded) { return srgbTable()[encoded]; }

glm::vec4 sampleTexture(const Texture& texture, glm::vec2 uv, bool srgb) {
    if (texture.width <= 0 || texture.height <= 0 ||
        texture.rgba.size() < size_t(texture.width) * size_t(texture.height) * 4)
        return glm::vec4(1.f);
    float s = reduceCoordinate(uv.x, texture.wrapS) * float(texture.width) - 0.5f;
    float t = reduceCoordinate(uv.y, texture.wrapT) * float(texture.height) - 0.5f;
    float fs = std::floor(s), ft = std::floor(t);
    float ws = s - fs, wt = t - ft;
    int x0 = int(fs), y0 = int(ft);
    int xa = wrapIndex(x0, texture.width, texture.wrapS), xb = wrapIndex(x0 + 1, texture.width, texture.wrapS);
    int ya = wrapIndex(y0, texture.height, texture.wrapT), yb = wrapIndex(y0 + 1, texture.height, texture.wrapT);
    glm::vec4 top = glm::mix(texel(texture, xa, ya, srgb), texel(texture, xb, ya, srgb), ws);
    glm::vec4 bottom = glm::mix(texel(texture, xa, yb, srgb), texel(texture, xb, yb, srgb), ws);
    return glm::mix(top, bottom, wt);
}

glm::vec4 vertexColorAt(const Scene& scene, uint32_t tri, glm::vec3 b) {
    if (scene.colors.size() != scene.positions.size() || tri >= scene.triangles.size()) return glm::vec4(1.f);
    const glm::uvec3& t = scene.triangles[tri];
    return gpu::scene_vertexColor(scene.colors[t.x], scene.colors[t.y], scene.colors[t.z], b);
}

glm::vec3 materialAlbedo(const Scene& scene, uint32_t material, glm::vec2 uv, glm::vec4 vertexColor) {
    if (material >= scene.materials.size()) return glm::vec3(0.8f);  // loader default grey
    const Material& m = scene.materials[material];
    glm::vec3 albedo(m.baseColorFactor);
    if (m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < scene.textures.size())
        albedo *= glm::vec3(sampleTexture(scene.textures[size_t(m.baseColorTexture)], uv, true));
    albedo *= glm::vec3(vertexColor);
    return glm::clamp(albedo, 0.f, 1.f);
}

float materialAlpha(const Scene& scene, uint32_t material, glm::vec2 uv, glm::vec4 vertexColor) {
    if (material >= scene.materials.size()) return 1.f;
    const Material& m = scene.materials[material];
    float a = m.baseColorFactor.a;
    if (m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < scene.textures.size())
        a *= sampleTexture(scene.textures[size_t(m.baseColorTexture)], uv, true).a;
    return a * vertexColor.a;
}

glm::vec3 materialEmission(const Scene& scene, uint32_t material, glm::vec2 uv) {
    if (material >= scene.materials.size()) return glm::vec3(0.f);
    const Material& m = scene.materials[material];
    if (!m.isEmissive()) return glm::vec3(0.f);
    glm::vec3 e = m.emissiveFactor;
    if (m.emissiveTexture >= 0 && size_t(m.emissiveTexture) < scene.textures.size())
        e *= glm::vec3(sampleTexture(scene.textures[size_t(m.emissiveTexture)], uv, true));
    return glm::max(e, glm::vec3(0.f));
}

}  // namespace vct
