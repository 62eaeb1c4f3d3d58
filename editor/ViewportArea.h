#pragma once
// The visible viewport: the part of the window that the docked panels leave free. A panel is
// docked when it lies against a side of the window (within kDockDistance): the left column
// (hierarchy, inspector), the right column (render settings, camera), the bottom strip between
// them (log, timeline). A panel dragged away from the sides floats over the viewport and is not
// counted, nor are the overlays inside it (performance, reference). The 2D views fill this area,
// F frames the selection in it, the mouse picks and grabs gizmos only inside it, and the
// viewport bar sits in its bottom-right corner. Window-free (lit_editor_core).

#include <glm/glm.hpp>
#include <span>

namespace lit::editor {

// How close to a window side (ImGui units) a panel's edge must be to count as docked there.
inline constexpr float kDockDistance = 24.0f;
// The gap left between the area and a docked panel (the layout's margin).
inline constexpr float kViewportMargin = 8.0f;

// `display`: the window's size; `top`: the main menu bar's height; `panels`: the shown panels'
// rectangles (x, y, width, height; top-left origin). Returns x, y, width, height (at least 1).
glm::vec4 visibleViewportArea(glm::vec2 display, float top, std::span<const glm::vec4> panels);

// Whether window point `p` lies in `area` (x, y, width, height).
bool insideArea(glm::vec4 area, glm::vec2 p);

}  // namespace lit::editor
