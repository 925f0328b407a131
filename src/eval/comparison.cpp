#include "eval/comparison.h"
#include "eval/provenance.h"

#include "eval/error_map.h"
#include "eval/image_io.h"
#include "eval/metrics.h"
#include "eval/roi.h"
#include "gl/context.h"
#include "methods/registry.h"
#include "render/renderer.h"
#include "util/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace vct {

std::string MethodVariant::label() const {
    if (params.empty()) return method;
    std::string s = method + "[";
    bool first = true;
    for (const auto& [k, v] : params) {
        s += (first ? "" : ";") + k + "=" + v;
        first = false;
    }
    return s + "]";
}

std::string MethodVariant::fileStem() const {
    std::string s = kind + "_" + label();
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_')) c = '_';
    return s;
}

std::vector<MethodVariant> parseMethodList(const std::string& text, const std::string& kind) {
    std::vector<MethodVariant> out;
    std::string item;
    int depth = 0;
    auto flush = [&] {
        if (item.empty()) return;
        MethodVariant v;
        v.kind = kind;
        size_t b = item.find('[');
        v.method = item.substr(0, b);
        if (b != std::string::npos) {
            if (item.back() != ']') throw UsageError("method '" + item + "': missing ']'");
            std::stringstream ss(item.substr(b + 1, item.size() - b - 2));
            std::string kv;
            while (std::getline(ss, kv, ';')) {
                size_t eq = kv.find('=');
                if (eq == std::string::npos || eq == 0)
                    throw UsageError("method '" + item + "': expected KEY=VALUE, got '" + kv + "'");
                v.params[kv.substr(0, eq)] = kv.substr(eq + 1);
            }
        }
        const Method* known = findMethod(kind == "gi" ? MethodKind::GI : MethodKind::AO, v.method);
        if (!known || known->groundTruth)
            throw UsageError("method '" + v.method + "' is not a " + kind + " method to compare");
        out.push_back(v);
        item.clear();
    };
    for (char c : text) {
        if (c == '[') ++depth;
        if (c == ']') --depth;
        if (c == ',' && depth == 0) flush();
        else item += c;
    }
    flush();
    return out;
}

namespace {

Image maskAnd(const Image& a, const Image& b, bool negateB) {
    Image m(a.width, a.height, 1);
    for (size_t i = 0; i < m.pixels.size(); ++i) {
        bool inB = b.pixels[i] > 0.5f;
        m.pixels[i] = (a.pixels[i] > 0.5f && (negateB ? !inB : inB)) ? 1.f : 0.f;
    }
    return m;
}

double rmsOf(const Image& img, const Image& mask) {
    double s = 0;
    size_t n = 0;
    for (size_t i = 0; i < mask.pixels.size(); ++i)
        if (mask.pixels[i] > 0.5f)
            for (int c = 0; c < img.channels; ++c, ++n) s += double(img.pixels[i * img.channels + c]) * img.pixels[i * img.channels + c];
    return n ? std::sqrt(s / n) : 0.0;
}

nlohmann::json metricsJson(const ErrorMetrics& m) {
    return {{"rmse", m.rmse}, {"mae", m.mae}, {"bias", m.bias}, {"max_abs", m.maxAbs},
            {"psnr", m.psnr}, {"ssim", m.ssim}, {"pixels", m.pixelCount}};
}

Scene withoutOffscreenOccluders(const Scene& scene) {
    Scene s = scene;
    s.triangles.clear();
    s.triangleMaterial.clear();
    s.triangleOffscreen.clear();
    for (size_t t = 0; t < scene.triangles.size(); ++t) {
        if (t < scene.triangleOffscreen.size() && scene.triangleOffscreen[t]) continue;
        s.triangles.push_back(scene.triangles[t]);
        s.triangleMaterial.push_back(scene.triangleMaterial[t]);
        s.triangleOffscreen.push_back(0);
    }
    return s;
}

}  // namespace

RenderRequest variantRequest(const RenderRequest& base, const MethodVariant& v) {
    RenderRequest req = base;
    for (const auto& [k, val] : v.params) req.params.set(k, val);
    if (v.kind == "ao") { req.ao = v.method; req.gi = kNoMethod; req.aovs = {"ao"}; }
    else { req.ao = kNoMethod; req.gi = v.method; req.aovs = {"indirect"}; }
    return req;
}

