#pragma once
// The bar in the bottom-right corner of the visible viewport (ViewportArea.h; the stats overlay
// has the top left): the gizmo's mode, space and snapping, and the name of the view on screen,
// so a data view is never mistaken for the final image.

#include <cstddef>
#include <glm/glm.hpp>
#include <string_view>

#include "EditorState.h"
#include "TransformGizmo.h"

namespace lit::editor {

// Call after the panels: returns the visible viewport, the area the docked panels drawn this
// frame leave free (visibleViewportArea), ImGui units: x, y, width, height. `view`: an
// EditorViews.h name; `selected`:
// how many nodes are selected; `shownMode`: the gizmo the viewport shows for the active node
// (GizmoChoice.h), highlighted; `scaleApplies`: false greys Scale out (a light or camera).
glm::vec4 drawViewportBar(float menuHeight, GizmoTool& gizmo, GizmoMode shownMode,
                          bool scaleApplies, std::string_view view, std::size_t selected);

}  // namespace lit::editor
