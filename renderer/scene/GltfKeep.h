#pragma once
// What the glTF import keeps of a file for a lossless save, and the export writes back (internal
// to the scene/GltfImport* and scene/GltfExport* files, and animation/SceneCameraPaths.cpp):
// extras and extensions as JSON text, so the Scene stays free of tinygltf types.

#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace lit::gltfkeep {

// Bytes per component of a glTF 2.0 accessor component type; 0 for anything else (tinygltf's
// GetComponentSizeInBytes also takes INT and DOUBLE, which glTF 2.0 accessors may not use).
inline int componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

nlohmann::json toJson(const tinygltf::Value& value);
tinygltf::Value toValue(const nlohmann::json& j);

// FNV-1a, 64 bits: tells a buffer view's bytes at save time from the file's (Scene::fileBufferViews).
inline std::uint64_t hashBytes(const unsigned char* bytes, std::size_t count) {
    std::uint64_t hash = 14695981039346656037ull;
    for (std::size_t i = 0; i < count; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    return hash;
}

// Extras as JSON text ("" when absent).
std::string extrasText(const tinygltf::Value& extras);

// The extensions except those Lit reads and writes itself (`known`), as a JSON object text.
std::string extensionsText(const tinygltf::ExtensionMap& extensions, std::initializer_list<const char*> known = {});

KeptGltf keep(const tinygltf::Value& extras, const tinygltf::ExtensionMap& extensions,
              std::initializer_list<const char*> known = {});

// Writes kept extras/extensions back; extensions already present (Lit's own) win.
void restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions);

// A material's optional fields (JSON pointers inside the material object) whose presence a save
// keeps: the loader notes those the file wrote (Material::fileFields), the writer writes them
// again even where they hold glTF's default, which tinygltf leaves out.
inline constexpr const char* kMaterialFields[] = {"alphaCutoff",
                                                  "alphaMode",
                                                  "doubleSided",
                                                  "emissiveFactor",
                                                  "pbrMetallicRoughness/baseColorFactor",
                                                  "pbrMetallicRoughness/metallicFactor",
                                                  "pbrMetallicRoughness/roughnessFactor",
                                                  "pbrMetallicRoughness/baseColorTexture/texCoord",
                                                  "pbrMetallicRoughness/metallicRoughnessTexture/texCoord",
                                                  "normalTexture/texCoord",
                                                  "normalTexture/scale",
                                                  "emissiveTexture/texCoord",
                                                  "occlusionTexture/texCoord",
                                                  "occlusionTexture/strength"};

// Extras and extensions of a JSON object the parser does not read (sparse accessor parts).
KeptGltf keepFromJson(const nlohmann::json& object);

}  // namespace lit::gltfkeep
