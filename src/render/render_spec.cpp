#include "render/render_spec.h"

#include "core/errors.h"

#include "core/method.h"
#include "methods/registry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vct {

RenderRequest makeRenderRequest(const RenderSpec& s, const Scene& scene) {
    RenderRequest r;
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384)
        throw UsageError("--size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                    ": each side must be in [1, 16384]");
    r.width = s.width;
    r.height = s.height;
    auto oneOf = [](const std::string& v, const std::vector<std::string>& set, const std::string& opt) {
        if (std::find(set.begin(), set.end(), v) == set.end()) {
            std::string all;
            for (const auto& x : set) all += (all.empty() ? "" : ", ") + x;
            throw UsageError(opt + " '" + v + "': expected one of " + all);
        }
    };
    requireMethod(MethodKind::AO, s.ao, "--ao");
    requireMethod(MethodKind::GI, s.gi, "--gi");
    oneOf(s.backend, {"gl", "vdb"}, "--backend");
    r.ao = s.ao;
    r.gi = s.gi;
    if (!std::isfinite(s.radius) || s.radius <= 0.f) throw UsageError("--radius must be finite and > 0");
    if (!std::isfinite(s.sky) || s.sky < 0.f) throw UsageError("--sky must be finite and >= 0");
    if (s.spp < 1 || s.spp > (1 << 20)) throw UsageError("--spp must be in [1, 1048576]");
    if (s.voxelRes < kMinVoxelRes || s.voxelRes > kMaxVoxelRes)
        throw UsageError("--voxel-res must be in [" + std::to_string(kMinVoxelRes) + ", " +
                                    std::to_string(kMaxVoxelRes) + "]");
    r.radius = s.radius;
    r.sky = s.sky;
    r.spp = s.spp;
    r.seed = s.seed;
    r.voxelRes = s.voxelRes;
    r.backend = s.backend;
    r.prune = s.prune;
    if (!s.aovs.empty()) r.aovs = s.aovs;
    for (const auto& a : r.aovs)
        if (!findAov(a)) {
            std::string all;
            for (const auto& k : knownAovs()) all += (all.empty() ? "" : ", ") + k.name;
            throw UsageError("--aov '" + a + "': unknown AOV (known: " + all + ")");
        }
    for (const auto& p : s.params) r.params.set(p);
    r.camera = resolveCamera(scene, s.camera, float(r.width) / float(r.height));
    return r;
}

void checkRenderResult(const RenderResult& result) {
    if (!result.unusedParams.empty())
        throw UsageError("--param " + result.unusedParams.front() +
                                    ": unknown parameter for this render (see --help-params)");
    for (const auto& [name, img] : result.aovs)
        for (float v : img.pixels)
            if (!std::isfinite(v)) throw InternalError("render", "AOV '" + name + "' has a non-finite value");
}

}  // namespace vct
