#include "EditorViews.h"

namespace lit::editor {

const std::vector<EditorView>& editorViews() {
    // The lighting terms first in the order of the sum (docs/GI.md), then the G-buffer, then the
    // light and voxel data.
    static const std::vector<EditorView> views{
        {"final", "Final image", 1, false, "1"},
        {"direct-diffuse", "Direct diffuse (L_DD)", 2, false, "2"},
        {"direct-specular", "Direct specular (L_DS)", 3, false, "3"},
        {"indirect-diffuse", "Indirect diffuse (L_ID)", 4, false, "4"},
        {"indirect-specular", "Indirect specular (L_IS)", 5, false, "5"},
        {"albedo", "Albedo", 6, false, "6"},
        {"normal", "Normal", 7, false, "7"},
        {"roughness-metalness", "Roughness / metalness", 8, false, "8"},
        {"shadow-map", "Shadow map", 9, false, "9"},
        {"voxels", "Voxels", 0, false, "0"},
        {"voxel-slice", "Voxel slice", 1, true, "Shift+1"},
        {"cone-directions", "Cone directions", 2, true, "Shift+2"},
        {"voxel-levels", "Voxel levels", 3, true, "Shift+3"},
    };
    return views;
}

const EditorView* findEditorView(std::string_view name) {
    for (const EditorView& view : editorViews())
        if (view.name == name) return &view;
    return nullptr;
}

const EditorView* editorViewForKey(int digit, bool shift) {
    for (const EditorView& view : editorViews())
        if (view.digit == digit && view.shift == shift) return &view;
    return nullptr;
}

std::string_view currentViewName(View view, bool coneDirections) {
    return coneDirections ? std::string_view(kConeDirectionsView) : toString(view);
}

bool isFlatView(View view) { return view == View::ShadowMap || view == View::VoxelSlice; }

}  // namespace lit::editor
