// EXT_meshopt_compression decoding (scene/GltfMeshopt.h). The extension's specification:
// https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Vendor/EXT_meshopt_compression

#include "scene/GltfMeshopt.h"

#include <meshoptimizer.h>

#include <cstdint>
#include <limits>
#include <optional>

#include "scene/GltfLoader.h"

namespace lit::gltfimport {

namespace {

// A non-negative integer field, or `fallback` when absent; anything else is an error.
std::size_t unsignedField(const std::string& what, const nlohmann::json& object, const char* key,
                          std::optional<std::size_t> fallback) {
    const auto found = object.find(key);
    if (found == object.end()) {
        if (!fallback) throw SceneLoadError(what + ": EXT_meshopt_compression has no '" + key + "'");
        return *fallback;
    }
    if (!found->is_number_unsigned() || found->get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
        throw SceneLoadError(what + ": EXT_meshopt_compression's '" + key + "' is " + found->dump() +
                             ", not an unsigned 32-bit integer");
    return static_cast<std::size_t>(found->get<std::uint64_t>());
}

std::string stringField(const std::string& what, const nlohmann::json& object, const char* key, const char* fallback) {
    const auto found = object.find(key);
    if (found == object.end() && fallback) return fallback;
    if (found == object.end() || !found->is_string())
        throw SceneLoadError(what + ": EXT_meshopt_compression's '" + key + "' is " +
                             (found == object.end() ? std::string("missing") : found->dump()) + ", not a string");
    return found->get<std::string>();
}

}  // namespace

void decodeMeshoptView(const std::string& what, const nlohmann::json& extension, const unsigned char* source,
                       std::size_t sourceSize, unsigned char* destination, std::size_t destinationSize) {
    if (!extension.is_object()) throw SceneLoadError(what + ": EXT_meshopt_compression is not an object");
    const std::size_t byteOffset = unsignedField(what, extension, "byteOffset", 0);
    const std::size_t byteLength = unsignedField(what, extension, "byteLength", std::nullopt);
    const std::size_t stride = unsignedField(what, extension, "byteStride", std::nullopt);
    const std::size_t count = unsignedField(what, extension, "count", std::nullopt);
    const std::string mode = stringField(what, extension, "mode", nullptr);
    const std::string filter = stringField(what, extension, "filter", "NONE");

    if (byteOffset > sourceSize || byteLength > sourceSize - byteOffset)
        throw SceneLoadError(what + ": EXT_meshopt_compression's data (offset " + std::to_string(byteOffset) + ", " +
                             std::to_string(byteLength) + " bytes) lies outside its buffer (" +
                             std::to_string(sourceSize) + " bytes)");
    if (stride == 0 || count > destinationSize / stride)
        throw SceneLoadError(what + ": EXT_meshopt_compression decodes " + std::to_string(count) + " elements of " +
                             std::to_string(stride) + " bytes, more than the buffer view's " +
                             std::to_string(destinationSize) + " bytes");
    // The spec's limits, which are also libmeshoptimizer's preconditions (asserts, not errors).
    if (mode == "ATTRIBUTES") {
        if (stride % 4 != 0 || stride > 256)
            throw SceneLoadError(what + ": EXT_meshopt_compression ATTRIBUTES byteStride " + std::to_string(stride) +
                                 " is not a multiple of 4 up to 256");
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4)
            throw SceneLoadError(what + ": EXT_meshopt_compression " + mode + " byteStride " + std::to_string(stride) +
                                 " is not 2 or 4");
        if (mode == "TRIANGLES" && count % 3 != 0)
            throw SceneLoadError(what + ": EXT_meshopt_compression TRIANGLES count " + std::to_string(count) +
                                 " is not a multiple of 3");
        if (filter != "NONE")
            throw SceneLoadError(what + ": EXT_meshopt_compression filter " + filter +
                                 " is allowed only with mode ATTRIBUTES");
    } else {
        throw SceneLoadError(what + ": EXT_meshopt_compression mode '" + mode +
                             "' is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
        throw SceneLoadError(what + ": EXT_meshopt_compression filter OCTAHEDRAL needs byteStride 4 or 8, not " +
                             std::to_string(stride));
    if (filter == "QUATERNION" && stride != 8)
        throw SceneLoadError(what + ": EXT_meshopt_compression filter QUATERNION needs byteStride 8, not " +
                             std::to_string(stride));
    if (filter != "NONE" && filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL")
        throw SceneLoadError(what + ": EXT_meshopt_compression filter '" + filter +
                             "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
    if (count == 0) return;

    // The decoders read only inside [data, data + byteLength) and report malformed or truncated
    // input (libmeshoptimizer: "safe to use for untrusted input").
    const unsigned char* data = source + byteOffset;
    const int status = mode == "ATTRIBUTES" ? meshopt_decodeVertexBuffer(destination, count, stride, data, byteLength)
                       : mode == "TRIANGLES"
                           ? meshopt_decodeIndexBuffer(destination, count, stride, data, byteLength)
                           : meshopt_decodeIndexSequence(destination, count, stride, data, byteLength);
    if (status != 0)
        throw SceneLoadError(what + ": EXT_meshopt_compression " + mode + " data (" + std::to_string(byteLength) +
                             " bytes for " + std::to_string(count) +
                             " elements) does not decode (libmeshoptimizer error " + std::to_string(status) +
                             ": truncated, malformed or of an unknown version)");
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(destination, count, stride);
    if (filter == "QUATERNION") meshopt_decodeFilterQuat(destination, count, stride);
    if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(destination, count, stride);
}

}  // namespace lit::gltfimport