Image validMaskFromDepth(const Image& depth) {
    Image m(depth.width, depth.height, 1);
    for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = depth.pixels[i] > 0.f ? 1.f : 0.f;
    return m;
}

double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::optional<double> medianOfEveryRun(const std::vector<double>& values, size_t runs) {
    if (values.empty() || values.size() != runs) return std::nullopt;
    return medianOf(values);
}

Image displayableEstimate(const Image& img, bool radiance) {
    if (radiance) return toneMapToSrgb(img, 0.f);
    Image out = img;
    for (float& v : out.pixels) v = std::clamp(v, 0.f, 1.f);
    return out;
}

void checkComparisonSettings(const ComparisonSettings& s) {
    if (s.variants.empty()) throw UsageError("--methods and --gi name no method to compare");
    if (s.referenceSpp < 1) throw UsageError("--ref-spp must be >= 1");
    if (s.timingRuns < 1 || s.timingRuns > 100) throw UsageError("--runs must be in [1, 100]");
}

nlohmann::json runComparison(const Scene& scene, const ComparisonSettings& s) {
    auto say = [&](const std::string& line) {
        if (s.progress) s.progress(line);
    };
    namespace fs = std::filesystem;
    const bool write = !s.outputDir.empty();
    if (write) fs::create_directories(s.outputDir);
    auto path = [&](const std::string& name) { return (fs::path(s.outputDir) / name).string(); };
    const bool anyAo = std::any_of(s.variants.begin(), s.variants.end(), [](auto& v) { return v.kind == "ao"; });
    const bool anyGi = std::any_of(s.variants.begin(), s.variants.end(), [](auto& v) { return v.kind == "gi"; });

    RenderSession session(scene);
    nlohmann::json doc;
    const Camera& cam = s.base.camera;
    doc["scene"] = scene.path;
    doc["camera"] = {{"eye", {cam.eye.x, cam.eye.y, cam.eye.z}},
                     {"target", {cam.target.x, cam.target.y, cam.target.z}},
                     {"fov_deg", cam.yfov * 180.0 / M_PI}};
    doc["width"] = s.base.width;
    doc["height"] = s.base.height;
    doc["radius"] = s.base.radius;
    doc["sky"] = s.base.sky;
    doc["voxel_res"] = s.base.voxelRes;
    doc["seed"] = s.base.seed;
    doc["provenance"] = runProvenance(scene.path, s.base.seed);
    doc["gl_renderer"] = GlContext::shared().info().renderer;
    doc["cores"] = std::thread::hardware_concurrency();
    doc["timing_runs"] = s.timingRuns;

    // The reference at the G-buffer's points, and the valid (non-sky) mask.
    RenderRequest ref = s.base;
    ref.ao = anyAo ? groundTruthMethod(MethodKind::AO).name : kNoMethod;
    ref.gi = kNoMethod;
    ref.spp = s.referenceSpp;
    ref.aovs = {"depth"};
    if (anyAo) ref.aovs.insert(ref.aovs.end(), {"ao", "ao_stderr"});
    say("reference AO: " + std::to_string(s.referenceSpp) + " spp");
    RenderResult refResult = session.render(ref);
    const Image valid = validMaskFromDepth(refResult.aovs.at("depth"));
    nlohmann::json refJson = {{"spp", s.referenceSpp}};
    Image refAo, refAoStderr, roi, nonRoi, refGi, refGiStderr, roiGi, nonRoiGi;
    if (anyAo) {
        refAo = refResult.aovs.at("ao");
        refAoStderr = refResult.aovs.at("ao_stderr");
        refJson["ao_mean_stderr"] = refResult.extra["reference_ao"]["mean_stderr"];
        refJson["ao_rms_pixel_stderr"] = rmsOf(refAoStderr, valid);
        refJson["ao_time_ms"] = refResult.totalMs;
        if (write) {
            writeImage(path("reference_ao.exr"), refAo, {"ao"});
            writeImage(path("reference_ao_stderr.exr"), refAoStderr, {"ao_stderr"});
            writeImage(path("reference_ao.png"), displayableEstimate(refAo, false));
        }
    }
    const SceneFeatures features = session.features();
    doc["offscreen_occluders"] = features.hasOffscreenOccluders;
    // The scene without its off-screen parts, for the ROIs: rendered only when they exist.
    std::optional<Scene> without;
    std::optional<RenderSession> other;
    auto sessionWithout = [&]() -> RenderSession& {
        if (!other) {
            without = withoutOffscreenOccluders(scene);
            other.emplace(*without);
        }
        return *other;
    };
    if (anyAo && features.hasOffscreenOccluders) {
        // ROI: where the reference AO changes when the off-screen occluders are removed
        // (by more than 3 sigma of the two estimates' combined noise).
        say("reference AO without the off-screen occluders (ROI)");
        RenderRequest r2 = ref;
        r2.aovs = {"ao", "ao_stderr"};
        r2.seed = ref.seed + 1;
        RenderResult res2 = sessionWithout().render(r2);
        roi = maskAnd(valid, deriveRoiMask(refAo, res2.aovs.at("ao"), refAoStderr, res2.aovs.at("ao_stderr"), 3.0), false);
        nonRoi = maskAnd(valid, roi, true);
        doc["roi_pixels"] = countMask(roi);
        if (write) writeImage(path("roi.png"), roi);
    } else {
        doc["roi_pixels"] = nullptr;
    }
    RenderRequest giRef;  // the path tracer's request (its cone models', too)
    if (anyGi) {
        RenderRequest g = s.base;
        g.ao = kNoMethod;
        g.gi = groundTruthMethod(MethodKind::GI).name;
        g.spp = s.referenceSpp;
        g.aovs = {"indirect", "indirect_stderr"};
        say("reference GI: " + std::to_string(s.referenceSpp) + " spp");
        RenderResult gr = session.render(g);
        giRef = g;
        refGi = gr.aovs.at("indirect");
        refGiStderr = gr.aovs.at("indirect_stderr");
        refJson["gi_mean_stderr"] = gr.extra["reference_gi"]["mean_stderr"];
        refJson["gi_rms_pixel_stderr"] = rmsOf(refGiStderr, valid);
        refJson["gi_time_ms"] = gr.totalMs;
        refJson["gi_bounces"] = gr.extra["reference_gi"]["bounces"];
        if (write) {
            writeImage(path("reference_gi.exr"), refGi, {"R", "G", "B"});
            writeImage(path("reference_gi_stderr.exr"), refGiStderr, {"indirect_stderr"});
            writeImage(path("reference_gi.png"), displayableEstimate(refGi, true));
        }
        if (features.hasOffscreenOccluders) {
            // The GI ROI: where the reference's indirect light (the mean of its channels, whose
            // standard error the reference reports) changes when the off-screen surfaces that
            // reflect or emit it are removed, by more than 3 sigma.
            say("reference GI without the off-screen surfaces (ROI)");
            RenderRequest g2 = g;
            g2.seed = g.seed + 1;
            RenderResult gr2 = sessionWithout().render(g2);
            roiGi = maskAnd(valid,
                            deriveRoiMask(channelMean(refGi), channelMean(gr2.aovs.at("indirect")), refGiStderr,
                                          gr2.aovs.at("indirect_stderr"), 3.0),
                            false);
            nonRoiGi = maskAnd(valid, roiGi, true);
            doc["roi_pixels_gi"] = countMask(roiGi);
            if (write) writeImage(path("roi_gi.png"), roiGi);
        }
    }
    if (!doc.contains("roi_pixels_gi")) doc["roi_pixels_gi"] = nullptr;
    doc["reference"] = refJson;
    if (write) writeImage(path("error_legend.png"), falseColorLegend(256, 16, 1.0));

    // The cone model of a cone-tracing variant's cone set, by the reference's rays (AO) or
    // paths (GI): what the variant converges to as its voxels refine. One per distinct cone
    // set and kind.
    std::map<std::string, Image> coneModels;
    auto coneModelFor = [&](const MethodVariant& v) -> const Image& {
        const bool ao = v.kind == "ao";
        RenderRequest c = ao ? ref : giRef;
        c.aovs = {ao ? "ao" : "indirect"};
        c.params.set("reference.cone-model", "1");
        std::string key = v.kind + ":";
        for (const char* k : {"vct.cones", "vct.aperture", "vct.jitter"}) {
            std::string value;
            if (auto it = v.params.find(k); it != v.params.end()) value = it->second;
            else if (s.base.params.has(k)) value = s.base.params.values().at(k);
            if (value.empty()) continue;
            c.params.set(k, value);
            key += std::string(k) + "=" + value + ";";
        }
        auto found = coneModels.find(key);
        if (found != coneModels.end()) return found->second;
        say("cone model of " + v.label() + ": " + std::to_string(s.referenceSpp) + " spp");
        return coneModels.emplace(key, session.render(c).aovs.at(c.aovs.front())).first->second;
    };

    doc["records"] = nlohmann::json::array();
    for (const MethodVariant& v : s.variants) {
        say(v.kind + " " + v.label());
        const RenderRequest req = variantRequest(s.base, v);
        RenderResult first = session.render(req);  // warm-up; its image is the one scored
        std::vector<double> totals, frames, gpuFrames;
        std::map<std::string, std::vector<double>> passTimes;
        for (int run = 0; run < s.timingRuns; ++run) {
            RenderRequest timed = req;
            timed.reuseSceneData = false;  // its own voxels or BVH count in its cold time
            RenderResult r = session.render(timed);
            totals.push_back(r.totalMs);
            frames.push_back(r.frameMs);
            if (r.frameGpuMs) gpuFrames.push_back(*r.frameGpuMs);
            for (const auto& p : r.passes) passTimes[p.name].push_back(p.wallMs);
        }
        const bool isAo = v.kind == "ao";
        const Image& est = first.aovs.at(isAo ? "ao" : "indirect");
        const Image& truth = isAo ? refAo : refGi;
        double peak = 1.0;
        if (!isAo) {
            peak = 1e-30;
            for (size_t i = 0; i < valid.pixels.size(); ++i)
                if (valid.pixels[i] > 0.5f)
                    for (int c = 0; c < 3; ++c) peak = std::max(peak, double(truth.pixels[3 * i + c]));
        }
        nlohmann::json rec;
        rec["label"] = v.label();
        rec["kind"] = v.kind;
        rec["method"] = v.method;
        rec["params"] = v.params;
        rec["time_ms"] = medianOf(totals);   // cold: the scene's static data built anew
        rec["frame_ms"] = medianOf(frames);  // the same runs less what a static scene's next frame reuses
        // The per-frame passes' GPU time, where every run had it (timer queries on a GPU).
        const std::optional<double> gpuFrame = medianOfEveryRun(gpuFrames, frames.size());
        rec["frame_gpu_ms"] = gpuFrame ? nlohmann::json(*gpuFrame) : nlohmann::json(nullptr);
        nlohmann::json passes = nlohmann::json::object();
        for (const auto& [name, t] : passTimes) passes[name] = medianOf(t);
        rec["passes"] = passes;
        rec["provenance"] = doc["provenance"];
        rec["provenance"]["params"] =
            resolvedParams(isAo ? MethodKind::AO : MethodKind::GI, v.method, req.params);
        ErrorMetrics all = computeErrorMetrics(est, truth, &valid, -1, peak);
        nlohmann::json m = metricsJson(all);
        for (auto it = m.begin(); it != m.end(); ++it) rec[it.key()] = it.value();
        const Image& roiOf = isAo ? roi : roiGi;
        const Image& nonRoiOf = isAo ? nonRoi : nonRoiGi;
        if (!roiOf.empty()) {
            rec["roi_rmse"] = computeErrorMetrics(est, truth, &roiOf, -1, peak).rmse;
            rec["nonroi_rmse"] = computeErrorMetrics(est, truth, &nonRoiOf, -1, peak).rmse;
        } else {
            rec["roi_rmse"] = nullptr;
            rec["nonroi_rmse"] = nullptr;
        }
        // Total error = cone error (the cone set's) + voxel error (the voxels' alone).
        const Method* method = findMethod(isAo ? MethodKind::AO : MethodKind::GI, v.method);
        if (method && method->tracesCones) {
            const Image& model = coneModelFor(v);
            rec["cone_error_rmse"] = computeErrorMetrics(model, truth, &valid, -1, peak).rmse;
            rec["voxel_error_rmse"] = computeErrorMetrics(est, model, &valid, -1, peak).rmse;
            rec["voxel_error_bias"] = computeErrorMetrics(est, model, &valid, -1, peak).bias;
        } else {
            rec["cone_error_rmse"] = nullptr;
            rec["voxel_error_rmse"] = nullptr;
            rec["voxel_error_bias"] = nullptr;
        }
        rec["extra"] = first.extra;
        rec["cost"] = deviceIndependentCost(first.extra, s.base.width * s.base.height);
        if (write && s.writeImages) {
            const std::string stem = v.fileStem();
            writeImage(path(stem + ".exr"), est, isAo ? std::vector<std::string>{"ao"} : std::vector<std::string>{"R", "G", "B"});
            writeImage(path(stem + ".png"), displayableEstimate(est, !isAo));
            const double scale = isAo ? 0.25 : 0.25 * std::max(1e-6, imageMean(truth, &valid, -1));
            writeImage(path(stem + "_error.png"), falseColorError(est, truth, scale, &valid));
            rec["images"] = {{"exr", stem + ".exr"}, {"png", stem + ".png"}, {"error_png", stem + "_error.png"},
                             {"error_scale", scale}};
        }
        doc["records"].push_back(rec);
    }
    if (write) {
        writeImage(path("valid.png"), valid);
        writeTextFileAtomic(path("results.json"), doc.dump(2) + "\n");
        writeTextFileAtomic(path("results.csv"), resultsCsv(doc));
    }
    return doc;
}

