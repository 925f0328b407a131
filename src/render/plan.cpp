#include "render/plan.h"

#include "methods/registry.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace vct {

std::vector<const Method*> ActiveMethods::list() const {
    std::vector<const Method*> out;
    if (ao) out.push_back(ao);
    if (gi) out.push_back(gi);
    return out;
}

ActiveMethods activeMethods(const RenderRequest& r) {
    return {requireMethod(MethodKind::AO, r.ao, "--ao"), requireMethod(MethodKind::GI, r.gi, "--gi")};
}

std::vector<PassId> allPassIds() {
    std::vector<PassId> ids = {kPassGBuffer, kPassShadow, kPassDirect};
    for (const Method* m : registeredMethods())
        for (const MethodPass& p : m->passes)
            if (std::find(ids.begin(), ids.end(), p.id) == ids.end()) ids.push_back(p.id);
    ids.push_back(kPassComposite);
    return ids;
}

std::vector<AovInfo> knownAovs() {
    std::vector<AovInfo> all = rendererAovs();
    for (const Method* m : registeredMethods())
        for (const MethodAov& a : m->aovs)
            if (std::none_of(all.begin(), all.end(), [&](const AovInfo& k) { return k.name == a.info.name; }))
                all.push_back(a.info);
    return all;
}

const AovInfo* findAov(const std::string& name) {
    static const std::vector<AovInfo> all = knownAovs();
    for (const AovInfo& a : all)
        if (a.name == name) return &a;
    return nullptr;
}

namespace {

std::string substitute(std::string text, const RenderRequest& r) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{ao}", r.ao}, {"{gi}", r.gi}})
        for (size_t p; (p = text.find(key)) != std::string::npos;) text.replace(p, key.size(), value);
    return text;
}

// The resource that serves a requested AOV in this request.
ResourceId resourceForAov(const std::string& aov, const SceneFeatures& s, const ActiveMethods& active) {
    const bool lit = active.gi && active.gi->lightsTheImage;
    if (aov == "beauty") return kBeauty;
    if (aov == "ao") {
        if (!active.ao) throw UsageError("--aov ao needs an AO method (--ao METHOD)");
        return kAo;
    }
    // No lights: direct is zero, known from the G-buffer alone.
    if (aov == "direct") return lit || s.lights > 0 ? kDirect : kGBuffer;
    if (aov == "indirect") return active.gi ? kGiIndirect : kAmbient;
    if (aov == "normal" || aov == "depth" || aov == "position") return kGBufferSurface;
    if (aov == "albedo" || aov == "emission") return kGBuffer;
    for (const Method* m : active.list())
        for (const MethodAov& a : m->aovs)
            if (a.info.name == aov) return a.resource;
    std::string providers;
    for (const Method* m : registeredMethods())
        for (const MethodAov& a : m->aovs)
            if (a.info.name == aov)
                providers += (providers.empty() ? "" : " or ") + std::string("--") + toString(m->kind) + " " + m->name;
    if (!providers.empty()) throw UsageError("--aov " + aov + " needs " + providers);
    throw UsageError("unknown AOV '" + aov + "'");
}

}  // namespace

