#include "eval/sequence_comparison.h"

#include "core/errors.h"
#include "eval/image_io.h"
#include "eval/metrics.h"
#include "eval/provenance.h"
#include "eval/temporal.h"
#include "gl/context.h"
#include "methods/registry.h"
#include "render/renderer.h"
#include "scene/gltf_animation.h"
#include "util/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

namespace vct {

namespace {

std::string frameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "%04d.png", frame);
    return name;
}

// What one frame of the reference gives every variant of that frame.
struct ReferenceFrame {
    View view;
    Image depth, position, normal, valid;
    Image ao, aoStderr, gi, giStderr;
};

// What a variant keeps from frame to frame.
struct VariantTrack {
    MethodVariant variant;
    Image previous;
    std::vector<double> rmse, frameMs, instability;
    TemporalScore temporal;
    double coldMs = 0.0;
    nlohmann::json extra, cost;
};

}  // namespace

void checkSequenceSettings(const SequenceSettings& s) {
    checkComparisonSettings(s.comparison);
    if (s.frames < 1 || s.frames > 10000) throw UsageError("--frames must be in [1, 10000]");
    if (s.path.keys.empty()) throw UsageError("--path " + s.path.source + ": the path has no keys");
}

void poseSequenceFrame(RenderSession& session, Scene& scene, const std::string& animation, double t) {
    if (&scene != &session.scene())
        throw InternalError("poseSequenceFrame", "the scene posed is not the one the session renders");
    if (animation.empty()) return;
    const AnimationPose moved = poseAnimation(scene, animation, t);
    if (moved.meshesMoved) session.geometryChanged();
    else if (moved.lightsMoved) session.lightsChanged();
}

