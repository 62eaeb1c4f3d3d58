#pragma once
// Reading a glTF file into a tinygltf model (internal to the glTF import, scene/GltfLoader.cpp):
// the guard's checks first (io/GltfGuard.h), then tinygltf with the guarded file callbacks,
// keeping each image's encoded bytes for the import to decode.

#include "scene/GltfImportDetail.h"

#include <filesystem>

namespace lit {
class Log;
}  // namespace lit

namespace lit::gltfimport {

// Throws SceneLoadError for a file that cannot be parsed or exceeds options.limits; tinygltf's
// warnings, images it could not take and files the guard refused go to `log`.
ParsedGltf parseGltf(const std::filesystem::path& path, Log& log, const GltfLoadOptions& options);

}  // namespace lit::gltfimport
