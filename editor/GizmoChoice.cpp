#include "GizmoChoice.h"

namespace lit::editor {

bool scaleAppliesTo(const Scene& scene, int node) {
    if (node < 0 || node >= static_cast<int>(scene.nodes.size())) return true;
    const Node& n = scene.nodes[static_cast<std::size_t>(node)];
    const bool lightOrCamera = n.light >= 0 || n.camera >= 0;
    return !lightOrCamera || n.mesh >= 0 || !n.children.empty();
}

GizmoMode gizmoModeFor(const GizmoTool& tool, const Scene& scene, int activeNode) {
    if (tool.mode == GizmoMode::Scale && !scaleAppliesTo(scene, activeNode)) return GizmoMode::Translate;
    return tool.mode;
}

}  // namespace lit::editor
