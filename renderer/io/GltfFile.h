#pragma once
// Writing a tinygltf::Model to disk as one atomic save, shared by the scene writer
// (scene/GltfWriter.h) and the camera-path saver (animation/CameraPathIO.h), plus the URI
// helpers both need for relative file references.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lit {

// Writes `model` as `file`: pretty-printed JSON text, or a GLB container when `binary` (buffer 0
// without a uri then becomes its BIN chunk). A buffer whose uri is a relative path is written to
// that file (percent-decoded) under `file`'s folder; other buffers are embedded as base64 data
// URIs. Images are written as the model describes them (their uri as it is, or bufferView and
// mimeType); Image::image is not written. A perspective camera's zfar of 0 (infinite) is left
// out instead of being written as 0, which glTF forbids and tinygltf 2.7 would do.
// Every file is written under a temporary name and renamed into place, buffers first and `file`
// last (io/AtomicFile.h), so a failure leaves all previous files as they were. Throws
// std::runtime_error whose message starts with the path of the file concerned.
// `alsoWrite`: other files committed together with the scene (staged before it).
// `jsonPatches`: (JSON pointer, JSON value text) pairs set into the document after tinygltf wrote
// it, in order, for what tinygltf 2.7 does not serialise (a sampler's name and extensions, a
// default value the source file wrote out); an empty text removes the member (a sampler's wrapS
// the source left out).
void writeGltfModel(tinygltf::Model model, const std::filesystem::path& file, bool binary,
                    const std::vector<std::pair<std::filesystem::path, std::string>>& alsoWrite = {},
                    const std::vector<std::pair<std::string, std::string>>& jsonPatches = {});

bool isDataUri(std::string_view uri);
// "%20" → ' ' (RFC 3986; '+' stays '+').
std::string percentDecode(std::string_view uri);
// A relative path as a URI reference: letters, digits, "-._~/" stay, every other byte is %XX.
std::string percentEncodePath(std::string_view path);
// A relative path inside the referring file's folder once decoded: no root, no "..".
bool staysInFolder(std::string_view uri);
std::string base64Encode(std::span<const std::uint8_t> bytes);

}  // namespace lit
