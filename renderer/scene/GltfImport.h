#pragma once
// glTF → Scene (internal to the glTF import, scene/GltfLoader.cpp): nodes, meshes, materials,
// textures, images, lights and cameras as Lit draws them, then what it keeps without drawing.

#include "scene/GltfImportDetail.h"

namespace lit::gltfimport {

// The Scene of a parsed file, world transforms computed. Throws SceneLoadError for data that
// cannot be used; recoverable problems are warnings in source.log.
Scene importScene(const GltfSource& source);

}  // namespace lit::gltfimport
