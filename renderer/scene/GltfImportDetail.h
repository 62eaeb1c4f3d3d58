#pragma once
// Internal to the glTF import (scene/GltfLoader.cpp and the steps it runs: GltfParse, GltfValidate,
// GltfImport, GltfImportImages, GltfImportKept): the parsed file, and the source every import
// step reads it through. Nothing here is part of Lit's API.

#include "Log.h"
#include "io/GltfGuard.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lit::gltfimport {

// By accessor index, the extras and extensions of its `sparse`, `sparse.indices` and
// `sparse.values` objects, which tinygltf 2.7 does not read (scene/GltfParse.cpp).
using SparseKept = std::map<int, std::array<KeptGltf, 3>>;

// A file as parsed, before anything is imported.
struct ParsedGltf {
    tinygltf::Model model;     // images hold their encoded bytes (decoded by the import)
    ImageDeduplicator images;  // which images are byte-identical to an earlier one
    SparseKept sparseKept;
    // The file's JSON (null when it does not parse as JSON here), for what tinygltf does not
    // tell: which optional fields the file wrote (materials, samplers, images).
    nlohmann::json doc;
    // The compression extensions whose data was decoded into `model` (scene/GltfCompression.h).
    std::vector<std::string> compression;
};

// The file being imported and where its messages and progress go. Every import step reads it;
// none changes it.
struct GltfSource {
    const std::filesystem::path& path;
    const tinygltf::Model& model;
    const ImageDeduplicator& images;
    const SparseKept& sparseKept;
    const nlohmann::json& doc;
    const std::vector<std::string>& compression;
    Log& log;
    const GltfLoadOptions& options;

    [[noreturn]] void fail(const std::string& problem) const { throw SceneLoadError(path.string() + ": " + problem); }
    void warn(const std::string& problem) const { log.warning(path.filename().string() + ": " + problem); }
    void report(const char* stage, std::size_t done, std::size_t total) const {
        if (options.progress) options.progress({stage, static_cast<int>(done), static_cast<int>(total)});
    }
    // The file's JSON object `index` of the top-level array `array` (null when absent).
    const nlohmann::json& fileObject(const char* array, std::size_t index) const {
        static const nlohmann::json none;
        if (!doc.is_object()) return none;
        const auto found = doc.find(array);
        if (found == doc.end() || !found->is_array() || index >= found->size() || !(*found)[index].is_object())
            return none;
        return (*found)[index];
    }
};

}  // namespace lit::gltfimport
