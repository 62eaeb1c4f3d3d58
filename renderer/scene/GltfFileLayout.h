#pragma once
// The buffer of a saved glTF file (internal to the glTF export, scene/GltfWriter.cpp): one
// buffer, laid out as the source file had it where the bytes are the file's.

#include <tiny_gltf.h>

namespace lit {
struct Scene;
}  // namespace lit

namespace lit::gltfexport {

// Moves every buffer's bytes into buffer 0 (the camera path animation brings a buffer of its
// own), so the scene is one .bin or one BIN chunk.
void mergeBuffers(tinygltf::Model& model);

// Puts written buffer views whose bytes a view of the source file had (same length and hash,
// Scene::fileBufferViews) at that view's place, so an unedited file's .bin comes back byte for
// byte; the other views go into the gaps or after the end. Runs on the merged buffer 0.
void keepFileLayout(tinygltf::Model& model, const Scene& scene);

}  // namespace lit::gltfexport
