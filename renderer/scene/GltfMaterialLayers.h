#pragma once
// KHR_materials_ior, _specular, _sheen, _clearcoat, _transmission and _volume: reading their factors
// into a Material, and writing them back into the file's extension objects (internal to the
// glTF import and export).

#include "scene/Scene.h"

#include <tiny_gltf.h>

#include <functional>
#include <string>

namespace lit::gltfkeep {

inline constexpr const char* kIorExtension = "KHR_materials_ior";
inline constexpr const char* kSpecularExtension = "KHR_materials_specular";
inline constexpr const char* kClearcoatExtension = "KHR_materials_clearcoat";
inline constexpr const char* kSheenExtension = "KHR_materials_sheen";
inline constexpr const char* kTransmissionExtension = "KHR_materials_transmission";
inline constexpr const char* kVolumeExtension = "KHR_materials_volume";

// Reads the factors of the six extensions in `extensions` into `material`. A value outside its
// range is clamped and reported through `warn`. The textures are read by the importer.
void readMaterialLayers(const tinygltf::ExtensionMap& extensions, Material& material,
                        const std::function<void(const std::string&)>& warn);

// Writes the six extensions of `material` into `extensions`: each starts from the object the
// file had (Material::kept: textures and unknown fields stay), with the factors set where they
// differ from the file's value (or, where the file had none, from the extension's default). An
// extension the file did not have is written only when a factor differs from its default.
// Calls `use` with each extension written.
void writeMaterialLayers(const Material& material, tinygltf::ExtensionMap& extensions,
                         const std::function<void(const std::string&)>& use);

}  // namespace lit::gltfkeep
