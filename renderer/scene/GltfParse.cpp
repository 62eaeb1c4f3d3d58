// Parsing a glTF file with tinygltf. tinygltf parses the JSON/GLB container and loads buffers;
// everything it hands over is validated by the import before use (scene/GltfValidate.h), because
// tinygltf 2.7 checks little of it and a bad file must give a SceneLoadError, never a crash.

#include "scene/GltfParse.h"

#include "Log.h"
#include "io/GltfGuard.h"
#include "scene/GltfCompression.h"
#include "scene/GltfContainer.h"
#include "scene/GltfExtensions.h"
#include "scene/GltfKeep.h"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lit::gltfimport {

namespace {

// ---------------------------------------------------------------------------------------------
// tinygltf image callback: keep the encoded bytes; decoding happens later, in parallel, by stb.

struct ImageCallbackContext {
    const tinygltf::Model* model = nullptr;  // being filled by tinygltf (buffers are parsed first)
    std::vector<std::string> problems;       // images whose bytes could not be taken safely
    ImageDeduplicator images;                // the encoded bytes, each distinct image once
};

bool keepEncodedImage(tinygltf::Image* image, const int imageIndex, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    auto& context = *static_cast<ImageCallbackContext*>(user);
    // tinygltf 2.7 does not check that an image's buffer view lies inside its buffer before
    // handing us the pointer: check it here, before reading the bytes.
    if (image->bufferView >= 0 && context.model) {
        const auto& views = context.model->bufferViews;
        const auto& buffers = context.model->buffers;
        const auto view = static_cast<std::size_t>(image->bufferView);
        const bool inside =
            view < views.size() && views[view].buffer >= 0 &&
            static_cast<std::size_t>(views[view].buffer) < buffers.size() &&
            views[view].byteOffset <= buffers[static_cast<std::size_t>(views[view].buffer)].data.size() &&
            views[view].byteLength <=
                buffers[static_cast<std::size_t>(views[view].buffer)].data.size() - views[view].byteOffset;
        if (!inside) {
            context.problems.push_back("image " + std::to_string(imageIndex) + ": buffer view " +
                                       std::to_string(image->bufferView) + " lies outside its buffer");
            image->image.clear();
            image->as_is = true;
            return true;
        }
    }
    // Kept once per distinct content (io/GltfGuard.h); put into the model after parsing.
    context.images.add(imageIndex, bytes, bytes && size > 0 ? static_cast<std::size_t>(size) : 0);
    image->image.clear();
    image->as_is = true;  // encoded bytes, not pixels
    return true;
}

// Splits tinygltf's newline-separated messages.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

// What tinygltf 2.7 does not read, from the file's JSON: an animation sampler's "extensions" (tinygltf reads them
// from the animation object instead of the sampler, fixed in the model) and the extras and
// extensions of sparse accessors' parts (returned by accessor index).
SparseKept readWhatTinygltfSkips(tinygltf::Model& model, const nlohmann::json& doc) {
    SparseKept sparseKept;
    const bool sparse = std::any_of(model.accessors.begin(), model.accessors.end(),
                                    [](const tinygltf::Accessor& a) { return a.sparse.isSparse; });
    if (model.animations.empty() && !sparse) return sparseKept;
    if (sparse && doc.is_object() && doc.contains("accessors") && doc["accessors"].is_array()) {
        const nlohmann::json& accessors = doc["accessors"];
        for (std::size_t i = 0; i < accessors.size() && i < model.accessors.size(); ++i) {
            if (!model.accessors[i].sparse.isSparse || !accessors[i].is_object()) continue;
            const auto found = accessors[i].find("sparse");
            if (found == accessors[i].end() || !found->is_object()) continue;
            const auto part = [&](const char* key) {
                const auto p = found->find(key);
                return p == found->end() ? KeptGltf{} : gltfkeep::keepFromJson(*p);
            };
            std::array<KeptGltf, 3> kept{gltfkeep::keepFromJson(*found), part("indices"), part("values")};
            if (!(kept == std::array<KeptGltf, 3>{})) sparseKept[static_cast<int>(i)] = std::move(kept);
        }
    }
    const nlohmann::json* animations = doc.is_object() && doc.contains("animations") ? &doc["animations"] : nullptr;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const nlohmann::json* samplers = animations && animations->is_array() && a < animations->size() &&
                                                 (*animations)[a].is_object() && (*animations)[a].contains("samplers")
                                             ? &(*animations)[a]["samplers"]
                                             : nullptr;
        for (std::size_t i = 0; i < model.animations[a].samplers.size(); ++i) {
            tinygltf::ExtensionMap& extensions = model.animations[a].samplers[i].extensions;
            extensions.clear();
            if (!samplers || !samplers->is_array() || i >= samplers->size() || !(*samplers)[i].is_object()) continue;
            const auto found = (*samplers)[i].find("extensions");
            if (found == (*samplers)[i].end() || !found->is_object()) continue;
            for (auto it = found->begin(); it != found->end(); ++it)
                extensions[it.key()] = gltfkeep::toValue(it.value());
        }
    }
    return sparseKept;
}

}  // namespace

