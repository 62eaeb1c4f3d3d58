#pragma once
// What Escape does in the editor's main window. A menu, combo or right-click menu takes it
// first: Escape closes that and nothing else (Dear ImGui 1.86 without keyboard navigation
// leaves them open, and a press meant to close a menu must not also drop the selection). With
// nothing open it clears the selection, as in Blender's Alt+A and Unity's Escape-free click on
// empty space. Modal dialogs handle Escape themselves (Cancel): the shortcuts do not run then.

namespace lit::editor {

enum class EscapeAction { ClosePopups, ClearSelection };

constexpr EscapeAction escapeAction(bool popupOpen) {
    return popupOpen ? EscapeAction::ClosePopups : EscapeAction::ClearSelection;
}

}  // namespace lit::editor
