#pragma once
// Which glTF extensions Lit reads, checked on the file's JSON before tinygltf parses it (internal
// to the glTF import): a file that needs an extension Lit lacks must say so in one line, not fail
// later with a message about a buffer view the extension would have explained.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>

namespace lit {
class Log;
}  // namespace lit

namespace lit::gltfimport {

// Whether the loader reads `name` (its data is used, not only kept for saving).
bool isSupportedExtension(std::string_view name);

// Throws SceneLoadError "<path>: requires KHR_foo, which Lit does not support" for every required
// extension Lit does not read (all of them named in the one message); writes one warning per
// extension that is only used. KHR_texture_basisu gets its own words: KTX2 textures are not
// decoded, and a texture falls back to its other `source` when it has one. `doc` that is not a
// JSON object is left to the parser's own messages.
void checkExtensions(const std::filesystem::path& path, const nlohmann::json& doc, Log& log);

}  // namespace lit::gltfimport