nlohmann::json runSequenceComparison(const Scene& scene, const SequenceSettings& s) {
    const ComparisonSettings& c = s.comparison;
    auto say = [&](const std::string& line) {
        if (c.progress) c.progress(line);
    };
    namespace fs = std::filesystem;
    const bool write = !c.outputDir.empty();
    if (write) fs::create_directories(c.outputDir);
    auto path = [&](const std::string& name) { return (fs::path(c.outputDir) / name).string(); };
    auto writeFrame = [&](const std::string& stem, int frame, const Image& img, bool radiance) {
        if (!write || !c.writeImages) return;
        const fs::path dir = fs::path(c.outputDir) / "frames" / stem;
        fs::create_directories(dir);
        writeImage((dir / frameName(frame)).string(), displayableEstimate(img, radiance));
    };
    const bool anyAo = std::any_of(c.variants.begin(), c.variants.end(), [](auto& v) { return v.kind == "ao"; });
    const bool anyGi = std::any_of(c.variants.begin(), c.variants.end(), [](auto& v) { return v.kind == "gi"; });
    const std::vector<double> times = pathFrameTimes(s.path, s.frames);

    // The lights and objects the path's animation moves are posed on a copy the session
    // renders, whose bounds hold every pose.
    Scene posed = scene;
    if (!s.path.animation.empty()) posed.bounds = animationBounds(scene, s.path.animation);
    RenderSession session(posed);
    std::vector<VariantTrack> tracks;
    for (const MethodVariant& v : c.variants) tracks.push_back(VariantTrack{v, {}, {}, {}, {}, {}, 0.0, {}, {}});
    TemporalScore refAoSelf, refGiSelf;
    std::vector<double> refAoMs, refGiMs;
    ReferenceFrame previous;
    for (int f = 0; f < s.frames; ++f) {
        say("frame " + std::to_string(f + 1) + "/" + std::to_string(s.frames));
        poseSequenceFrame(session, posed, s.path.animation, times[size_t(f)]);
        RenderRequest base = c.base;
        // Near and far planes around the posed scene's bounds (those the animation sweeps), as
        // `vct render --path` frames them.
        base.camera = cameraOnPath(s.path, times[size_t(f)], posed);
        base.seed = frameSeed(c.base.seed, f);
        ReferenceFrame now;
        now.view = makeView(base.camera, base.width, base.height);
        RenderRequest ref = base;
        ref.ao = anyAo ? groundTruthMethod(MethodKind::AO).name : kNoMethod;
        ref.gi = kNoMethod;
        ref.spp = c.referenceSpp;
        ref.aovs = {"depth", "position", "normal"};
        if (anyAo) ref.aovs.insert(ref.aovs.end(), {"ao", "ao_stderr"});
        RenderResult rr = session.render(ref);
        now.depth = rr.aovs.at("depth");
        now.position = rr.aovs.at("position");
        now.normal = rr.aovs.at("normal");
        now.valid = validMaskFromDepth(now.depth);
        if (anyAo) {
            now.ao = rr.aovs.at("ao");
            now.aoStderr = rr.aovs.at("ao_stderr");
            // As the variants' frames below: what the frame paid (a BVH rebuilt for moved objects).
            refAoMs.push_back(f == 0 ? rr.frameMs : rr.totalMs);
            writeFrame("reference_ao", f, now.ao, false);
        }
        if (anyGi) {
            RenderRequest g = base;
            g.ao = kNoMethod;
            g.gi = groundTruthMethod(MethodKind::GI).name;
            g.spp = c.referenceSpp;
            g.aovs = {"indirect", "indirect_stderr"};
            RenderResult gr = session.render(g);
            now.gi = gr.aovs.at("indirect");
            now.giStderr = gr.aovs.at("indirect_stderr");
            refGiMs.push_back(f == 0 ? gr.frameMs : gr.totalMs);
            writeFrame("reference_gi", f, now.gi, true);
        }
        Reprojection reprojection;
        if (f > 0) {
            reprojection = reprojectFrame(now.view, now.position, now.depth, now.normal, previous.view,
                                          previous.position, previous.depth, previous.normal);
            if (anyAo)
                refAoSelf.add(scoreFramePair(reprojection, now.ao, previous.ao, nullptr, nullptr, &now.aoStderr,
                                             &previous.aoStderr));
            if (anyGi)
                refGiSelf.add(scoreFramePair(reprojection, now.gi, previous.gi, nullptr, nullptr, &now.giStderr,
                                             &previous.giStderr));
        }
        for (VariantTrack& t : tracks) {
            const bool isAo = t.variant.kind == "ao";
            RenderRequest req = variantRequest(base, t.variant);
            if (!s.perFrameSeeds) req.seed = c.base.seed;
            RenderResult r = session.render(req);
            const Image& est = r.aovs.at(isAo ? "ao" : "indirect");
            t.rmse.push_back(computeErrorMetrics(est, isAo ? now.ao : now.gi, &now.valid).rmse);
            // The frame as the sequence paid for it: what reran because the camera moved (a
            // camera-fitted voxel region is rebuilt, a scene-wide grid is not), less the
            // G-buffer every method shares (drawn by the frame's first render, or again with
            // materials by the first method that reads them).
            double gbufferMs = 0.0;
            for (const PassTiming& p : r.passes)
                if (p.name == "gbuffer") gbufferMs += p.wallMs;
            t.frameMs.push_back((f == 0 ? r.frameMs : r.totalMs) - gbufferMs);
            if (f == 0) {
                t.extra = r.extra;
                t.cost = deviceIndependentCost(r.extra, req.width * req.height);
                std::vector<double> cold;
                for (int run = 0; run < c.timingRuns; ++run) {
                    RenderRequest timed = req;
                    timed.reuseSceneData = false;
                    cold.push_back(session.render(timed).totalMs);
                }
                t.coldMs = medianOf(cold);
            } else {
                const TemporalScore pair = isAo ? scoreFramePair(reprojection, est, t.previous, &now.ao, &previous.ao,
                                                                 &now.aoStderr, &previous.aoStderr)
                                                : scoreFramePair(reprojection, est, t.previous, &now.gi, &previous.gi,
                                                                 &now.giStderr, &previous.giStderr);
                t.instability.push_back(pair.instability());
                t.temporal.add(pair);
            }
            writeFrame(t.variant.fileStem(), f, est, !isAo);
            t.previous = est;
        }
        previous = std::move(now);
    }

    nlohmann::json doc;
    doc["scene"] = scene.path;
    doc["path"] = cameraPathToJson(s.path);
    doc["path"]["source"] = s.path.source;
    doc["frames"] = s.frames;
    doc["times"] = times;
    doc["per_frame_seeds"] = s.perFrameSeeds;
    doc["width"] = c.base.width;
    doc["height"] = c.base.height;
    doc["radius"] = c.base.radius;
    doc["sky"] = c.base.sky;
    doc["voxel_res"] = c.base.voxelRes;
    doc["seed"] = c.base.seed;
    doc["provenance"] = runProvenance(scene.path, uint32_t(c.base.seed));
    doc["gl_renderer"] = GlContext::shared().info().renderer;
    doc["cores"] = std::thread::hardware_concurrency();
    doc["timing_runs"] = c.timingRuns;
    nlohmann::json refJson = {{"spp", c.referenceSpp}};
    if (anyAo) {
        refJson["ao_frame_ms"] = medianOf(refAoMs);
        refJson["ao_temporal"] = temporalScoreJson(refAoSelf);
    }
    if (anyGi) {
        refJson["gi_frame_ms"] = medianOf(refGiMs);
        refJson["gi_temporal"] = temporalScoreJson(refGiSelf);
    }
    doc["reference"] = refJson;
    doc["records"] = nlohmann::json::array();
    for (const VariantTrack& t : tracks) {
        const bool isAo = t.variant.kind == "ao";
        nlohmann::json rec;
        rec["label"] = t.variant.label();
        rec["kind"] = t.variant.kind;
        rec["method"] = t.variant.method;
        rec["params"] = t.variant.params;
        double sum = 0.0;
        for (double e : t.rmse) sum += e;
        rec["rmse_mean"] = sum / double(t.rmse.size());
        rec["rmse_worst"] = *std::max_element(t.rmse.begin(), t.rmse.end());
        std::vector<double> steady(t.frameMs.begin() + (t.frameMs.size() > 1 ? 1 : 0), t.frameMs.end());
        rec["frame_ms"] = medianOf(steady);
        rec["time_ms"] = t.coldMs;
        rec["temporal"] = temporalScoreJson(t.temporal);
        rec["instability"] = t.temporal.instability();
        rec["per_frame"] = {{"rmse", t.rmse}, {"frame_ms", t.frameMs}, {"instability", t.instability}};
        rec["cost"] = t.cost;
        rec["extra"] = t.extra;
        const RenderRequest req = variantRequest(c.base, t.variant);
        rec["provenance"] = doc["provenance"];
        rec["provenance"]["params"] =
            resolvedParams(isAo ? MethodKind::AO : MethodKind::GI, t.variant.method, req.params);
        if (write && c.writeImages) rec["frames_dir"] = "frames/" + t.variant.fileStem();
        doc["records"].push_back(rec);
    }
    if (write) {
        writeTextFileAtomic(path("results.json"), doc.dump(2) + "\n");
        writeTextFileAtomic(path("results.csv"), sequenceResultsCsv(doc));
    }
    return doc;
}

std::string sequenceResultsCsv(const nlohmann::json& results) {
    std::ostringstream out;
    out << "scene,label,kind,method,params,frames,rmse_mean,rmse_worst,instability,change_rms,reference_noise_rms,"
           "frame_ms,time_ms\n";
    for (const auto& r : results["records"]) {
        std::string params;
        for (auto it = r["params"].begin(); it != r["params"].end(); ++it)
            params += (params.empty() ? "" : ";") + it.key() + "=" + it.value().get<std::string>();
        out << '"' << results["scene"].get<std::string>() << "\",\"" << r["label"].get<std::string>() << "\","
            << r["kind"].get<std::string>() << ',' << r["method"].get<std::string>() << ",\"" << params << "\","
            << results["frames"].dump() << ',' << r["rmse_mean"].dump() << ',' << r["rmse_worst"].dump() << ','
            << r["instability"].dump() << ',' << r["temporal"]["change_rms"].dump() << ','
            << r["temporal"]["reference_noise_rms"].dump() << ',' << r["frame_ms"].dump() << ','
            << r["time_ms"].dump() << '\n';
    }
    return out.str();
}

}  // namespace vct
