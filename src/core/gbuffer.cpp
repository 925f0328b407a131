#include "core/gbuffer.h"

#include "core/errors.h"
#include "gl/readback.h"

namespace vct {

void requireGBuffer(const GBuffer& g, const std::string& pass, bool albedo) {
    if (g.width <= 0 || g.height <= 0 || !g.position || !g.normal || !g.geomNormal || (albedo && !g.albedo))
        throw InternalError(pass, albedo ? "G-buffer is incomplete (position, normal, geomNormal, albedo)"
                                         : "G-buffer is incomplete (position, normal, geomNormal)");
}

void bindGBufferTextures(const GBuffer& g) {
    glBindTextureUnit(kUnitPosition, g.position.id());
    glBindTextureUnit(kUnitNormal, g.normal.id());
    glBindTextureUnit(kUnitGeomNormal, g.geomNormal.id());
    glBindTextureUnit(kUnitAlbedo, g.albedo.id());
    glBindTextureUnit(kUnitEmission, g.emission.id());
    glBindTextureUnit(kUnitDepth, g.depth.id());
}

std::vector<GBufferPoint> readGBufferPoints(const GBuffer& g, bool albedo) {
    const Image pos = readTexture2D(g.position.id(), g.width, g.height, 4);
    const Image nrm = readTexture2D(g.normal.id(), g.width, g.height, 4);
    const Image geo = readTexture2D(g.geomNormal.id(), g.width, g.height, 4);
    const Image alb = albedo ? readTexture2D(g.albedo.id(), g.width, g.height, 4) : Image();
    std::vector<GBufferPoint> pts(size_t(g.width) * g.height);
    for (size_t i = 0; i < pts.size(); ++i) {
        const float* p = &pos.pixels[4 * i];
        const float* n = &nrm.pixels[4 * i];
        const float* q = &geo.pixels[4 * i];
        pts[i].position = glm::vec3(p[0], p[1], p[2]);
        pts[i].normal = glm::vec3(n[0], n[1], n[2]);
        pts[i].geomNormal = glm::vec3(q[0], q[1], q[2]);
        if (albedo) pts[i].albedo = glm::vec3(alb.pixels[4 * i], alb.pixels[4 * i + 1], alb.pixels[4 * i + 2]);
        pts[i].valid = p[3] > 0.f;
    }
    return pts;
}

GBuffer makeGBufferFromPoints(const std::vector<GBufferPoint>& points, int width, int height) {
    if (width < 1 || height < 1 || points.size() != size_t(width) * size_t(height))
        throw InternalError("makeGBufferFromPoints", std::to_string(points.size()) + " points for a " +
                                                         std::to_string(width) + "x" + std::to_string(height) + " image");
    Image position(width, height, 4), normal(width, height, 4), geom(width, height, 4), albedo(width, height, 4),
        emission(width, height, 4);
    for (size_t i = 0; i < points.size(); ++i) {
        const GBufferPoint& p = points[i];
        if (!p.valid) continue;
        for (int c = 0; c < 3; ++c) {
            position.pixels[4 * i + c] = p.position[c];
            normal.pixels[4 * i + c] = p.normal[c];
            geom.pixels[4 * i + c] = p.geomNormal[c];
            albedo.pixels[4 * i + c] = p.albedo[c];
        }
        position.pixels[4 * i + 3] = 1.f;  // a positive depth marks a surface
        normal.pixels[4 * i + 3] = 1.f;
        geom.pixels[4 * i + 3] = 1.f;
        albedo.pixels[4 * i + 3] = 1.f;
    }
    GBuffer g;
    g.width = width;
    g.height = height;
    for (auto [texture, image] : {std::pair<GlTexture*, const Image*>{&g.position, &position}, {&g.normal, &normal},
                                  {&g.geomNormal, &geom}, {&g.albedo, &albedo}, {&g.emission, &emission}}) {
        *texture = createTexture2D(GL_RGBA32F, width, height);
        uploadTexture2D(texture->id(), *image);
    }
    g.depth = createTexture2D(GL_DEPTH_COMPONENT32F, width, height);
    return g;
}

}  // namespace vct
