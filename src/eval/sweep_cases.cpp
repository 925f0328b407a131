// The cases of a sweep: the spec's scenes x cameras x radii in a fixed order, with ids that
// name a case's directory, and the case.json that describes one.
#include "eval/sweep_spec.h"

#include "eval/sweep_detail.h"

#include <cctype>
#include <cstdio>
#include <map>

namespace vct {

using nlohmann::json;

namespace {

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_')) c = '_';
    return s;
}

std::string radiusText(float r) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(r));
    return buf;
}

}  // namespace

std::vector<SweepCase> enumerateSweepCases(const SweepSpec& spec) {
    std::vector<SweepCase> out;
    std::map<std::string, std::string> seen;  // id -> what made it
    for (size_t si = 0; si < spec.scenes.size(); ++si) {
        const SweepScene& s = spec.scenes[si];
        for (const SweepCamera& cam : s.cameras)
            for (float r : s.settings.radii) {
                SweepCase c;
                c.index = out.size();
                c.scene = si;
                c.camera = cam;
                c.radius = r;
                c.id = fileSafe(s.stem + "__" + cam.label + "__r" + radiusText(r));
                const std::string what = "scene '" + s.entry + "' camera '" + cam.label + "' radius " + radiusText(r);
                auto [it, fresh] = seen.emplace(c.id, what);
                if (!fresh)
                    sweep_detail::fail("scenes", "two cases share the id '" + c.id + "' (" + it->second + "; " +
                                                     what + "): rename a camera or a scene file");
                out.push_back(c);
            }
    }
    return out;
}

json caseJson(const SweepSpec& spec, const SweepCase& c) {
    const SweepScene& s = spec.scenes.at(c.scene);
    json cam = {{"label", c.camera.label}};
    if (c.camera.isPath()) {
        cam["path"] = c.camera.path.entry;
        if (c.camera.path.animation.empty()) cam["path_file"] = c.camera.path.file.source;
        cam["frames"] = c.camera.path.frames;
        cam["frame_seeds"] = c.camera.path.perFrameSeeds ? "per-frame" : "fixed";
    } else if (c.camera.hasEye) {
        cam["eye"] = {c.camera.eye.x, c.camera.eye.y, c.camera.eye.z};
        cam["target"] = {c.camera.target.x, c.camera.target.y, c.camera.target.z};
        cam["fov_deg"] = c.camera.fovDeg;
    } else {
        cam["name_or_index"] = c.camera.nameOrIndex;
    }
    json variants = json::array();
    for (const MethodVariant& v : s.variants) variants.push_back({{"kind", v.kind}, {"label", v.label()}});
    return {{"id", c.id},
            {"index", c.index},
            {"scene", s.stem},
            {"scene_entry", s.entry},
            {"scene_path", s.path},
            {"camera", cam},
            {"radius", c.radius},
            {"width", s.settings.width},
            {"height", s.settings.height},
            {"ref_spp", s.settings.referenceSpp},
            {"runs", s.settings.timingRuns},
            {"voxel_res", s.settings.voxelRes},
            {"seed", s.settings.seed},
            {"sky", s.settings.sky},
            {"params", s.settings.params},
            {"variants", variants},
            {"spec", spec.specPath},
            {"spec_name", spec.name}};
}

}  // namespace vct
