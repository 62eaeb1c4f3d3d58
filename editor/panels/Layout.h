#pragma once
// Where the editor's panels start: a column on the right (render settings above camera), the
// log along the bottom left and the stats overlay in the top left corner, leaving the middle of
// the viewport clear. Placements are applied on the first frame and again whenever the window
// size changes, so panels never end up outside the window; in between the user may move them.

#include <imgui.h>

#include <algorithm>

namespace lit::editor {

struct Placement {
    ImVec2 position;
    ImVec2 size;          // 0 on an axis = fit the content
    ImGuiCond condition;  // ImGuiCond_Always when the layout must be (re)applied this frame
};

// Applies a placement to the next ImGui::Begin.
inline void placeNextWindow(const Placement& placement) {
    ImGui::SetNextWindowPos(placement.position, placement.condition);
    if (placement.size.x > 0.0f && placement.size.y > 0.0f)
        ImGui::SetNextWindowSize(placement.size, placement.condition);
}

struct PanelLayout {
    Placement stats;
    Placement renderSettings;
    Placement camera;
    Placement log;
};

// `display`: window size in ImGui units (screen coordinates); `menuHeight`: the main menu bar's;
// `cameraHeight`: what the camera panel needs, the settings panel gets the rest of the column.
inline PanelLayout computePanelLayout(ImVec2 display, float menuHeight, float cameraHeight, ImGuiCond condition) {
    constexpr float kMargin = 8.0f;
    const float columnWidth = std::clamp(display.x * 0.27f, 260.0f, 360.0f);
    const float top = menuHeight + kMargin;
    const float columnX = display.x - columnWidth - kMargin;
    const float columnHeight = std::max(display.y - top - kMargin, 100.0f);
    cameraHeight = std::clamp(cameraHeight, 50.0f, columnHeight * 0.5f);
    const float settingsHeight = std::max(columnHeight - cameraHeight - kMargin, 50.0f);
    const float logHeight = std::clamp(display.y * 0.2f, 90.0f, 240.0f);
    const float logWidth = std::max(columnX - 2.0f * kMargin, 100.0f);

    PanelLayout layout;
    layout.stats = {{kMargin, top}, {0.0f, 0.0f}, condition};
    layout.renderSettings = {{columnX, top}, {columnWidth, settingsHeight}, condition};
    layout.camera = {{columnX, top + settingsHeight + kMargin}, {columnWidth, cameraHeight}, condition};
    layout.log = {{kMargin, display.y - logHeight - kMargin}, {logWidth, logHeight}, condition};
    return layout;
}

}  // namespace lit::editor
