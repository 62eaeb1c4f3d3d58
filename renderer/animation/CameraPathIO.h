#pragma once
// Camera paths on disk, two ways:
//
// 1. A small JSON file of its own (`*.path.json`), written atomically (temporary file + rename):
//      { "version": 1, "loop": false, "constantSpeed": false, "easeInOut": false,
//        "keys": [ { "time": 0, "position": [x, y, z], "rotation": [x, y, z, w], "yfov": 0.69 } ] }
//    Times in seconds, positions in metres (world space), rotations camera-to-world quaternions
//    in glTF order (x, y, z, w), yfov in radians. version and keys are required, and every field
//    of a key; the three options default to false. Unknown fields are errors (a typo such as
//    "constantspeed" would otherwise be silently ignored).
//
// 2. A glTF animation on a camera node inside the scene file, for Blender and other tools: the
//    path is sampled at kGltfSampleRate into LINEAR translation + rotation channels (so any glTF
//    player shows the same motion, easing and constant speed included; the channels are in the
//    node's parent space), and the keys themselves are stored in the animation's
//    extras.litCameraPath in the JSON format above, so Lit reloads them exactly. A file that has
//    no such extras (an animation made in Blender) is read from its channels: one key per
//    keyframe time of the translation and rotation channels, with the camera's yfov.
//    glTF cannot animate a camera's field of view without extensions: other tools see the first
//    key's yfov only when Lit creates the camera, and the camera's own yfov otherwise.
//
// Every load either returns a complete path or throws CameraPathError naming the file, the
// animation or key, and the problem; nothing is loaded half-way.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "animation/CameraPath.h"

namespace tinygltf {
class Model;
}

namespace lit {

inline constexpr int kCameraPathVersion = 1;                           // the JSON format's "version"
inline constexpr double kGltfSampleRate = 30.0;                        // Hz: keyframes written per second
inline constexpr const char* kDefaultCameraAnimation = "camera path";  // animation name Lit uses
inline constexpr const char* kCameraPathExtrasKey = "litCameraPath";   // in the animation's extras

// ---- JSON ------------------------------------------------------------------------------------
std::string cameraPathToJson(const CameraPath& path);  // pretty-printed, ends with a newline
CameraPath cameraPathFromJson(std::string_view text);  // throws CameraPathError
// Writes a temporary beside `file` and renames it over `file` (io/AtomicFile.h); creates the
// folder. Throws CameraPathError whose message starts with the file name.
void saveCameraPathJson(const std::filesystem::path& file, const CameraPath& path);
// Throws CameraPathError whose message starts with the file name.
CameraPath loadCameraPathJson(const std::filesystem::path& file);

// ---- glTF, in memory -------------------------------------------------------------------------
// Adds the animation `name` to `model`, or replaces the one of that name (reusing its accessors,
// buffer views and buffer when Lit wrote them, so saving again does not grow the file). The
// channels target `cameraNode`; -1 picks the node the animation already targets, else the first
// node with a camera, else a new perspective camera node added to the default scene. The path's
// data goes into a buffer of its own, named `name`, with no uri: the file writer below gives it
// one. Throws CameraPathError for an empty path or a node with no camera.
void writeCameraPathAnimation(tinygltf::Model& model, const CameraPath& path, const std::string& name,
                              int cameraNode = -1);
// Reads the animation `name`: its extras.litCameraPath when present, else its channels. Throws
// CameraPathError when there is no such animation, it animates no camera node, or its data is bad.
CameraPath readCameraPathAnimation(const tinygltf::Model& model, const std::string& name);
// Names of the animations a camera path can be read from (Lit's extras, or a translation or
// rotation channel on a node that holds a camera), in file order. Unnamed animations are left out.
std::vector<std::string> cameraAnimationNames(const tinygltf::Model& model);

// ---- glTF, files (.gltf or .glb) -------------------------------------------------------------
// Loads the scene file with tinygltf, writes the animation into it and writes it back with
// writeGltfModel (io/GltfFile.h): every file goes to a temporary beside its target and is
// renamed into place (buffers first, the .gltf/.glb last), so a failure leaves the old files
// intact. A .glb stays one file (extra buffers embedded); a .gltf whose buffers were all
// embedded stays embedded; otherwise the path's buffer is written next to the scene as
// "<scene>_<name>.bin". Images are kept as they were (not decoded or re-encoded).
void saveCameraPathToGltf(const std::filesystem::path& scene, const CameraPath& path,
                          const std::string& name = kDefaultCameraAnimation, int cameraNode = -1);
CameraPath loadCameraPathFromGltf(const std::filesystem::path& scene, const std::string& name);
std::vector<std::string> cameraAnimationNames(const std::filesystem::path& scene);

}  // namespace lit
