#pragma once
// Compressed glTF geometry (internal to the glTF import): EXT_meshopt_compression
// (scene/GltfMeshopt.h) and KHR_draco_mesh_compression (scene/GltfDraco.h).
//
// tinygltf 2.7 cannot parse either: a meshopt fallback buffer has no data ("Invalid byteLength")
// and a Draco primitive's indices accessor has no buffer view ("accessor[0] invalid bufferView").
// So a load of such a file runs in two steps around tinygltf:
//   1. tinygltfInput: the file's JSON rewritten so that tinygltf takes it (a fallback buffer gets
//      a 3-byte placeholder, a Draco primitive loses its `indices` until step 2);
//   2. decodeCompressedGeometry: the compressed data decoded into the parsed model, which then
//      reads as an uncompressed file (the extensions removed from buffers, buffer views,
//      primitives, extensionsUsed and extensionsRequired). The import after it sees plain
//      accessors; a save writes the geometry uncompressed (docs/ARCHITECTURE.md).

#include "io/GltfGuard.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace lit::gltfimport {

// The compression extensions a file's JSON uses (in extensionsUsed or extensionsRequired), in a
// fixed order: EXT_meshopt_compression, KHR_draco_mesh_compression.
std::vector<std::string> compressionExtensions(const nlohmann::json& doc);

// Step 1: the bytes to give tinygltf in place of `guarded.bytes` (a GLB rebuilt around the new
// JSON chunk) or of `guarded.json` (a .gltf); empty when the file needs no rewriting.
std::vector<unsigned char> tinygltfInput(const GuardedScene& guarded, const nlohmann::json& doc);

// Step 2 on the model tinygltf parsed from step 1's bytes. Every field of the extensions is
// checked before use, and decoded sizes against `limits.memoryBudgetBytes`; a file whose
// compressed data is malformed, truncated or disagrees with its accessors throws SceneLoadError
// naming the buffer view or primitive. Returns compressionExtensions(doc).
std::vector<std::string> decodeCompressedGeometry(const std::filesystem::path& path, const nlohmann::json& doc,
                                                  const GltfLimits& limits, tinygltf::Model& model);

}  // namespace lit::gltfimport