ParsedGltf parseGltf(const std::filesystem::path& path, Log& log, const GltfLoadOptions& options) {
    checkSceneFile(path, options.limits);
    const Container container = detectContainer(path);
    // Size, depth, version and URIs checked before tinygltf sees the file (io/GltfGuard.h).
    const GuardedScene guarded = guardGltfFile(path, container == Container::Binary, options.limits);
    GuardedFileSystem files(path, options.limits, guarded.externalImages, guarded.absoluteFiles);

    ParsedGltf parsed;
    // The JSON once more, for what tinygltf does not read or report (a few ms for Sponza's 0.3 MB),
    // first of all the extensions: one Lit lacks is named before tinygltf stumbles on its data.
    parsed.doc = nlohmann::json::parse(guarded.json.begin(), guarded.json.end(), nullptr, false);
    checkExtensions(path, parsed.doc, log);
    // Compressed geometry: the JSON rewritten for tinygltf, decoded after (scene/GltfCompression.h).
    const std::vector<unsigned char> rewritten = tinygltfInput(guarded, parsed.doc);
    tinygltf::Model& model = parsed.model;
    tinygltf::TinyGLTF parser;
    parser.SetFsCallbacks(files.callbacks());
    ImageCallbackContext imageContext;
    imageContext.model = &model;
    parser.SetImageLoader(&keepEncodedImage, &imageContext);
    std::string err, warn;
    bool ok = false;
    try {
        const std::string baseDir = path.parent_path().string();
        if (container == Container::Binary) {
            const std::vector<unsigned char>& bytes = rewritten.empty() ? guarded.bytes : rewritten;
            ok = parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                             baseDir);
        } else {
            const std::string_view json =
                rewritten.empty() ? guarded.json
                                  : std::string_view(reinterpret_cast<const char*>(rewritten.data()), rewritten.size());
            ok = parser.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                            baseDir);
        }
    } catch (const std::exception& e) {
        throw SceneLoadError(path.string() + ": tinygltf failed: " + e.what());
    }
    const std::string file = path.filename().string();
    for (const std::string& line : lines(warn)) log.warning(file + ": " + line);
    for (const std::string& problem : imageContext.problems) log.warning(file + ": " + problem);
    for (const std::string& refusal : files.refusals()) log.warning(file + ": not read: " + refusal);
    if (!ok) {
        std::string message =
            path.string() + ": " +
            (container == Container::Binary ? "cannot load the GLB file" : "cannot load the glTF file");
        std::vector<std::string> errors = lines(err);
        for (const std::string& refusal : files.refusals()) errors.push_back("not read: " + refusal);
        for (std::size_t i = 0; i < errors.size(); ++i) message += (i == 0 ? ": " : "; ") + errors[i];
        throw SceneLoadError(message);
    }
    for (std::size_t i = 0; i < model.images.size(); ++i)
        model.images[i].image = imageContext.images.take(static_cast<int>(i));
    parsed.compression = decodeCompressedGeometry(path, parsed.doc, options.limits, model);
    parsed.sparseKept = readWhatTinygltfSkips(model, parsed.doc);
    checkMemoryBudget(path, model, imageContext.images, options.limits);
    parsed.images = std::move(imageContext.images);
    return parsed;
}

}  // namespace lit::gltfimport
