#pragma once
// Every debug view the editor offers, in the order of the View menu, with its number-key
// shortcut: the renderer's views (RenderSettings.h View, by their script names) and the editor's
// own "cone-directions". Window-free (lit_editor_core): the menu, the shortcuts, the viewport
// label and the --help text read this one table.

#include <optional>
#include <string_view>
#include <vector>

namespace lit::editor {

struct EditorView {
    std::string_view name;   // script / settings name: "final", "voxel-slice", "cone-directions"
    std::string_view label;  // menu and viewport label: "Final image", "Voxel slice"
    int digit;               // number key 0..9
    bool shift;              // with Shift (the views past the tenth)
    std::string_view shortcut;  // as the menu shows it: "1", "Shift+1"
};

const std::vector<EditorView>& editorViews();
// The entry named `name`, or nullptr.
const EditorView* findEditorView(std::string_view name);
// The entry for number key `digit` (0..9) with or without Shift, or nullptr.
const EditorView* editorViewForKey(int digit, bool shift);

}  // namespace lit::editor
