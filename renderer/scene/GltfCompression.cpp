// Compressed glTF geometry around tinygltf (scene/GltfCompression.h).

#include "scene/GltfCompression.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "io/LittleEndian.h"
#include "scene/GltfDraco.h"
#include "scene/GltfLoader.h"
#include "scene/GltfMeshopt.h"

namespace lit::gltfimport {

namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";
constexpr const char* kDraco = "KHR_draco_mesh_compression";
// What a fallback buffer holds for tinygltf: 3 zero bytes (tinygltf 2.7 refuses an empty data
// URI and, in a GLB, reads a buffer without a URI from the BIN chunk).
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AAAA";
constexpr std::uint64_t kPlaceholderBytes = 3;

bool declares(const nlohmann::json& doc, const char* name) {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        const auto list = doc.find(key);
        if (list != doc.end() && list->is_array() && std::find(list->begin(), list->end(), name) != list->end())
            return true;
    }
    return false;
}

// object.extensions[name], or null when absent.
const nlohmann::json* extensionOf(const nlohmann::json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) return nullptr;
    const auto found = extensions->find(name);
    return found == extensions->end() ? nullptr : &*found;
}

// A buffer that only stands for meshopt's decoded data (EXT_meshopt_compression.fallback).
bool isFallbackBuffer(const nlohmann::json& buffer) {
    const nlohmann::json* meshopt = extensionOf(buffer, kMeshopt);
    return meshopt && meshopt->is_object() && meshopt->value("fallback", false) == true;
}

// The file's top-level array `key` (an empty one when absent or not an array).
const nlohmann::json& arrayOf(const nlohmann::json& doc, const char* key) {
    static const nlohmann::json empty = nlohmann::json::array();
    const auto found = doc.find(key);
    return found != doc.end() && found->is_array() ? *found : empty;
}

}  // namespace

std::vector<std::string> compressionExtensions(const nlohmann::json& doc) {
    std::vector<std::string> names;
    if (!doc.is_object()) return names;
    for (const char* name : {kMeshopt, kDraco})
        if (declares(doc, name)) names.emplace_back(name);
    return names;
}

std::vector<unsigned char> tinygltfInput(const GuardedScene& guarded, const nlohmann::json& doc) {
    if (compressionExtensions(doc).empty()) return {};
    nlohmann::json rewritten = doc;
    bool changed = false;
    if (auto buffers = rewritten.find("buffers"); buffers != rewritten.end() && buffers->is_array())
        for (nlohmann::json& buffer : *buffers)
            if (isFallbackBuffer(buffer)) {
                buffer["uri"] = kPlaceholderUri;
                buffer["byteLength"] = kPlaceholderBytes;
                changed = true;
            }
    if (auto meshes = rewritten.find("meshes"); meshes != rewritten.end() && meshes->is_array())
        for (nlohmann::json& mesh : *meshes) {
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (nlohmann::json& primitive : mesh["primitives"])
                if (extensionOf(primitive, kDraco) && primitive.contains("indices")) {
                    primitive.erase("indices");  // restored by decodeCompressedGeometry
                    changed = true;
                }
        }
    if (!changed) return {};
    std::string text = rewritten.dump();
    if (!guarded.binary) return std::vector<unsigned char>(text.begin(), text.end());

    // A GLB: the header and JSON chunk anew, the chunks after the JSON chunk as they were (the
    // guard checked the header's lengths against the file).
    const std::vector<unsigned char>& bytes = guarded.bytes;
    const std::size_t declared = std::min<std::size_t>(readLittleEndian32(bytes.data() + 8), bytes.size());
    const std::size_t afterJson =
        std::min<std::size_t>(20 + std::size_t(readLittleEndian32(bytes.data() + 12)), declared);
    text.resize((text.size() + 3) & ~std::size_t(3), ' ');  // chunks are 4-byte aligned; JSON pads with spaces
    std::vector<unsigned char> out(20 + text.size());
    std::memcpy(out.data(), bytes.data(), 12);
    writeLittleEndian32(out.data() + 12, static_cast<std::uint32_t>(text.size()));
    std::memcpy(out.data() + 16, "JSON", 4);
    std::memcpy(out.data() + 20, text.data(), text.size());
    out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(afterJson),
               bytes.begin() + static_cast<std::ptrdiff_t>(declared));
    writeLittleEndian32(out.data() + 8, static_cast<std::uint32_t>(out.size()));
    return out;
}

