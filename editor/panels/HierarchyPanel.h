#pragma once
// The scene's node tree. Each row shows the node's name and what it holds ([M] mesh, [L] light,
// [C] camera); a click selects the node (Document::selectedNode), whose row is highlighted. With
// text in the filter box the tree becomes a flat list of the matching nodes.

#include <imgui.h>

#include <glm/glm.hpp>

#include "Document.h"
#include "panels/Layout.h"

namespace lit::editor {

// What a row's right-click menu asked for.
enum class NodeAction { None, Duplicate, Delete, MoveToRoot };

class HierarchyPanel {
public:
    // Returns true when the user changed the selection this frame. `viewRight`: the viewport
    // camera's right vector, where Duplicate moves the copies (duplicateSelection).
    bool draw(Document& doc, glm::vec3 viewRight, const Placement& placement, bool* open);

private:
    bool drawNode(Document& doc, int index, int depth);
    // The rows of a node whose mesh has several primitives, one per primitive: a click selects it.
    bool drawPrimitives(Document& doc, int index, int primitives);
    bool carryOut(Document& doc, NodeAction action, glm::vec3 viewRight);
    bool drawFlatList(Document& doc);

    ImGuiTextFilter filter_;
    int revealedSelection_ = -1;  // the selection the tree was last opened up to
    int revealedPrimitive_ = -1;  // the picked primitive of it last scrolled to (-1: none)
    NodeAction pendingAction_ = NodeAction::None;  // a row's menu choice, done after the tree
};

}  // namespace lit::editor
