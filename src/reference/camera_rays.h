// Primary rays of a View, matching the rasterizer's pixel grid: pixel (x, y), y = 0 the TOP
// row, has its centre at NDC ((x + 0.5) / W * 2 - 1, 1 - (y + 0.5) / H * 2).
#pragma once

#include "core/view.h"

#include <glm/glm.hpp>

namespace vct {

struct CameraRay {
    glm::vec3 origin{0.f};
    glm::vec3 direction{0.f, 0.f, -1.f};  // unit, world space
    float tnear = 0.f;                    // distance to the near plane along the ray (raster clips there)
};

// (px, py) in pixel units from the top-left image corner: the centre of pixel (x, y) is
// (x + 0.5, y + 0.5).
inline CameraRay cameraRay(const View& view, float px, float py) {
    float ndcX = px / float(view.width) * 2.f - 1.f;
    float ndcY = 1.f - py / float(view.height) * 2.f;
    float tanHalf = std::tan(0.5f * view.camera.yfov);
    glm::vec3 dirView(ndcX * tanHalf * view.aspect(), ndcY * tanHalf, -1.f);
    float len = glm::length(dirView);
    CameraRay r;
    r.origin = glm::vec3(view.worldFromView[3]);
    r.direction = glm::normalize(glm::mat3(view.worldFromView) * (dirView / len));
    r.tnear = view.camera.znear * len;  // view-space depth znear
    return r;
}

}  // namespace vct
