#pragma once
// Which glTF container a file is (JSON text or binary GLB), decided from its first bytes and its
// extension before anything parses it (internal to the glTF import, scene/GltfParse.cpp).

#include <filesystem>

namespace lit::gltfimport {

enum class Container { Json, Binary };

// Decides how to parse `path` from its first bytes and extension, and checks a GLB's header
// against the file size so a truncated file is reported as such. A JSON file's syntax is checked
// too, so a truncated or hand-broken file gets a message that names the problem and the place.
// Throws SceneLoadError (scene/GltfLoader.h).
Container detectContainer(const std::filesystem::path& path);

}  // namespace lit::gltfimport
