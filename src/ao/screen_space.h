// What every screen-space AO method shares: its passes (evaluate at full or half
// resolution, blur, upsample), the filter settings, and the Method descriptor built from an
// estimator's own part. A screen-space method is an estimator (settings, one evaluation
// pass) in a folder of its own under src/ao/, made a Method by screenSpaceMethod().
//
// Every method takes the reference's world radius R and returns A in [0, 1] (1 = open) at
// the G-buffer's resolution; sky pixels are 1.
#pragma once

#include "ao/ao_filters.h"
#include "ao/ao_pass.h"
#include "core/method.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vct {

inline constexpr PassId kPassSsao{"ssao"};
inline constexpr PassId kPassBlur{"blur"};
inline constexpr PassId kPassUpsample{"upsample"};
inline constexpr ResourceId kAoRaw{"ao_raw"};
inline constexpr ResourceId kAoBlurred{"ao_blurred"};

// An estimator's own part.
struct ScreenSpaceAo {
    std::string name;        // as --ao accepts it
    std::string summary;
    bool noiseTile = false;  // a 4x4 rotation tile that the box blur undoes (ssao-crytek, -hemisphere)
    // The estimator's keys (its settings table's docs).
    std::function<std::vector<SettingDoc>()> settings;
    // Method::presetValues: the values its presets give the keys they set; empty: none.
    std::function<std::map<std::string, std::string>(const ParamMap& params)> presetValues;
    // One evaluation at ctx's resolution (R32F). `filtered`: a blur or upsample follows, so
    // values above 1 may be kept for it.
    std::function<GlTexture(const AoPassContext& ctx, const ParamMap& params, bool filtered)> evaluate;
    std::vector<ProgramKey> programs;  // the evaluation's programs
    // Whether the evaluation reads the G-buffer's albedo with these parameters (GTAO's
    // multi-bounce fit); empty: never. The others read the surface alone, so an AO-only
    // render draws its G-buffer without materials.
    std::function<bool(const ParamMap& params)> readsAlbedo;
};

// The Method of a screen-space estimator: passes ssao, blur, upsample.
Method screenSpaceMethod(const ScreenSpaceAo& ao);

// Runs `ao` (evaluate, then the blur and upsample the filter settings ask for) and returns
// an R32F texture of gbuffer.width x gbuffer.height (GL bottom-left origin, as the
// G-buffer). `view` must be the camera the G-buffer was rendered with; `seed` fixes kernels
// and per-pixel noise. Throws UsageError for a bad parameter and InternalError for a radius
// that is not finite and > 0 or a view/G-buffer size mismatch.
GlTexture computeScreenSpaceAO(const ScreenSpaceAo& ao, const GBuffer& gbuffer, const View& view, float radius,
                               const ParamMap& params, uint64_t seed, PassTimer& timer);

// The blur's and upsample's programs (shared by every screen-space method).
std::vector<ProgramKey> screenSpaceFilterPrograms();

}  // namespace vct
