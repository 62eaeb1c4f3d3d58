#pragma once
// Which gizmo the viewport shows for the active node. glTF lights and cameras ignore their
// node's scale (a light's reach is its intensity and range, a camera's view its field of view),
// so a scale gizmo on them would change nothing visible: there the tool's Scale falls back to
// Move. The tool keeps its mode, so selecting a mesh again brings the scale gizmo back.
// Window-free (lit_editor_core).

#include "TransformGizmo.h"
#include "scene/Scene.h"

namespace lit::editor {

// False for a node that holds a light or a camera and nothing a scale would change (no mesh,
// no children); true otherwise, and for an index out of range.
bool scaleAppliesTo(const Scene& scene, int node);

// The tool's mode, except Scale on a node where scale means nothing: Translate.
GizmoMode gizmoModeFor(const GizmoTool& tool, const Scene& scene, int activeNode);

}  // namespace lit::editor
