#include "ViewportArea.h"

#include <algorithm>

namespace lit::editor {

glm::vec4 visibleViewportArea(glm::vec2 display, float top, std::span<const glm::vec4> panels) {
    float left = 0.0f, right = display.x, bottom = display.y;
    // The columns first: the bottom strip is what lies between them.
    for (const glm::vec4& panel : panels) {
        if (panel.x <= kDockDistance) left = std::max(left, panel.x + panel.z + kViewportMargin);
        if (panel.x + panel.z >= display.x - kDockDistance) right = std::min(right, panel.x - kViewportMargin);
    }
    for (const glm::vec4& panel : panels) {
        const bool column = panel.x <= kDockDistance || panel.x + panel.z >= display.x - kDockDistance;
        if (!column && panel.y + panel.w >= display.y - kDockDistance) bottom = std::min(bottom, panel.y - kViewportMargin);
    }
    return {left, top, std::max(right - left, 1.0f), std::max(bottom - top, 1.0f)};
}

bool insideArea(glm::vec4 area, glm::vec2 p) {
    return p.x >= area.x && p.y >= area.y && p.x < area.x + area.z && p.y < area.y + area.w;
}

}  // namespace lit::editor
