#include "LayoutFile.h"

#include <cstdio>

#include "TextParse.h"

namespace lit::editor {

namespace fs = std::filesystem;

std::optional<fs::path> layoutFilePath(bool scripted, const EnvironmentLookup& environment) {
    if (const char* file = environment("LIT_EDITOR_LAYOUT"); file != nullptr) {
        if (*file == '\0') return std::nullopt;
        return fs::path(file);
    }
    if (scripted) return std::nullopt;
    // XDG Base Directory: a relative XDG_CONFIG_HOME is invalid and ignored.
    if (const char* config = environment("XDG_CONFIG_HOME"); config != nullptr && fs::path(config).is_absolute())
        return fs::path(config) / "lit" / "imgui.ini";
    if (const char* home = environment("HOME"); home != nullptr && *home != '\0')
        return fs::path(home) / ".config" / "lit" / "imgui.ini";
    return std::nullopt;
}

std::string layoutSectionText(const PanelVisibility& panels, glm::vec2 display) {
    std::string text;
    PanelVisibility copy = panels;
    for (const char* name : kPanelNames)
        text += std::string("panel.") + name + "=" + (*panelFlag(copy, name) ? "1" : "0") + "\n";
    char size[64];
    std::snprintf(size, sizeof size, "display=%.0f,%.0f\n", static_cast<double>(display.x),
                  static_cast<double>(display.y));
    return text + size;
}

bool readLayoutLine(std::string_view line, PanelVisibility& panels, glm::vec2& display) {
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos) return false;
    const std::string_view key = trim(line.substr(0, equals));
    const std::string_view value = trim(line.substr(equals + 1));
    if (key.starts_with("panel.")) {
        bool* flag = panelFlag(panels, key.substr(6));
        if (flag == nullptr || (value != "0" && value != "1")) return false;
        *flag = value == "1";
        return true;
    }
    if (key == "display") {
        const std::size_t comma = value.find(',');
        if (comma == std::string_view::npos) return false;
        const auto width = parseNumber<float>(std::string(trim(value.substr(0, comma))));
        const auto height = parseNumber<float>(std::string(trim(value.substr(comma + 1))));
        if (!width || !height) return false;
        display = {*width, *height};
        return true;
    }
    return false;
}

}  // namespace lit::editor
