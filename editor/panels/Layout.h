#pragma once
// Where the editor's panels start, around a clear viewport in the middle:
//
//   +-----------+---------------------------+-------------+
//   | Hierarchy | Stats                     | Render      |
//   |           |                           | settings    |
//   +-----------+        (viewport)         |             |
//   | Inspector |                           +-------------+
//   |           +-------------+-------------+ Camera      |
//   |           | Log         | Timeline    |             |
//   +-----------+-------------+-------------+-------------+
//
// The scene's structure and the selection's properties on the left (read top to bottom: pick,
// then edit), how it is rendered on the right, time-based things (messages, the camera path)
// along the bottom. Placements are applied on the first frame and again whenever the window
// size changes, so panels never end up outside the window; in between the user may move and
// resize them.

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
    Placement hierarchy;
    Placement inspector;
    Placement stats;
    Placement renderSettings;
    Placement camera;
    Placement log;
    Placement timeline;
};

// `display`: window size in ImGui units (screen coordinates); `menuHeight`: the main menu bar's;
// `cameraHeight`: what the camera panel needs, the settings panel gets the rest of the column.
inline PanelLayout computePanelLayout(ImVec2 display, float menuHeight, float cameraHeight, ImGuiCond condition) {
    constexpr float kMargin = 8.0f;
    // Column widths: wide enough for a label and a three-component drag at 1280 wide, and never
    // more than about half the window together.
    const float leftWidth = std::clamp(display.x * 0.22f, 220.0f, 320.0f);
    const float rightWidth = std::clamp(display.x * 0.27f, 260.0f, 360.0f);
    const float top = menuHeight + kMargin;
    const float columnHeight = std::max(display.y - top - kMargin, 100.0f);
    const float leftX = kMargin;
    const float rightX = display.x - rightWidth - kMargin;

    // Left column: the hierarchy gets two fifths, the inspector (longer: transform, material,
    // light) the rest.
    const float hierarchyHeight = std::max(columnHeight * 0.4f - kMargin * 0.5f, 50.0f);
    const float inspectorHeight = std::max(columnHeight - hierarchyHeight - kMargin, 50.0f);

    // Right column: the camera panel as tall as its content, the settings the rest.
    cameraHeight = std::clamp(cameraHeight, 50.0f, columnHeight * 0.5f);
    const float settingsHeight = std::max(columnHeight - cameraHeight - kMargin, 50.0f);

    // Bottom strip between the columns: log on the left, timeline (which needs the width for
    // its ruler) on the right.
    const float centreX = leftX + leftWidth + kMargin;
    const float centreWidth = std::max(rightX - kMargin - centreX, 100.0f);
    const float bottomHeight = std::clamp(display.y * 0.24f, 110.0f, 260.0f);
    const float bottomY = display.y - bottomHeight - kMargin;
    const float logWidth = std::max((centreWidth - kMargin) * 0.45f, 50.0f);
    const float timelineWidth = std::max(centreWidth - logWidth - kMargin, 50.0f);

    PanelLayout layout;
    layout.hierarchy = {{leftX, top}, {leftWidth, hierarchyHeight}, condition};
    layout.inspector = {{leftX, top + hierarchyHeight + kMargin}, {leftWidth, inspectorHeight}, condition};
    layout.stats = {{centreX, top}, {0.0f, 0.0f}, condition};
    layout.renderSettings = {{rightX, top}, {rightWidth, settingsHeight}, condition};
    layout.camera = {{rightX, top + settingsHeight + kMargin}, {rightWidth, cameraHeight}, condition};
    layout.log = {{centreX, bottomY}, {logWidth, bottomHeight}, condition};
    layout.timeline = {{centreX + logWidth + kMargin, bottomY}, {timelineWidth, bottomHeight}, condition};
    return layout;
}

}  // namespace lit::editor
