#pragma once
// The glTF import's images (internal to the glTF import): decoded by stb_image (WebP by libwebp,
// when built with it) to RGBA8 on up to hardware_concurrency threads (or
// GltfLoadOptions::decodeThreads), progress reported on the calling thread. An image that is
// missing or cannot be decoded becomes 1x1 white with a warning, and materials that used it as a
// normal map drop the normal map (normalTexture = -1) so they fall back to vertex normals.
// Embedded images keep their encoded bytes for a save.

#include "scene/GltfImportDetail.h"

namespace lit::gltfimport {

// Fills scene.images from the file's images; runs after the materials and textures are imported
// (which images are colour, which normal maps, which textures have no image).
void importImages(const GltfSource& source, Scene& scene);

}  // namespace lit::gltfimport
