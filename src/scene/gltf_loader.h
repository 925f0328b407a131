// glTF 2.0 (.gltf / .glb) to the flat world-space Scene of scene.h.
//
// What the loader does with the file:
// - the node hierarchy of the default scene (or of every root node when the file has no
//   scenes) is baked into world space: positions by the node's world matrix, normals by
//   its inverse transpose, winding flipped where the matrix mirrors (negative determinant);
// - TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives become one triangle list;
//   POINTS and LINES* are an error that names the mesh and primitive;
// - primitives without NORMAL get flat normals (the glTF spec asks for flat normals;
//   every triangle gets its own three vertices); a zero or unusable normal in the file is
//   replaced by the area-weighted average of the face normals around that vertex;
// - zero-area triangles are dropped and counted in Scene::warnings;
// - a node whose name starts with "offscreen" or whose extras hold
//   {"offscreen_occluder": true} marks its triangles, and those of its descendants, in
//   Scene::triangleOffscreen;
// - KHR_lights_punctual and KHR_materials_emissive_strength are read; glTF lights and
//   cameras look down -Z of their node, with +Y up.
//
// Every problem throws SceneError with the file and the element in the message, e.g.
// "scenes/x.gltf: accessor 3 (mesh 'floor', primitive 0, indices): index 77 out of range [0, 24)".
#pragma once

#include "scene/scene.h"

#include <stdexcept>
#include <string>

namespace tinygltf {
class Model;
}

namespace vct {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Reads a .gltf (JSON, external or embedded buffers) or .glb file; the format is chosen by
// the file's first four bytes ("glTF" = binary), not by its extension.
Scene loadScene(const std::string& path);

// Converts an already parsed model; `pathForMessages` prefixes error messages and is
// stored in Scene::path. Used by loadScene and by SceneBuilder::toScene.
Scene sceneFromModel(const tinygltf::Model& model, const std::string& pathForMessages);

}  // namespace vct
