#include "SettingCommand.h"

#include <nlohmann/json.hpp>

#include <bit>
#include <exception>
#include <optional>

namespace lit::editor {

std::string applySetting(RenderSettings& settings, std::string_view key, std::string_view value) {
    const std::string name(key);
    if (name == "width" || name == "height")
        return "setting " + name + ": the editor sizes its render from the window (use --size WxH)";
    // The GI preset is not a field of its own: it names values of anisotropicVoxels,
    // coneFootprintPerHeight and diffuseFromVoxelIrradiance (RenderSettings.h, GiMode).
    if (name == "giMode") {
        const std::optional<GiMode> mode = parseGiMode(value);
        if (!mode) return "setting giMode: expected fast, accurate or cached (got '" + std::string(value) + "')";
        setGiMode(settings, *mode);
        return "";
    }
    // renderSettingsFromJson ignores unknown keys (files from newer versions still load); a
    // script naming one has a typo, so check against the keys toJson writes.
    const nlohmann::json known = nlohmann::json::parse(toJson(settings));
    // `exposure` (linear) is the pre-stops key that renderSettingsFromJson still reads.
    if (!known.contains(name) && name != "exposure") return "unknown render setting '" + name + "'";

    nlohmann::json parsed = nlohmann::json::parse(value, nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded() || parsed.is_object()) parsed = std::string(value);
    const nlohmann::json object = {{name, parsed}};
    RenderSettings updated;
    try {
        updated = renderSettingsFromJson(object.dump(), settings);
    } catch (const std::exception& error) {
        return std::string(error.what()) + " (got '" + std::string(value) + "')";
    }
    // The one range the JSON types cannot express and the renderer relies on.
    if (updated.voxelResolution != settings.voxelResolution &&
        (updated.voxelResolution < 64 || updated.voxelResolution > 512 ||
         !std::has_single_bit(static_cast<unsigned>(updated.voxelResolution))))
        return "setting voxelResolution: " + std::to_string(updated.voxelResolution) +
               " is not a power of two in 64..512";
    settings = updated;
    return "";
}

}  // namespace lit::editor