std::vector<std::string> decodeCompressedGeometry(const std::filesystem::path& path, const nlohmann::json& doc,
                                                  const GltfLimits& limits, tinygltf::Model& model) {
    const std::vector<std::string> names = compressionExtensions(doc);
    if (names.empty()) return names;
    const std::string file = path.string();
    const auto fail = [&](const std::string& problem) { throw SceneLoadError(file + ": " + problem); };

    // EXT_meshopt_compression: fallback buffers get their declared size, then every compressed
    // buffer view is decoded into its place in them.
    const nlohmann::json& buffers = arrayOf(doc, "buffers");
    std::vector<char> fallback(model.buffers.size(), 0);
    std::uint64_t decodedBytes = 0;
    for (std::size_t b = 0; b < buffers.size() && b < model.buffers.size(); ++b) {
        if (!isFallbackBuffer(buffers[b])) continue;
        const auto length = buffers[b].find("byteLength");
        if (length == buffers[b].end() || !length->is_number_unsigned())
            fail("buffer " + std::to_string(b) + " (an EXT_meshopt_compression fallback) has no valid byteLength");
        const std::uint64_t bytes = length->get<std::uint64_t>();
        decodedBytes += std::min(bytes, limits.memoryBudgetBytes + 1);
        if (decodedBytes > limits.memoryBudgetBytes)
            fail("the EXT_meshopt_compression fallback buffers declare more bytes than the memory budget (" +
                 std::to_string(limits.memoryBudgetBytes) + " bytes)");
        model.buffers[b].data.assign(static_cast<std::size_t>(bytes), 0);
        fallback[b] = 1;
    }
    const nlohmann::json& views = arrayOf(doc, "bufferViews");
    std::vector<unsigned char> scratch;
    for (std::size_t v = 0; v < views.size() && v < model.bufferViews.size(); ++v) {
        const nlohmann::json* meshopt = extensionOf(views[v], kMeshopt);
        if (!meshopt) continue;
        const std::string what = file + ": buffer view " + std::to_string(v);
        tinygltf::BufferView& view = model.bufferViews[v];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
            throw SceneLoadError(what + " names buffer " + std::to_string(view.buffer) + ", which does not exist");
        std::vector<unsigned char>& target = model.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > target.size() || view.byteLength > target.size() - view.byteOffset)
            throw SceneLoadError(what + " (offset " + std::to_string(view.byteOffset) + ", " +
                                 std::to_string(view.byteLength) + " bytes) lies outside buffer " +
                                 std::to_string(view.buffer) + " (" + std::to_string(target.size()) + " bytes)");
        const auto sourceIndex = meshopt->is_object() ? meshopt->find("buffer") : meshopt->end();
        if (!meshopt->is_object() || sourceIndex == meshopt->end() || !sourceIndex->is_number_unsigned() ||
            sourceIndex->get<std::uint64_t>() >= model.buffers.size())
            throw SceneLoadError(what + ": EXT_meshopt_compression names no buffer that exists (the file has " +
                                 std::to_string(model.buffers.size()) + ")");
        const auto source = static_cast<std::size_t>(sourceIndex->get<std::uint64_t>());
        if (fallback[source])
            throw SceneLoadError(what + ": EXT_meshopt_compression reads buffer " + std::to_string(source) +
                                 ", a fallback buffer that holds no data");
        // Decoded aside, then copied: the source and the target may be the same buffer.
        scratch.assign(view.byteLength, 0);
        const std::vector<unsigned char>& compressed = model.buffers[source].data;
        decodeMeshoptView(what, *meshopt, compressed.data(), compressed.size(), scratch.data(), scratch.size());
        std::copy(scratch.begin(), scratch.end(), target.begin() + static_cast<std::ptrdiff_t>(view.byteOffset));
        view.extensions.erase(kMeshopt);
    }
    for (tinygltf::Buffer& buffer : model.buffers) buffer.extensions.erase(kMeshopt);

    // KHR_draco_mesh_compression: every Draco primitive decoded into one new buffer.
    const nlohmann::json& meshes = arrayOf(doc, "meshes");
    int decoded = -1;
    for (std::size_t m = 0; m < meshes.size() && m < model.meshes.size(); ++m) {
        if (!meshes[m].is_object() || !meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array())
            continue;
        const nlohmann::json& primitives = meshes[m]["primitives"];
        for (std::size_t p = 0; p < primitives.size() && p < model.meshes[m].primitives.size(); ++p) {
            const nlohmann::json* draco = extensionOf(primitives[p], kDraco);
            if (!draco) continue;
            const std::string& name = model.meshes[m].name;
            const std::string what = file + ": mesh " + std::to_string(m) + (name.empty() ? "" : " ('" + name + "')") +
                                     " primitive " + std::to_string(p);
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            // The indices tinygltfInput took away from tinygltf.
            const auto indices = primitives[p].find("indices");
            primitive.indices =
                indices != primitives[p].end() && indices->is_number_unsigned() &&
                        indices->get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                    ? static_cast<int>(indices->get<std::uint64_t>())
                    : -1;
            if (decoded < 0) {
                model.buffers.emplace_back();
                decoded = static_cast<int>(model.buffers.size() - 1);
            }
            decodeDracoPrimitive(what, *draco, primitive, model, decoded);
            if (decodedBytes + model.buffers[static_cast<std::size_t>(decoded)].data.size() > limits.memoryBudgetBytes)
                throw SceneLoadError(what + ": the decoded Draco geometry exceeds the memory budget (" +
                                     std::to_string(limits.memoryBudgetBytes) + " bytes)");
            primitive.extensions.erase(kDraco);
        }
    }

    // From here on the model reads as an uncompressed file.
    for (std::vector<std::string>* list : {&model.extensionsUsed, &model.extensionsRequired})
        list->erase(std::remove_if(
                        list->begin(), list->end(),
                        [&](const std::string& e) { return std::find(names.begin(), names.end(), e) != names.end(); }),
                    list->end());
    return names;
}

}  // namespace lit::gltfimport
