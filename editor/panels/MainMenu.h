#pragma once
// The main menu bar: File (Open… with a path field, recent files, Quit) and View (panel
// toggles). It returns what the user asked for; the App carries it out.

#include <filesystem>
#include <optional>
#include <string>

#include "EditorState.h"
#include "RecentFiles.h"

namespace lit::editor {

struct MenuRequests {
    std::optional<std::filesystem::path> open;  // scene to load
    bool quit = false;
};

class MainMenu {
public:
    // `currentScene` pre-fills the Open dialog's path field. Returns the menu bar's height
    // through `height` (screen coordinates) so panels can be laid out below it.
    MenuRequests draw(PanelVisibility& visible, const RecentFiles& recent, const std::filesystem::path& currentScene,
                      float& height);

private:
    void drawOpenPopup(const RecentFiles& recent, MenuRequests& requests);

    std::string pathInput_;       // the Open dialog's text field
    bool openRequested_ = false;  // File > Open… was chosen this frame
};

}  // namespace lit::editor
