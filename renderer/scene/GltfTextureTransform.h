#pragma once
// KHR_texture_transform in a glTF texture reference and back (internal to the glTF import and
// export): the extension's JSON object ↔ scene/TextureTransform.h.

#include "scene/TextureTransform.h"

#include <tiny_gltf.h>

#include <functional>
#include <string>

namespace lit::gltfkeep {

inline constexpr const char* kTextureTransformExtension = "KHR_texture_transform";

// The reference's KHR_texture_transform (identity, present = false, when it has none). Fields of
// the wrong type or size are reported through `warn` ("offset is not two numbers; ignored") and
// keep their default.
TextureTransform readTextureTransform(const tinygltf::ExtensionMap& extensions,
                                      const std::function<void(const std::string&)>& warn);

// The extension's object for `transform`: the fields that differ from the defaults.
tinygltf::Value textureTransformValue(const TextureTransform& transform);

}  // namespace lit::gltfkeep
