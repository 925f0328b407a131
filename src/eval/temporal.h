// Temporal instability: how much a method's image changes from one frame of a camera path to
// the next beyond what the scene's true change explains.
//
// Reprojection. Each valid pixel p of frame t holds a world point x_p (the G-buffer's position:
// the motion vectors of a static scene are the camera's). x_p is projected by frame t-1's camera
// to a sub-pixel position q; frame t-1's images are read there by bilinear interpolation over
// the four pixels around q. The pixel is disoccluded (masked) when q falls outside the image, or
// any of the four taps (weight >= 1e-3) is sky or another surface: its point is farther than
// tau from x_p's tangent plane, tau = 2 pixel footprints of frame t-1 at that distance
// (|x - eye_{t-1}| / focal_px) + 1e-5 |x_p|, or its normal is more than ~37 deg from x_p's.
//
// Instability of a method m against the reference r over frames t = 1..T-1 and the pixels
// valid in each, with Dm = m_t(p) - m_{t-1}(q) and Dr = r_t(p) - r_{t-1}(q):
//   I^2 = mean[(Dm - Dr)^2] - mean[s_t(p)^2 + sum_k w_k^2 s_{t-1}(k)^2]
// s is the reference's per-pixel standard error. Frames of the reference are independent
// estimates (each frame its own seed), so the second mean is the expected square of Dr's noise,
// and I^2 estimates the mean square of Dm - (the true change). I = sqrt(max(0, I^2)), reported
// with the raw RMS of Dm - Dr, the RMS of Dm (the method's change alone) and the noise floor.
// A static path gives Dm = 0 for a deterministic method, so I is zero within the reference's
// noise; GI is scored on the mean of the three channels, the quantity whose error s is.
// Without a reference (scoring the reference's own frames), Dr = 0: I then measures the change
// of r beyond its noise, zero for a still scene whatever the camera does.
#pragma once

#include "core/view.h"
#include "image/image.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <vector>

namespace vct {

// Where each pixel of frame t reads frame t-1 (four taps and their bilinear weights), or masked.
struct Reprojection {
    int width = 0, height = 0;
    std::vector<int32_t> taps;     // 4 per pixel: indices into frame t-1, -1 unused
    std::vector<float> weights;    // 4 per pixel, summing to 1 where valid
    std::vector<uint8_t> valid;    // 1: reprojected, 0: sky in frame t, off-screen or disoccluded
    size_t validCount() const;
};

// `position` / `normal`: the G-buffers' world positions (w = depth, 0 for sky) as read back
// (position: 4 channels, or 3 with `depth` separately), normals (3 channels).
// A camera that did not move (the same matrices) maps every pixel onto itself exactly: the
// motion vectors of a still camera over a static scene are zero, not a rounding error of the
// projection. A point projecting within half a pixel outside the image reads the edge pixels.
Reprojection reprojectFrame(const View& view, const Image& position, const Image& depth, const Image& normal,
                            const View& previousView, const Image& previousPosition, const Image& previousDepth,
                            const Image& previousNormal);

// An image of frame t-1 read at frame t's pixels (masked pixels 0).
Image reprojectImage(const Reprojection& reprojection, const Image& previous);

struct TemporalScore {
    double sumDiff2 = 0.0;    // sum of (Dm - Dr)^2
    double sumNoise2 = 0.0;   // sum of the reference's noise variance in Dr
    double sumChange2 = 0.0;  // sum of Dm^2
    double sumExcess2 = 0.0;  // sum of ((Dm - Dr)^2 - noise)^2, for the resolution
    size_t samples = 0;       // pixels x frames scored

    double instability() const;  // sqrt(max(0, (sumDiff2 - sumNoise2) / samples))
    double rawRms() const;       // sqrt(sumDiff2 / samples)
    double changeRms() const;    // sqrt(sumChange2 / samples)
    double noiseRms() const;     // sqrt(sumNoise2 / samples)
    // The smallest instability this score tells from zero: sqrt(2 SE), SE the standard error of
    // I^2 over its samples (taken as independent). The reference's noise sets it: an instability
    // below it, a deterministic method's on a still path included, is zero within the noise.
    double resolution() const;
    void add(const TemporalScore& other);
};

// One frame pair's contribution. `method` / `methodPrevious`: the method's frames t and t-1 (1 or
// 3 channels: 3 are averaged); `reference*` may be null (Dr = 0), `stderr*` may be null (no noise
// term). All images at frame t's size.
TemporalScore scoreFramePair(const Reprojection& reprojection, const Image& method, const Image& methodPrevious,
                             const Image* reference, const Image* referencePrevious, const Image* stderrNow,
                             const Image* stderrPrevious);

nlohmann::json temporalScoreJson(const TemporalScore& score);

}  // namespace vct
