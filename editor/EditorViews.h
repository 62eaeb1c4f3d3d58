#pragma once
// Every debug view the editor offers, in the order of the View menu, with its number-key
// shortcut: the renderer's views (RenderSettings.h View, by their script names) and the editor's
// own "cone-directions". Window-free (lit_editor_core): the menu, the shortcuts, the viewport
// label and the --help text read this one table.

#include <optional>
#include <string_view>
#include <vector>

#include "RenderSettings.h"

namespace lit::editor {

// The editor-only view name: the final image with the cones of a picked pixel drawn over it.
inline constexpr const char* kConeDirectionsView = "cone-directions";

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

// The name of the view on screen: "cone-directions" while that editor view is on, else the
// renderer's view.
std::string_view currentViewName(View view, bool coneDirections);

// The shadow map and the voxel slice are 2D images, not the camera's view: they fill the free
// viewport area, a click there picks nothing and no world-space overlay is drawn over them.
bool isFlatView(View view);

}  // namespace lit::editor
