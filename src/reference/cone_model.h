// Directions for the cone model: the integral that voxel cone tracing approximates with exact
// visibility. A cone set (cone/cone_set.h: axes in the tangent frame, weights summing to 1)
// and an aperture define A_cones = sum_c w_c V_c, V_c the visible fraction of cone c's solid
// angle within R. Its Monte Carlo estimate picks cone c with probability w_c and a direction
// uniform in its cap: the fraction of such rays left open is A_cones. As the cone passes do,
// a cone whose axis lies below the geometric plane is closed, and the part of a cone below
// the plane is open (the cones never see the surface they start from), or with
// vct.below-plane=mirror reflected above the plane (cone_mirrored), as the passes march it.
// GI's cone model replaces the cosine lobe of a diffuse reflection by the same sampling:
// L_gathered = sum_c w_c (mean of L_in over cone c's cap), what the cone passes' sum_c w_c L_c
// converges to; an open direction below the plane sees the sky, a closed cone gathers nothing.
#pragma once

#include "common/tangent_frame.h"
#include "cone/cone_shared.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace vct {

struct ConeModelSample {
    glm::vec3 direction{0.f};
    bool closed = false;   // the cone's axis is below the geometric plane
    bool belowPlane = false;  // the direction is below the geometric plane (counts open)
};

class ConeModelSampler {
public:
    ConeModelSampler() = default;
    ConeModelSampler(std::vector<glm::vec4> cones, float apertureDeg, bool mirrorBelowPlane = false)
        : mCones(std::move(cones)), mCosHalf(std::cos(0.5f * apertureDeg * 3.14159265358979f / 180.f)),
          mMirror(mirrorBelowPlane) {
        float sum = 0.f;
        for (const glm::vec4& c : mCones) mCdf.push_back(sum += c.w);
        for (float& v : mCdf) v /= sum;
    }
    bool empty() const { return mCones.empty(); }

    // vct.jitter: point i's cone set turned about its normal by rotations[i] radians
    // (cone_jitterAngle of its pixel), as the cone passes turn it; empty: no turn.
    void setRotations(std::vector<float> rotations) { mRotations = std::move(rotations); }
    float rotationOf(size_t point) const { return point < mRotations.size() ? mRotations[point] : 0.f; }

    // u in [0, 1)^2; n the shading normal (the cone set's frame, as the cone passes take it),
    // ng the geometric normal; `rotation` turns the set about n (cone_common.glsl's frame).
    ConeModelSample sample(glm::vec2 u, const glm::vec3& n, const glm::vec3& ng, float rotation = 0.f) const {
        size_t c = 0;
        while (c + 1 < mCdf.size() && u.x >= mCdf[c]) ++c;
        // Reuse the first coordinate within the chosen cone's interval, so the 2D point set
        // stays stratified.
        const float lo = c == 0 ? 0.f : mCdf[c - 1];
        const float ux = (u.x - lo) / std::max(mCdf[c] - lo, 1e-12f);
        const glm::mat3 frame = frameOf(n, rotation);
        const glm::vec3 axis = glm::normalize(frame * glm::vec3(mCones[c]));
        ConeModelSample s;
        if (glm::dot(axis, ng) <= 0.f) {
            s.closed = true;
            return s;
        }
        const float cosT = 1.f - (1.f - mCosHalf) * ux, sinT = std::sqrt(std::max(0.f, 1.f - cosT * cosT));
        const float phi = 2.f * 3.14159265358979f * u.y;
        s.direction = gpu::frame_fromZ(axis) * glm::vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
        s.belowPlane = glm::dot(s.direction, ng) <= 0.f;
        if (s.belowPlane && mMirror) {
            s.direction = gpu::cone_mirrored(s.direction, ng);
            s.belowPlane = false;
        }
        return s;
    }

    // The density over directions of sample()'s open, above-plane directions: the sum over the
    // open cones whose cap holds w (mirrored: or its reflection below the plane) of w_c / (the
    // cap's solid angle), weights normalised as sample() picks them. GI's cone model uses it as
    // both the lobe and its pdf (for MIS against emitter sampling); 0 below the plane and
    // outside every open cap.
    float density(const glm::vec3& w, const glm::vec3& n, const glm::vec3& ng, float rotation = 0.f) const {
        if (mCones.empty() || glm::dot(w, ng) <= 0.f) return 0.f;
        const glm::mat3 frame = frameOf(n, rotation);
        const float capSolidAngle = 2.f * 3.14159265358979f * (1.f - mCosHalf);
        float sum = 0.f;
        for (size_t c = 0; c < mCones.size(); ++c) {
            const glm::vec3 axis = glm::normalize(frame * glm::vec3(mCones[c]));
            if (glm::dot(axis, ng) <= 0.f) continue;
            const float share = mCdf[c] - (c == 0 ? 0.f : mCdf[c - 1]);
            if (glm::dot(w, axis) >= mCosHalf) sum += share;
            if (mMirror && glm::dot(glm::reflect(w, ng), axis) >= mCosHalf) sum += share;
        }
        return sum / capSolidAngle;
    }

private:
    // The cone set's frame about n, turned by `rotation` (cone_common.glsl's frame).
    static glm::mat3 frameOf(const glm::vec3& n, float rotation) {
        glm::mat3 frame = gpu::frame_fromZ(n);
        if (rotation != 0.f) {
            const float cr = std::cos(rotation), sr = std::sin(rotation);
            frame = frame * glm::mat3(cr, sr, 0.f, -sr, cr, 0.f, 0.f, 0.f, 1.f);
        }
        return frame;
    }

    std::vector<glm::vec4> mCones;
    std::vector<float> mCdf;
    std::vector<float> mRotations;
    float mCosHalf = 1.f;
    bool mMirror = false;  // vct.below-plane=mirror
};

}  // namespace vct
