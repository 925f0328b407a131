#include "scene/camera.h"

#include "core/errors.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vct {
namespace {


// The bounding sphere of `b`, with a unit sphere at the origin for empty bounds.
void boundingSphere(const Bounds3& b, glm::vec3* center, float* radius) {
    if (b.empty()) {
        *center = glm::vec3(0.f);
        *radius = 1.f;
        return;
    }
    *center = b.center();
    *radius = 0.5f * glm::length(b.extent());
    if (!(*radius > 0.f)) *radius = std::max(1e-3f, 1e-3f * glm::length(*center));  // a single point
}

// An up vector not parallel to the view direction: world +Y, or -Z when looking straight up/down.
glm::vec3 upFor(const glm::vec3& forward) {
    return std::abs(glm::dot(forward, glm::vec3(0.f, 1.f, 0.f))) > 0.999f ? glm::vec3(0.f, 0.f, -1.f)
                                                                          : glm::vec3(0.f, 1.f, 0.f);
}

// Near/far planes that keep the whole bounding sphere between them as seen from `eye`.
void clipRange(const glm::vec3& eye, const glm::vec3& center, float radius, float* znear, float* zfar) {
    const float d = glm::length(eye - center);
    *zfar = 1.5f * (d + radius);
    // Outside the sphere: half the gap to it; inside: a small fraction of the radius.
    *znear = d > radius ? std::max(0.5f * (d - radius), 1e-4f * radius) : 1e-3f * radius;
}

}  // namespace

bool parseIndex(const std::string& s, size_t* index) {
    if (s.empty() || s.size() > 9) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    *index = size_t(std::stoul(s));
    return true;
}

std::string describeCameras(const Scene& scene) {
    if (scene.cameras.empty()) return "(none)";
    std::ostringstream os;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        os << (i ? ", " : "") << i << " '" << scene.cameras[i].name << "'";
    return os.str();
}

Camera defaultCamera(const Bounds3& bounds, float aspect, float yfovRadians) {
    if (!(aspect > 0.f) || !std::isfinite(aspect))
        throw InternalError("defaultCamera", "aspect must be > 0");
    if (!(yfovRadians > 0.f && yfovRadians < 3.1415926f))
        throw InternalError("defaultCamera", "yfov must be in (0, pi)");
    glm::vec3 center;
    float radius;
    boundingSphere(bounds, &center, &radius);
    const float halfY = 0.5f * yfovRadians;
    const float halfX = std::atan(std::tan(halfY) * aspect);
    // A sphere of radius r at distance d subtends a half-angle asin(r/d): fit it in the narrower fov.
    const float distance = 1.05f * radius / std::sin(std::min(halfX, halfY));
    const glm::vec3 fromCenter = glm::normalize(glm::vec3(0.55f, 0.5f, 1.f));  // right, above, in front (+Z)

    Camera c;
    c.name = "default";
    c.eye = center + distance * fromCenter;
    c.target = center;
    c.up = glm::vec3(0.f, 1.f, 0.f);
    c.yfov = yfovRadians;
    clipRange(c.eye, center, radius, &c.znear, &c.zfar);
    return c;
}

Camera resolveCamera(const Scene& scene, const CameraRequest& request, float aspect) {
    if (!(request.fovDeg > 0.f && request.fovDeg < 180.f))
        throw UsageError("camera: fov " + std::to_string(request.fovDeg) + " degrees not in (0, 180)");
    if (request.hasEye) {
        if (!finite3(request.eye) || !finite3(request.target))
            throw UsageError("camera: eye or target is not finite");
        const glm::vec3 forward = request.target - request.eye;
        if (!(glm::length(forward) > 0.f)) throw UsageError("camera: eye and target coincide");
        Camera c;
        c.name = "explicit";
        c.eye = request.eye;
        c.target = request.target;
        c.up = upFor(glm::normalize(forward));
        c.yfov = glm::radians(request.fovDeg);
        glm::vec3 center;
        float radius;
        boundingSphere(scene.bounds, &center, &radius);
        clipRange(c.eye, center, radius, &c.znear, &c.zfar);
        return c;
    }
    if (!request.nameOrIndex.empty()) {
        for (const Camera& c : scene.cameras)
            if (c.name == request.nameOrIndex) return c;
        size_t index = 0;
        if (parseIndex(request.nameOrIndex, &index) && index < scene.cameras.size())
            return scene.cameras[index];
        throw UsageError("camera '" + request.nameOrIndex + "' not found in " +
                         (scene.path.empty() ? std::string("the scene") : scene.path) +
                         "; available cameras: " + describeCameras(scene));
    }
    if (!scene.cameras.empty()) return scene.cameras.front();
    return defaultCamera(scene.bounds, aspect, glm::radians(request.fovDeg));
}

glm::vec3 parseVec3(const std::string& text) {
    auto bad = [&](const std::string& why) {
        return UsageError("'" + text + "' is not a vector 'x,y,z': " + why);
    };
    glm::vec3 v(0.f);
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t comma = text.find(',', start);
        if ((k < 2) != (comma != std::string::npos))
            throw bad("expected exactly three comma-separated numbers");
        const std::string part = text.substr(start, k < 2 ? comma - start : std::string::npos);
        size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(part, &used);
        } catch (const std::exception&) {
            throw bad("component " + std::to_string(k) + " '" + part + "' is not a number");
        }
        while (used < part.size() && std::isspace(static_cast<unsigned char>(part[used]))) ++used;
        if (used != part.size())
            throw bad("component " + std::to_string(k) + " '" + part + "' is not a number");
        if (!std::isfinite(x) || !std::isfinite(float(x)))
            throw bad("component " + std::to_string(k) + " is not finite");
        v[k] = float(x);
        start = comma + 1;
    }
    return v;
}

}  // namespace vct
