// The glTF extensions Lit reads (scene/GltfExtensions.h).

#include "scene/GltfExtensions.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "Log.h"
#include "scene/GltfLoader.h"

namespace lit::gltfimport {

namespace {

// KTX2 textures (Basis Universal): Lit has no transcoder.
constexpr std::string_view kBasisu = "KHR_texture_basisu";
// WebP textures: decoded when Lit is built with libwebp (LIT_HAS_WEBP).
constexpr std::string_view kWebp = "EXT_texture_webp";

// The names in the file's top-level array `key`, once each, in file order (non-strings skipped).
std::vector<std::string> namesIn(const nlohmann::json& doc, const char* key) {
    std::vector<std::string> names;
    const auto found = doc.find(key);
    if (found == doc.end() || !found->is_array()) return names;
    for (const nlohmann::json& name : *found)
        if (name.is_string() && std::find(names.begin(), names.end(), name.get<std::string>()) == names.end())
            names.push_back(name.get<std::string>());
    return names;
}

// Textures whose only image is the KTX2 one (no `source`): drawn without their image.
std::size_t texturesWithoutFallback(const nlohmann::json& doc) {
    const auto textures = doc.find("textures");
    if (textures == doc.end() || !textures->is_array()) return 0;
    return static_cast<std::size_t>(std::count_if(textures->begin(), textures->end(), [](const nlohmann::json& t) {
        return t.is_object() && !t.contains("source") && t.contains("extensions") && t["extensions"].is_object() &&
               t["extensions"].contains(kBasisu);
    }));
}

}  // namespace

bool isSupportedExtension(std::string_view name) {
    // KHR_mesh_quantization only widens the accessor types allowed for attributes, which the
    // generic accessor reader handles; the compressed geometry is decoded before the import
    // (scene/GltfCompression.h).
    static constexpr std::array<std::string_view, 12> supported = {
        "KHR_lights_punctual",     "KHR_materials_emissive_strength", "KHR_mesh_quantization",
        "EXT_meshopt_compression", "KHR_draco_mesh_compression",      "KHR_texture_transform",
        "KHR_materials_ior",       "KHR_materials_specular",          "KHR_materials_clearcoat",
        "KHR_materials_sheen",     "KHR_materials_transmission",      "KHR_materials_volume"};
    if (name == kWebp) return LIT_HAS_WEBP != 0;
    return std::find(supported.begin(), supported.end(), name) != supported.end();
}

void checkExtensions(const std::filesystem::path& path, const nlohmann::json& doc, Log& log) {
    if (!doc.is_object()) return;
    const std::vector<std::string> required = namesIn(doc, "extensionsRequired");
    std::vector<std::string> missing;
    for (const std::string& name : required)
        if (!isSupportedExtension(name)) missing.push_back(name);
    if (!missing.empty()) {
        std::string names;
        for (std::size_t i = 0; i < missing.size(); ++i)
            names += (i == 0 ? "" : i + 1 == missing.size() ? " and " : ", ") + missing[i];
        std::string message = path.string() + ": requires " + names + ", which Lit does not support";
        if (std::find(missing.begin(), missing.end(), kBasisu) != missing.end())
            message += " (KHR_texture_basisu: KTX2 textures, which Lit does not decode)";
        if (std::find(missing.begin(), missing.end(), kWebp) != missing.end())
            message += " (EXT_texture_webp: WebP textures; this build of Lit has no libwebp, configure with "
                       "-DLIT_WEBP=ON)";
        throw SceneLoadError(message);
    }
    const std::string file = path.filename().string();
    for (const std::string& name : namesIn(doc, "extensionsUsed")) {
        if (isSupportedExtension(name)) continue;
        if (name == kBasisu) {
            const std::size_t bare = texturesWithoutFallback(doc);
            log.warning(file +
                        ": uses KHR_texture_basisu (KTX2 textures), which Lit does not decode; textures use "
                        "their other source" +
                        (bare == 0 ? std::string()
                                   : " (" + std::to_string(bare) + (bare == 1 ? " texture has" : " textures have") +
                                         " none and " + (bare == 1 ? "is" : "are") + " drawn without it)"));
            continue;
        }
        if (name == kWebp) {
            log.warning(file +
                        ": uses EXT_texture_webp (WebP textures), which this build of Lit does not decode (no "
                        "libwebp); textures use their fallback source, or white where they have none");
            continue;
        }
        log.warning(file + ": uses " + name +
                    ", which Lit does not support; it is ignored (its data is kept and saved back as it was)");
    }
}

}  // namespace lit::gltfimport
