#pragma once
// The scene's node tree. Each row shows the node's name and what it holds ([M] mesh, [L] light,
// [C] camera); a click selects the node (Document::selectedNode), whose row is highlighted. With
// text in the filter box the tree becomes a flat list of the matching nodes.

#include <imgui.h>

#include "Document.h"
#include "panels/Layout.h"

namespace lit::editor {

class HierarchyPanel {
public:
    // Returns true when the user changed the selection this frame.
    bool draw(Document& doc, const Placement& placement, bool* open);

private:
    bool drawNode(Document& doc, int index, int depth);
    bool drawFlatList(Document& doc);

    ImGuiTextFilter filter_;
    int revealedSelection_ = -1;  // the selection the tree was last opened up to
};

}  // namespace lit::editor
