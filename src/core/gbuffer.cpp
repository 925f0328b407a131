#include "core/gbuffer.h"

#include "gl/readback.h"

namespace vct {

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

}  // namespace vct
