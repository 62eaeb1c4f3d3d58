#pragma once
// KHR_draco_mesh_compression (internal to the glTF import, scene/GltfCompression.h): one
// primitive's Draco mesh decoded by libdraco into plain accessors.

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <string>

namespace lit::gltfimport {

// Decodes the Draco mesh of `primitive` (its extension object `extension`: bufferView and the
// attribute ids) and points the accessors it names at the result: each accessor's elements, in
// the accessor's own type, appended tightly packed (4-byte aligned) to `model.buffers[decoded]`
// in a new buffer view. Only the indices and the attributes the extension lists are decoded;
// the primitive's other attributes keep their own buffer views. Checks before use: the buffer
// view inside its buffer, a triangle mesh with indices, the decoded point and face counts equal
// to the accessors' counts, every index inside the points and representable in the index type.
// Throws SceneLoadError with `what` ("<file>: mesh 2 ('box') primitive 0") and the reason.
void decodeDracoPrimitive(const std::string& what, const nlohmann::json& extension,
                          const tinygltf::Primitive& primitive, tinygltf::Model& model, int decoded);

}  // namespace lit::gltfimport
