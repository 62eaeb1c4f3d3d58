#pragma once
// EXT_meshopt_compression (internal to the glTF import, scene/GltfCompression.h): one buffer
// view's compressed bytes decoded by libmeshoptimizer into the bytes the view stands for.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace lit::gltfimport {

// Decodes the extension object `extension` of a buffer view (its fields as the spec names them:
// buffer, byteOffset, byteLength, byteStride, count, mode, filter) from `source` (the bytes of
// the buffer it names, `sourceSize` of them) into `destination` (the view's own bytes,
// `destinationSize` of them). Every field is checked before libmeshoptimizer sees it (its
// decoders assert on a bad stride or count) and the data must decode completely; anything else
// throws SceneLoadError with `what` ("<file>: buffer view 3") and the reason.
void decodeMeshoptView(const std::string& what, const nlohmann::json& extension, const unsigned char* source,
                       std::size_t sourceSize, unsigned char* destination, std::size_t destinationSize);

}  // namespace lit::gltfimport
