#pragma once
// glTF meshes → Scene::meshes (internal to the glTF import, scene/GltfImport.cpp):
// - Missing NORMALs are computed as flat normals (the primitive is unwelded, as glTF requires);
//   missing TANGENTs are always computed (not only for normal-mapped materials), so every
//   vertex carries a valid tangent frame. A file's TANGENTs are ignored when its NORMALs are
//   missing (glTF 2.0 §3.7.2.1).
// - Only mode TRIANGLES is drawn; primitives of other modes are kept for saving
//   (Mesh::otherPrimitives, warning), and so are the attributes and morph targets Lit does not
//   draw with (scene/GltfImportKept.h).

#include "scene/GltfImportDetail.h"

namespace lit::gltfimport {

// Needs scene.materials: computed tangents follow the UV set of a primitive's normal texture, and a
// primitive whose material reads TEXCOORD_1 without having it is named.
void importMeshes(const GltfSource& source, Scene& scene);

}  // namespace lit::gltfimport
