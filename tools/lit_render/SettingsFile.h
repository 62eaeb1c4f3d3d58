#pragma once
// lit-render's render settings from outside the flags: a --settings file, and the check that the
// settings from a file or from --set can be rendered.

#include <filesystem>
#include <string>

#include "Options.h"

namespace lit {
class Log;
}

namespace lit::cli {

// Reads a RenderSettings JSON file (as the editor saves it). Keys it does not know, older keys
// (with their deprecation messages) and values it clamps are warnings; a file that cannot be read
// or parsed, and sizes it cannot render, are UsageErrors (exit 2).
RenderSettings loadSettingsFile(const std::filesystem::path& path, Log& log);

// The values lit-render can render: sizes out of range are UsageErrors starting with `errorSource`
// ("settings FILE", "--set"); values it clamps are warnings starting with `warningSource`.
void checkRenderableSettings(RenderSettings& settings, const std::string& errorSource, const std::string& warningSource,
                             Log& log);

}  // namespace lit::cli
