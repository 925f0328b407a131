#include "render/plan.h"

#include "cone/cone_bounce.h"

#include "render/voxel_region.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace vct {

SceneFeatures analyzeScene(const Scene& scene) {
    SceneFeatures f;
    f.triangles = scene.triangles.size();
    f.materials = scene.materials.size();
    f.lights = scene.lights.size();
    f.hasTextures = !scene.textures.empty();
    // Emission counts only if some triangle uses an emissive material.
    std::vector<bool> used(scene.materials.size(), false);
    for (uint32_t m : scene.triangleMaterial)
        if (m < used.size()) used[m] = true;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        if (!used[m]) continue;
        f.hasEmission |= scene.materials[m].isEmissive();
        f.hasAlphaMask |= scene.materials[m].alphaMask;
    }
    f.hasOffscreenOccluders =
        std::any_of(scene.triangleOffscreen.begin(), scene.triangleOffscreen.end(), [](uint8_t v) { return v != 0; });
    return f;
}

const std::vector<std::string>& allPassNames() {
    static const std::vector<std::string> names = {
        "gbuffer", "shadow",   "direct",  "voxelize", "inject",       "mips",         "ssao",
        "blur",    "upsample", "cone_ao", "cone_gi",  "reference_ao", "reference_gi", "voxel_view",
        "composite"};
    return names;
}

bool RenderPlan::runs(const std::string& pass) const {
    return std::any_of(run.begin(), run.end(), [&](const PassDecl& p) { return p.name == pass; });
}

std::vector<std::string> RenderPlan::runNames() const {
    std::vector<std::string> out;
    for (const auto& p : run) out.push_back(p.name);
    return out;
}

