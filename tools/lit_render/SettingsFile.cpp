#include "SettingsFile.h"

#include <shared.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>
#include <vector>

#include "Log.h"

namespace lit::cli {

namespace fs = std::filesystem;

namespace {

// Settings files are small; anything larger than this is not one (a wrong path, a video).
constexpr std::uintmax_t kMaxSettingsBytes = 1 << 20;

std::string readTextFile(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw UsageError("cannot read settings " + path.string() + ": no such file");
    if (!fs::is_regular_file(status))
        throw UsageError("cannot read settings " + path.string() + ": not a regular file");
    if (fs::file_size(path, ec) > kMaxSettingsBytes)
        throw UsageError("cannot read settings " + path.string() + ": larger than 1 MiB, not a settings file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UsageError("cannot read settings " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The keys of a settings file that lit-render does not read: older keys (read, with their
// deprecation messages) and unknown ones (ignored: a typo, or a file from a newer version).
void warnAboutKeys(const std::string& name, const std::string& text, Log& log) {
    const nlohmann::json given = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const nlohmann::json known = nlohmann::json::parse(lit::toJson(lit::RenderSettings{}));
    // An older flat key is read (with its deprecation message); anything else unknown is a typo.
    std::vector<std::string> deprecated;
    lit::renderSettingsFromJson(text, {}, &deprecated);
    for (const std::string& message : deprecated) log.warning(name + ": " + message);
    if (given.is_object())
        for (const auto& [key, value] : given.items()) {
            const bool old = std::any_of(deprecated.begin(), deprecated.end(), [&key](const std::string& message) {
                return message.find("'" + key + "'") != std::string::npos;
            });
            if (old) continue;
            if (!known.contains(key)) {
                log.warning(name + ": unknown setting '" + key + "' ignored");
            } else if (value.is_object()) {
                for (const auto& [field, fieldValue] : value.items())
                    if (!known[key].contains(field))
                        log.warning(name + ": unknown setting '" + key + "." + field + "' ignored");
            }
        }
}

}  // namespace

RenderSettings loadSettingsFile(const fs::path& path, Log& log) {
    const std::string text = readTextFile(path);
    RenderSettings settings;
    try {
        settings = renderSettingsFromJson(text);
    } catch (const std::exception& e) {
        throw UsageError("cannot use settings " + path.string() + ": " + e.what());
    }
    warnAboutKeys(path.filename().string(), text, log);
    checkRenderableSettings(settings, "settings " + path.string(), path.filename().string(), log);
    return settings;
}

void checkRenderableSettings(RenderSettings& settings, const std::string& errorSource, const std::string& warningSource,
                             Log& log) {
    const auto requireRange = [&](const char* key, int value, int lo, int hi) {
        if (value < lo || value > hi)
            throw UsageError(errorSource + ": " + key + " is " + std::to_string(value) + ", expected " +
                             std::to_string(lo) + ".." + std::to_string(hi));
    };
    requireRange("output.width", settings.output.width, 1, kMaxImageSide);
    requireRange("output.height", settings.output.height, 1, kMaxImageSide);
    requireRange("gi.voxelResolution", settings.gi.voxelResolution, 64, 512);
    if ((settings.gi.voxelResolution & (settings.gi.voxelResolution - 1)) != 0)
        throw UsageError(errorSource + ": gi.voxelResolution is " + std::to_string(settings.gi.voxelResolution) +
                         ", expected a power of two (64, 128, 256 or 512)");
    requireRange("shadows.mapSize", settings.shadows.mapSize, 16, kMaxImageSide);
    const auto clampWarn = [&](const char* key, auto& value, auto lo, auto hi) {
        using T = std::decay_t<decltype(value)>;
        const T clamped = std::clamp(value, static_cast<T>(lo), static_cast<T>(hi));
        if (!(clamped == value)) {  // also catches NaN, which compares unequal
            std::ostringstream line;
            line << warningSource << ": " << key << " " << value << " is outside " << lo << ".." << hi << "; using "
                 << clamped;
            log.warning(line.str());
            value = clamped;
        }
    };
    clampWarn("indirect.specularSamples", settings.indirect.specularSamples, 1, 8);
    clampWarn("debug.voxelSliceAxis", settings.debug.voxelSliceAxis, 0, 2);
    clampWarn("debug.voxelSlice", settings.debug.voxelSlice, 0.0f, 1.0f);
    clampWarn("output.exposureEv", settings.output.exposureEv, -10.0f, 20.0f);
    clampWarn("gi.coneStepScale", settings.gi.coneStepScale, 0.05f, 4.0f);
    clampWarn("gi.maxTraceDistance", settings.gi.maxTraceDistance, 0.0f, 2.0f);
    clampWarn("shadows.cascades", settings.shadows.cascades, 0, LIT_MAX_SHADOW_CASCADES);
    clampWarn("shadows.cascadeDistance", settings.shadows.cascadeDistance, 0.0f, 1e5f);
    clampWarn("shadows.cascadeSplit", settings.shadows.cascadeSplit, 0.0f, 1.0f);
}

}  // namespace lit::cli
