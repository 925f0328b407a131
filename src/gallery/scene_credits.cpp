#include "gallery/scene_credits.h"

#include <filesystem>
#include <map>

namespace vct {

std::string sceneCredit(const std::string& scenePath) {
    // Copied from shared/scenes/README.md; keep in step when scenes are added there.
    static const std::map<std::string, std::string> kThirdParty = {
        {"mcguire_CornellBox-Original.glb",
         "Cornell Box by Guedis Cardenas and Morgan McGuire, Williams College 2011 (McGuire Computer "
         "Graphics "
         "Archive); CC BY 3.0"},
        {"floor_cube.glb", "made for this project (Blender)"},
        {"floor_suzanne.glb", "made for this project (Blender's Suzanne primitive)"},
        {"npm_bunny.glb", "low-resolution Stanford bunny (npm package 'bunny'); public domain"},
        {"mcguire_bunny.glb",
         "Stanford bunny (Stanford 3D Scanning Repository), via the McGuire Computer Graphics Archive; "
         "Stanford scan terms"},
        {"mcguire_sponza.glb",
         "Dabrovic Sponza by Marko Dabrovic, fixes by Kenzie Lamar, McGuire Computer Graphics Archive; CC "
         "BY-NC"},
        {"mcguire_sibenik.glb",
         "Sibenik cathedral by Marko Dabrovic, fixes by Kenzie Lamar, McGuire Computer Graphics Archive; CC "
         "BY-NC"},
        {"mcguire_lost_empire.glb",
         "\"Lost Empire\" (Vokselia Minecraft world) via Mineways, McGuire Computer Graphics Archive; CC BY "
         "3.0"},
        {"mcguire_conference.glb",
         "Conference room by Greg Ward, recreated by Kenzie Lamar, McGuire Computer Graphics Archive; "
         "public domain"},
    };
    const std::string name = std::filesystem::path(scenePath).filename().string();
    if (auto it = kThirdParty.find(name); it != kThirdParty.end()) return it->second;
    // The project's own scenes are the .gltf files in its scenes/ folder (tools/scenegen).
    const std::filesystem::path p(scenePath);
    if (p.extension() == ".gltf" && p.parent_path().filename() == "scenes")
        return "made for this project (vct, tools/scenegen)";
    return "credit unknown: see the scene's source";
}

}  // namespace vct