namespace {

bool isScreenSpace(const std::string& ao) {
    return ao == "ssao-crytek" || ao == "ssao-hemisphere" || ao == "ssao-horizon" || ao == "alchemy" ||
           ao == "hbao" || ao == "gtao";
}

// The passes this request could use, with what each reads and writes, in execution order;
// `notApplicable` collects why the others cannot serve this request at all.
std::vector<PassDecl> declarePasses(const SceneFeatures& s, const RenderRequest& r,
                                    std::map<std::string, std::string>& notApplicable) {
    std::vector<PassDecl> d;
    const bool lights = s.lights > 0;
    const bool ptDirect = r.gi == "reference";  // the path tracer computes direct light itself
    const bool voxels = r.ao == "vct" || r.gi == "vct";

    d.push_back({"gbuffer", {}, {"gbuffer"}, "surface points for every estimator"});
    if (!lights) {
        notApplicable["shadow"] = "the scene has no punctual lights";
        notApplicable["direct"] = "the scene has no punctual lights";
    } else if (ptDirect) {
        notApplicable["shadow"] = "direct light comes from the path tracer (--gi reference)";
        notApplicable["direct"] = "direct light comes from the path tracer (--gi reference)";
    } else {
        d.push_back({"shadow", {}, {"shadowmaps"}, "visibility of the scene's punctual lights"});
        d.push_back({"direct", {"gbuffer", "shadowmaps"}, {"direct"}, "direct light from punctual lights"});
    }

    if (voxels) {
        d.push_back({"voxelize", {}, {"voxels"},
                     "world-space occupancy for cone tracing; " + voxelRegionExplanation(r)});
        // Without lights or emission the voxels still carry sky light once it bounces between
        // them (dense grid only: the vdb backend and clipmaps hold direct light only).
        const bool skyBounces = r.gi == "vct" && r.sky > 0.f && r.backend != "vdb" && clipmapLevelCount(r) == 0 &&
                                readVctBounces(r.params) > 0;
        const bool radiance = r.gi == "vct" && (lights || s.hasEmission || skyBounces);
        if (r.gi != "vct")
            notApplicable["inject"] = "AO needs opacity only, not radiance (no --gi vct)";
        else if (!radiance)
            notApplicable["inject"] = "the scene has no lights and no emission, and no sky light bounces between "
                                      "voxels (--sky 0, vct.bounces=0, --backend vdb or clipmaps): cones see the sky "
                                      "directly";
        else if (!lights && !s.hasEmission)
            d.push_back({"inject", {"voxels"}, {"radiance"},
                         "no lights or emission: empty direct light, then vct.bounces bounces of the sky light "
                         "between the voxels (timed as 'bounce')"});
        else
            d.push_back({"inject", {"voxels"}, {"radiance"},
                         "direct light and emission into the voxels, then vct.bounces diffuse bounces between "
                         "them (dense grid; timed as 'bounce')"});
        std::vector<std::string> mipReads{"voxels"};
        if (radiance) mipReads.push_back("radiance");
        d.push_back({"mips", mipReads, {"voxel_mips"}, "filtered levels for wide cones"});
    } else {
        const std::string why = "no method reads voxels (--ao " + r.ao + ", --gi " + r.gi + ")";
        for (const char* p : {"voxelize", "inject", "mips"}) notApplicable[p] = why;
    }

    if (isScreenSpace(r.ao)) {
        const bool halfRes = r.params.getBool("ao.half-res", false, "evaluate screen-space AO at half resolution");
        const bool blur = r.params.getBool("blur", true, "bilateral (or box) blur of screen-space AO");
        std::string produced = "ao_raw";
        d.push_back({"ssao", {"gbuffer"}, {produced}, "screen-space AO estimator " + r.ao});
        if (blur) {
            d.push_back({"blur", {"gbuffer", produced}, {"ao_blurred"}, "edge-aware denoise"});
            produced = "ao_blurred";
        } else {
            notApplicable["blur"] = "--param blur=0";
        }
        if (halfRes) d.push_back({"upsample", {"gbuffer", produced}, {"ao"}, "depth-aware upsample to full size"});
        else notApplicable["upsample"] = "full-resolution AO (ao.half-res=0)";
        if (!halfRes) d[d.size() - 1].writes = {"ao"};
    } else {
        for (const char* p : {"ssao", "blur", "upsample"})
            notApplicable[p] = "--ao " + r.ao + " is not a screen-space method";
    }
    if (r.ao == "vct") d.push_back({"cone_ao", {"gbuffer", "voxel_mips"}, {"ao"}, "world-space AO cones"});
    else notApplicable["cone_ao"] = "--ao is not vct";
    if (r.gi == "vct") d.push_back({"cone_gi", {"gbuffer", "voxel_mips"}, {"gi_indirect"}, "diffuse GI cones"});
    else notApplicable["cone_gi"] = "--gi is not vct";
    if (r.ao == "reference")
        d.push_back({"reference_ao", {"gbuffer"}, {"ao", "ao_stderr"}, "ray-traced AO at the G-buffer's points"});
    else notApplicable["reference_ao"] = "--ao is not reference";
    if (r.gi == "reference")
        d.push_back({"reference_gi", {}, {"gi_indirect", "pt_direct", "pt_beauty", "indirect_stderr"},
                     "path-traced ground truth"});
    else notApplicable["reference_gi"] = "--gi is not reference";
    if (voxels) d.push_back({"voxel_view", {"voxel_mips"}, {"voxel_view"}, "voxel grid seen from the camera"});
    else notApplicable["voxel_view"] = "no voxel grid in this render";

    if (r.gi == "reference") {
        notApplicable["composite"] = "beauty comes from the path tracer (--gi reference)";
    } else {
        std::vector<std::string> reads{"gbuffer"};
        if (lights) reads.push_back("direct");
        if (r.gi == "vct") reads.push_back("gi_indirect");
        else if (r.ao != "none") reads.push_back("ao");
        d.push_back({"composite", reads, {"beauty", "ambient"}, "emission + direct + ambient"});
    }
    return d;
}

// The resource that serves a requested AOV in this request.
std::string resourceForAov(const std::string& aov, const RenderRequest& r, const SceneFeatures& s) {
    if (aov == "beauty") return r.gi == "reference" ? "pt_beauty" : "beauty";
    if (aov == "ao") {
        if (r.ao == "none") throw std::invalid_argument("--aov ao needs an AO method (--ao METHOD)");
        return "ao";
    }
    if (aov == "ao_stderr") {
        if (r.ao != "reference") throw std::invalid_argument("--aov ao_stderr needs --ao reference");
        return "ao_stderr";
    }
    if (aov == "indirect_stderr") {
        if (r.gi != "reference") throw std::invalid_argument("--aov indirect_stderr needs --gi reference");
        return "indirect_stderr";
    }
    if (aov == "direct") {
        if (r.gi == "reference") return "pt_direct";
        return s.lights > 0 ? "direct" : "gbuffer";  // no lights: direct is zero, known from the G-buffer alone
    }
    if (aov == "indirect") return r.gi != "none" ? "gi_indirect" : "ambient";
    if (aov == "voxel_albedo" || aov == "voxel_radiance" || aov == "voxel_opacity") {
        if (r.ao != "vct" && r.gi != "vct")
            throw std::invalid_argument("--aov " + aov + " needs a voxel method (--ao vct or --gi vct)");
        if (aov == "voxel_radiance" && r.gi != "vct")
            throw std::invalid_argument("--aov voxel_radiance needs --gi vct (AO-only grids carry no radiance)");
        return "voxel_view";
    }
    if (aov == "normal" || aov == "depth" || aov == "albedo" || aov == "position" || aov == "emission")
        return "gbuffer";
    throw std::invalid_argument("unknown AOV '" + aov + "'");
}

}  // namespace

