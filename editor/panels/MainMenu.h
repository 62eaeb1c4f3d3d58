#pragma once
// The main menu bar: File (Open… with a path field and recent files, Save, Save As…, the two
// screenshots, Quit), Edit (Undo / Redo with the step's name, Duplicate, Delete), Add (empty,
// lights, camera, primitives) and View (every debug view with its number key, frame selected,
// panel toggles). It
// returns what the user asked for; the App carries it out, asking about unsaved changes first.

#include <filesystem>
#include <optional>
#include <string>

#include "EditorState.h"
#include "RecentFiles.h"
#include "SceneEdits.h"

namespace lit::editor {

// What the menu shows besides the panel flags.
struct MenuContext {
    const RecentFiles& recent;
    std::filesystem::path currentScene;  // pre-fills the Open path field
    std::filesystem::path documentFile;  // the document's file (empty: none), for Save As's suggestion
    std::string undoLabel;               // "" = nothing to undo
    std::string redoLabel;
    std::string currentView;  // EditorViews.h name, ticked in the View menu
    bool hasSelection = false;
};

struct MenuRequests {
    std::optional<std::filesystem::path> open;    // scene to load
    bool save = false;                            // save to the current file (Save As when none)
    std::optional<std::filesystem::path> saveAs;  // save to this file
    bool saveAsCancelled = false;                 // the Save As dialog was closed without saving
    bool screenshot = false;                      // the viewport alone, to screenshots/
    bool screenshotWithUi = false;                // the whole window
    bool undo = false;
    bool redo = false;
    bool quit = false;
    std::optional<NodeKind> add;      // Add menu: a new node of this kind
    bool deleteSelection = false;     // Edit > Delete
    bool duplicateSelection = false;  // Edit > Duplicate
    bool frameSelection = false;      // View > Frame selected
    std::optional<std::string> view;  // View > a debug view (EditorViews.h name)
};

class MainMenu {
public:
    // Returns the menu bar's height through `height` (screen coordinates) so panels can be laid
    // out below it.
    MenuRequests draw(PanelVisibility& visible, const MenuContext& context, float& height);
    // Opens the Save As dialog (for Save on a document that has no file yet).
    void askSaveAs(const std::filesystem::path& suggestion);

private:
    void drawOpenPopup(const RecentFiles& recent, MenuRequests& requests);
    void drawSaveAsPopup(MenuRequests& requests);

    std::string pathInput_;       // the Open dialog's text field
    bool openRequested_ = false;  // File > Open… was chosen this frame
    std::string saveAsInput_;     // the Save As dialog's text field
    bool saveAsRequested_ = false;
};

}  // namespace lit::editor
