#pragma once
// Camera animations of a loaded Scene, for the editor's timeline and lit-render --path:
//
//   scene.cameraAnimationNames                 every camera animation of the file, in file order
//                                              (filled by loadGltf; Blender's "fly", Lit's
//                                              "camera path", ...)
//   CameraPath path = loadCameraPath(scene, "fly");   one of them as a CameraPath
//
// The path is read from the Scene's own copy of the animation (Scene::animations), not from the
// file, so it works after the file has moved and agrees with what a save writes back. The rules
// are CameraPathIO's: Lit's extras.litCameraPath keys when present, else one key per keyframe of
// the translation/rotation channels of the camera node, with that camera's yfov. To save an
// edited path under its own name, pass that name as GltfSaveOptions::cameraPathName: the saved
// path replaces the kept animation of that name and every other animation is kept.

#include "animation/CameraPath.h"

#include <string>

namespace lit {

struct Scene;

// Throws CameraPathError naming the animation and listing the scene's camera animations when
// there is no camera animation of that name, or its data cannot make a path.
CameraPath loadCameraPath(const Scene& scene, const std::string& name);

}  // namespace lit
