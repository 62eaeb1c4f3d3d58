#pragma once
// Writes a Scene back to glTF 2.0 (.gltf + .bin, or one .glb) so that Blender and other tools
// read it: nodes with TRS (or the file's matrix while unedited), in the file's order, meshes in
// the file's layout, metallic-roughness materials (with
// KHR_materials_emissive_strength when the strength is not 1), textures and samplers,
// KHR_lights_punctual lights, perspective cameras, and optionally a camera path as a glTF
// animation (animation/CameraPathIO.h), plus everything of the source file the loader kept
// without drawing it (nodes outside the shown scene, other scenes and animations, extras,
// extensions, names of accessors and buffer views, skins, morph targets, extra vertex
// attributes, other primitive modes, orthographic cameras). loadGltf() reads everything written
// here back.
//
// Saving is atomic: every file is written under a temporary name in the target folder and then
// renamed into place (buffers first, the .gltf/.glb last), so a failed save leaves the previous
// files as they were.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lit {

struct Scene;
class CameraPath;

class SceneSaveError : public std::runtime_error {
public:
    explicit SceneSaveError(const std::string& message) : std::runtime_error(message) {}
};

struct GltfSaveOptions {
    // Written as an animation named `cameraPathName` on the scene's first camera node (a camera
    // node is added when the scene has none). Null or empty: no animation.
    const CameraPath* cameraPath = nullptr;
    std::string cameraPathName = "camera path";
    // Files saved in the same commit as the scene (the editor's settings sidecar): all of them
    // and the scene are replaced together or not at all (io/AtomicFile.h).
    std::vector<std::pair<std::filesystem::path, std::string>> alsoWrite;
};

// `file` ends in .gltf (JSON + "<stem>.bin" beside it) or .glb (one binary file). Images that
// came from a file that still exists are referenced by a relative URI; images embedded in the
// source are embedded again with their own bytes; generated ones are embedded as PNG. Throws
// SceneSaveError naming the file and the reason; on error no existing file is changed.
void saveGltf(const Scene& scene, const std::filesystem::path& file, const GltfSaveOptions& options = {});

// The line a front end logs after saving `scene` when the save differs from its source in a way
// the user should know: a scene loaded from compressed geometry (Scene::decodedCompression) is
// saved uncompressed ("written uncompressed: the source used KHR_draco_mesh_compression, which
// Lit reads but does not write"). Empty when there is nothing to say.
std::string uncompressedSaveNote(const Scene& scene);

}  // namespace lit