nlohmann::json deviceIndependentCost(const nlohmann::json& extra, int pixels) {
    nlohmann::json cost = {{"samples_per_pixel", nullptr}, {"fetches_per_pixel", nullptr},
                           {"rays_per_pixel", nullptr}, {"voxel_bytes", nullptr}};
    double rays = 0.0;
    bool anyRays = false;
    for (auto it = extra.begin(); it != extra.end(); ++it) {
        const nlohmann::json& e = it.value();
        if (!e.is_object()) continue;
        if (e.contains("samples_per_pixel")) {
            cost["samples_per_pixel"] = e["samples_per_pixel"];
            cost["fetches_per_pixel"] = e["fetches_per_pixel"];
        }
        if (e.contains("rays") && e["rays"].is_number()) {
            rays += e["rays"].get<double>();
            anyRays = true;
        }
        if (e.contains("memory_bytes") && e["memory_bytes"].is_number()) cost["voxel_bytes"] = e["memory_bytes"];
    }
    if (anyRays && pixels > 0) cost["rays_per_pixel"] = rays / double(pixels);
    return cost;
}

std::string resultsCsv(const nlohmann::json& results) {
    std::ostringstream out;
    out << "scene,label,kind,method,params,time_ms,frame_ms,rmse,mae,bias,max_abs,psnr,ssim,roi_rmse,nonroi_rmse,"
           "cone_error_rmse,voxel_error_rmse,samples_per_pixel,fetches_per_pixel,rays_per_pixel,voxel_bytes\n";
    auto num = [](const nlohmann::json& j) { return j.is_null() ? std::string() : j.dump(); };
    for (const auto& r : results["records"]) {
        std::string params;
        for (auto it = r["params"].begin(); it != r["params"].end(); ++it)
            params += (params.empty() ? "" : ";") + it.key() + "=" + it.value().get<std::string>();
        out << '"' << results["scene"].get<std::string>() << "\",\"" << r["label"].get<std::string>() << "\","
            << r["kind"].get<std::string>() << ',' << r["method"].get<std::string>() << ",\"" << params << "\","
            << num(r["time_ms"]) << ',' << num(r.value("frame_ms", nlohmann::json())) << ',' << num(r["rmse"]) << ',' << num(r["mae"]) << ',' << num(r["bias"]) << ','
            << num(r["max_abs"]) << ',' << num(r["psnr"]) << ',' << num(r["ssim"]) << ',' << num(r["roi_rmse"]) << ','
            << num(r["nonroi_rmse"]) << ',' << num(r.value("cone_error_rmse", nlohmann::json())) << ','
            << num(r.value("voxel_error_rmse", nlohmann::json()));
        const nlohmann::json cost = r.value("cost", nlohmann::json::object());
        for (const char* k : {"samples_per_pixel", "fetches_per_pixel", "rays_per_pixel", "voxel_bytes"})
            out << ',' << num(cost.value(k, nlohmann::json()));
        out << '\n';
    }
    return out.str();
}

}  // namespace vct
