#pragma once
// glTF 2.0 import (.gltf and .glb) through tinygltf, into lit::Scene.

#include "scene/Scene.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace lit {

class Log;

// A file that cannot be loaded. The message names the file and the problem ("accessor 3 reads
// past the end of buffer view 1", "not a glTF file", ...).
class SceneLoadError : public std::runtime_error {
public:
    explicit SceneLoadError(const std::string& message) : std::runtime_error(message) {}
};

// Loads a scene. Throws SceneLoadError for files that cannot be used; recoverable problems
// (a missing or undecodable texture, an unsupported extension) become warnings in `log` and the
// texture is replaced by a neutral one (1×1 white; a material that used it as its normal map
// gets normalTexture = -1). The returned scene has world transforms computed.
Scene loadGltf(const std::filesystem::path& path, Log& log);

}  // namespace lit