RenderPlan planRender(const SceneFeatures& scene, const RenderRequest& request) {
    std::map<std::string, std::string> notApplicable;
    std::vector<PassDecl> decls = declarePasses(scene, request, notApplicable);

    std::set<std::string> needed;
    for (const auto& aov : request.aovs) needed.insert(resourceForAov(aov, request, scene));
    if (request.ao == "reference" || request.gi == "reference") {
        // The reference's own noise is always reported with it.
        if (request.ao == "reference") needed.insert("ao_stderr");
        if (request.gi == "reference") needed.insert("indirect_stderr");
    }

    // Walk backwards: a pass runs if it writes a needed resource (or pruning is off);
    // what it reads becomes needed.
    std::vector<bool> selected(decls.size(), false);
    std::map<std::string, std::string> unusedOutputs;
    for (size_t i = decls.size(); i-- > 0;) {
        const PassDecl& p = decls[i];
        bool writesNeeded = std::any_of(p.writes.begin(), p.writes.end(),
                                        [&](const std::string& w) { return needed.count(w) != 0; });
        if (writesNeeded || !request.prune) {
            selected[i] = true;
            needed.insert(p.reads.begin(), p.reads.end());
        }
    }

    RenderPlan plan;
    std::set<std::string> declared;
    for (size_t i = 0; i < decls.size(); ++i) {
        declared.insert(decls[i].name);
        if (selected[i]) {
            plan.run.push_back(decls[i]);
        } else {
            std::string outs;
            for (const auto& w : decls[i].writes) outs += (outs.empty() ? "" : ", ") + w;
            plan.skipped.push_back({decls[i].name, "nothing requested reads its output (" + outs + ")"});
        }
    }
    for (const auto& name : allPassNames()) {
        if (declared.count(name)) continue;
        auto it = notApplicable.find(name);
        plan.skipped.push_back({name, it != notApplicable.end() ? it->second : "not applicable"});
    }
    if (plan.runs("gbuffer")) {
        if (!scene.hasTextures) plan.notes.push_back("gbuffer shader compiled without texture sampling (no textures)");
        if (!scene.hasAlphaMask) plan.notes.push_back("gbuffer shader compiled without the alpha test (no MASK materials)");
    }
    // Keep skipped passes in the canonical order for stable output.
    const auto& order = allPassNames();
    std::stable_sort(plan.skipped.begin(), plan.skipped.end(), [&](const SkippedPass& a, const SkippedPass& b) {
        return std::find(order.begin(), order.end(), a.name) < std::find(order.begin(), order.end(), b.name);
    });
    return plan;
}

std::string describePlan(const RenderPlan& plan) {
    std::ostringstream out;
    out << "passes to run:\n";
    for (const auto& p : plan.run) {
        out << "  " << p.name << ": " << p.why;
        if (!p.reads.empty()) {
            out << " (reads";
            for (const auto& r : p.reads) out << ' ' << r;
            out << ")";
        }
        out << '\n';
    }
    out << "passes left out:\n";
    for (const auto& s : plan.skipped) out << "  " << s.name << ": " << s.reason << '\n';
    if (!plan.notes.empty()) {
        out << "scene-dependent choices:\n";
        for (const auto& n : plan.notes) out << "  " << n << '\n';
    }
    return out.str();
}

}  // namespace vct