RenderPlan planRender(const SceneFeatures& s, const RenderRequest& r) {
    const ActiveMethods active = activeMethods(r);
    const bool lights = s.lights > 0;
    const Method* lit = active.gi && active.gi->lightsTheImage ? active.gi : nullptr;
    std::map<std::string, std::string> notApplicable;
    std::vector<PassDecl> decls;
    auto declared = [&](PassId id) {
        return std::any_of(decls.begin(), decls.end(), [&](const PassDecl& d) { return d.id == id; });
    };

    decls.push_back({kPassGBuffer, {}, {kGBuffer, kGBufferSurface}, "surface points for every estimator"});
    if (!lights) {
        for (PassId p : {kPassShadow, kPassDirect}) notApplicable[std::string(p.name)] = "the scene has no punctual lights";
    } else if (lit) {
        for (PassId p : {kPassShadow, kPassDirect})
            notApplicable[std::string(p.name)] = "direct light comes from --gi " + lit->name + ", which lights the image itself";
    } else {
        decls.push_back({kPassShadow, {}, {kShadowMaps}, "visibility of the scene's punctual lights"});
        decls.push_back({kPassDirect, {kGBuffer, kShadowMaps}, {kDirect}, "direct light from punctual lights"});
    }
    // The methods' passes; a pass two methods share (the voxels of --ao vct --gi vct) once.
    const PlanContext ctx{s, r};
    for (const Method* m : active.list()) {
        PassDeclarations d;
        m->declare(ctx, d);
        for (PassDecl& p : d.passes)
            if (!declared(p.id)) decls.push_back(std::move(p));
        for (auto& [pass, why] : d.notApplicable) notApplicable.emplace(pass, why);
    }
    if (lit) {
        notApplicable[std::string(kPassComposite.name)] = "beauty comes from --gi " + lit->name + ", which lights the image itself";
    } else {
        std::vector<ResourceId> reads{kGBuffer};
        if (lights) reads.push_back(kDirect);
        if (active.gi) reads.push_back(kGiIndirect);
        else if (active.ao) reads.push_back(kAo);
        decls.push_back({kPassComposite, reads, {kBeauty, kAmbient}, "emission + direct + ambient"});
    }

    std::set<ResourceId> needed;
    for (const auto& aov : r.aovs) needed.insert(resourceForAov(aov, s, active));

    // Walk backwards: a pass runs if it writes a needed resource (or must run, or pruning is
    // off); what it reads becomes needed.
    std::vector<bool> selected(decls.size(), false);
    for (size_t i = decls.size(); i-- > 0;) {
        const PassDecl& p = decls[i];
        const bool writesNeeded =
            std::any_of(p.writes.begin(), p.writes.end(), [&](ResourceId w) { return needed.count(w) != 0; });
        if (writesNeeded || p.alwaysRun || !r.prune) {
            selected[i] = true;
            needed.insert(p.reads.begin(), p.reads.end());
        }
    }

    RenderPlan plan;
    plan.gbufferMaterials = needed.count(kGBuffer) != 0;
    for (size_t i = 0; i < decls.size(); ++i) {
        if (selected[i]) {
            plan.run.push_back(decls[i]);
        } else {
            std::string outs;
            for (ResourceId w : decls[i].writes) outs += (outs.empty() ? "" : ", ") + std::string(w.name);
            plan.skipped.push_back({decls[i].id, "nothing requested reads its output (" + outs + ")"});
        }
    }
    // Every other known pass, with why it cannot serve this request.
    for (PassId id : allPassIds()) {
        if (declared(id)) continue;
        auto it = notApplicable.find(std::string(id.name));
        std::string reason = it != notApplicable.end() ? it->second : "not applicable";
        if (it == notApplicable.end())
            for (const Method* m : registeredMethods())
                for (const MethodPass& p : m->passes)
                    if (p.id == id && reason == "not applicable") reason = substitute(p.unusedReason, r);
        plan.skipped.push_back({id, reason});
    }
    if (plan.runs(kPassGBuffer)) {
        if (!s.hasTextures) plan.notes.push_back("gbuffer shader compiled without texture sampling (no textures)");
        if (!s.hasAlphaMask) plan.notes.push_back("gbuffer shader compiled without the alpha test (no MASK materials)");
        if (!plan.gbufferMaterials)
            plan.notes.push_back("gbuffer drawn without albedo and emission (no pass or AOV of this render reads them)");
    }
    // Skipped passes in the canonical order for stable output.
    const std::vector<PassId> order = allPassIds();
    std::stable_sort(plan.skipped.begin(), plan.skipped.end(), [&](const SkippedPass& a, const SkippedPass& b) {
        return std::find(order.begin(), order.end(), a.id) < std::find(order.begin(), order.end(), b.id);
    });
    return plan;
}

std::string describePlan(const RenderPlan& plan) {
    std::ostringstream out;
    out << "passes to run:\n";
    for (const auto& p : plan.run) {
        out << "  " << p.id.name << ": " << p.why;
        if (!p.reads.empty()) {
            out << " (reads";
            for (ResourceId r : p.reads) out << ' ' << r.name;
            out << ")";
        }
        out << '\n';
    }
    out << "passes left out:\n";
    for (const auto& s : plan.skipped) out << "  " << s.id.name << ": " << s.reason << '\n';
    if (!plan.notes.empty()) {
        out << "scene-dependent choices:\n";
        for (const auto& n : plan.notes) out << "  " << n << '\n';
    }
    return out.str();
}

}  // namespace vct
