#include "SettingCommand.h"

#include <array>
#include <bit>
#include <exception>
#include <utility>

#include "TextParse.h"

namespace lit::editor {

std::string applySetting(RenderSettings& settings, std::string_view key, std::string_view value,
                         std::vector<std::string>* warnings) {
    const std::string name(key);
    if (name == "output.width" || name == "output.height" || name == "width" || name == "height")
        return "setting " + name + ": the editor sizes its render from the window (use --size WxH)";
    RenderSettings updated = settings;
    try {
        setRenderSetting(updated, key, value, warnings);
    } catch (const std::exception& error) {
        const std::string message = error.what();
        // An unknown key is wrong whatever its value; a bad value is shown.
        return message.starts_with("unknown") ? message : message + " (got '" + std::string(value) + "')";
    }
    // The one range the JSON types cannot express and the renderer relies on.
    if (updated.gi.voxelResolution != settings.gi.voxelResolution &&
        (updated.gi.voxelResolution < 64 || updated.gi.voxelResolution > 512 ||
         !std::has_single_bit(static_cast<unsigned>(updated.gi.voxelResolution))))
        return "setting gi.voxelResolution: " + std::to_string(updated.gi.voxelResolution) +
               " is not a power of two in 64..512";
    settings = updated;
    return "";
}

std::optional<std::string> applyEditorSetting(ViewportSettings& viewport, std::string_view key, std::string_view value,
                                              std::vector<std::string>* warnings) {
    // The editor's own keys, and the render-settings keys they had before they moved here.
    constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kOldKeys{{
        {"interactiveFpsTarget", "editor.interactiveFpsTarget"},
        {"voxelIrradianceVoxelsPerFrame", "editor.giUpdateVoxelsPerFrame"},
        {"voxelIrradianceRefineVoxelsPerFrame", "editor.giRefineVoxelsPerFrame"},
    }};
    std::string name(key);
    for (const auto& [old, now] : kOldKeys)
        if (key == old) {
            name = now;
            if (warnings)
                warnings->push_back("setting '" + std::string(old) + "' is deprecated; it is " + std::string(now));
        }
    if (name == "editor.interactiveFpsTarget") {
        const std::optional<float> fps = parseNumber<float>(std::string(value));
        if (!fps || *fps < 0.0f)
            return "setting " + name + ": expected frames per second from 0 (got '" + std::string(value) + "')";
        viewport.interactiveFpsTarget = *fps;
        return "";
    }
    if (name == "editor.giMillisecondsPerFrame" || name == "editor.giIdleMillisecondsPerFrame") {
        const std::optional<float> ms = parseNumber<float>(std::string(value));
        if (!ms || !(*ms >= 0.0f))
            return "setting " + name + ": expected milliseconds from 0 (got '" + std::string(value) + "')";
        (name == "editor.giMillisecondsPerFrame" ? viewport.giMillisecondsPerFrame
                                                 : viewport.giIdleMillisecondsPerFrame) = *ms;
        return "";
    }
    if (name == "editor.redrawOnDemand") {
        if (value != "true" && value != "false")
            return "setting " + name + ": expected true or false (got '" + std::string(value) + "')";
        viewport.redrawOnDemand = value == "true";
        return "";
    }
    int* count = name == "editor.giUpdateVoxelsPerFrame"   ? &viewport.giUpdateVoxelsPerFrame
                 : name == "editor.giRefineVoxelsPerFrame" ? &viewport.giRefineVoxelsPerFrame
                                                           : nullptr;
    if (!count) return std::nullopt;
    const std::optional<int> voxels = parseNumber<int>(std::string(value));
    if (!voxels || *voxels < 0)
        return "setting " + name + ": expected a voxel count from 0 (got '" + std::string(value) + "')";
    *count = *voxels;
    return "";
}

}  // namespace lit::editor
