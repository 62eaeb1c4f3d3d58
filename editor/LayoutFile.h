#pragma once
// Where the editor keeps its layout between runs, and the editor's own part of that file. The
// file is Dear ImGui's ini (window positions and sizes) with one more section, [Lit][Editor],
// holding which panels are shown (the overlay's details and the legend among them) and the window
// size the positions belong to. Window-free (lit_editor_core); ImGuiLayer reads and writes it.

#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "EditorState.h"

namespace lit::editor {

// Reads an environment variable (std::getenv in the editor, a table in the tests).
using EnvironmentLookup = std::function<const char*(const char*)>;

// The layout file: $LIT_EDITOR_LAYOUT when set ("" keeps none); else none for scripted runs
// (--script, --screenshot: their pictures must not depend on earlier sessions); else
// $XDG_CONFIG_HOME/lit/imgui.ini, or ~/.config/lit/imgui.ini; none without a home.
std::optional<std::filesystem::path> layoutFilePath(bool scripted, const EnvironmentLookup& environment);

// The [Lit][Editor] section's lines ("panel.log=1", "display=1280,720"), without the header.
std::string layoutSectionText(const PanelVisibility& panels, glm::vec2 display);
// One line of that section into `panels` and `display`; false for a line it does not know.
bool readLayoutLine(std::string_view line, PanelVisibility& panels, glm::vec2& display);

}  // namespace lit::editor
