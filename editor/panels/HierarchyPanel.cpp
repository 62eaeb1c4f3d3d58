#include "panels/HierarchyPanel.h"

#include <algorithm>
#include <string>
#include <utility>

#include "SceneEdits.h"

namespace lit::editor {

namespace {

// A glTF tree can nest deeply; rows stop indenting usefully long before this, and the limit
// keeps a malformed (cyclic) parent list from recursing forever.
constexpr int kMaxDepth = 64;

// "[M][L]" style tags for what a node holds, so lights and cameras stand out among meshes.
std::string tagsOf(const Node& node) {
    std::string tags;
    if (node.mesh >= 0) tags += "[M]";
    if (node.light >= 0) tags += "[L]";
    if (node.camera >= 0) tags += "[C]";
    return tags;
}

std::string labelOf(const Node& node, int index) {
    const std::string name = node.name.empty() ? "node " + std::to_string(index) : node.name;
    const std::string tags = tagsOf(node);
    // The index makes the ImGui ID unique even when two nodes share a name.
    return (tags.empty() ? name : tags + " " + name) + "##node" + std::to_string(index);
}

// Whether `ancestor` is `node` or above it.
bool isAncestorOrSelf(const Scene& scene, int ancestor, int node) {
    for (int depth = 0; node >= 0 && depth < kMaxDepth; ++depth) {
        if (node == ancestor) return true;
        node = scene.nodes[static_cast<std::size_t>(node)].parent;
    }
    return false;
}

constexpr const char* kDragPayload = "LIT_NODE";

// Dropping a dragged node makes `newParent` its parent (the whole selection's when the dragged
// node is selected), keeping world transforms; -1 = the scene root.
bool acceptNodeDrop(Document& doc, int newParent) {
    bool changed = false;
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kDragPayload)) {
            const int dragged = *static_cast<const int*>(payload->Data);
            if (!doc.isSelected(dragged)) doc.select(dragged);
            doc.lastRefusal = reparentSelection(doc, newParent);
            changed = true;
        }
        ImGui::EndDragDropTarget();
    }
    return changed;
}

// Right-click menu of a row: the edits of the Edit menu on this node. They are carried out
// after the tree is drawn (HierarchyPanel::carryOut): the tree must not change under the loop
// that draws it, and the rows must be drawn once more to scroll to a new selection.
NodeAction nodeContextMenu(Document& doc, int index) {
    NodeAction action = NodeAction::None;
    if (ImGui::BeginPopupContextItem()) {
        if (!doc.isSelected(index)) doc.select(index);
        if (ImGui::MenuItem("Duplicate", "Ctrl+D")) action = NodeAction::Duplicate;
        if (ImGui::MenuItem("Delete", "Del")) action = NodeAction::Delete;
        if (ImGui::MenuItem("Move to the root", nullptr, false, doc.scene.nodes[static_cast<std::size_t>(index)].parent >= 0))
            action = NodeAction::MoveToRoot;
        ImGui::EndPopup();
    }
    return action;
}

}  // namespace

bool HierarchyPanel::draw(Document& doc, glm::vec3 viewRight, const Placement& placement, bool* open) {
    placeNextWindow(placement);
    bool changed = false;
    if (ImGui::Begin("Hierarchy", open)) {
        // ImGuiTextFilter::Draw has no hint text; an empty box would not say what it is for.
        ImGui::SetNextItemWidth(-1.0f);
        if (ImGui::InputTextWithHint("##filter", "Filter by name", filter_.InputBuf, IM_ARRAYSIZE(filter_.InputBuf)))
            filter_.Build();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show only nodes whose name contains this (\"a,-b\": a but not b)");
        ImGui::Separator();
        ImGui::BeginChild("tree");
        const Scene& scene = doc.scene;
        if (scene.nodes.empty()) ImGui::TextDisabled("(no scene)");
        if (filter_.IsActive()) {
            changed = drawFlatList(doc);
        } else {
            for (const int root : scene.roots) changed |= drawNode(doc, root, 0);
        }
        revealedSelection_ = doc.selectedNode;
        // After revealedSelection_: a copy made here is scrolled to on the next frame.
        changed |= carryOut(doc, std::exchange(pendingAction_, NodeAction::None), viewRight);
        // The space below the rows: a drop there moves the dragged nodes to the scene root.
        ImGui::Dummy(ImVec2(-1.0f, std::max(ImGui::GetContentRegionAvail().y, 24.0f)));
        changed |= acceptNodeDrop(doc, -1);
        // A click on empty space below the rows clears the selection.
        if (ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !ImGui::IsAnyItemHovered() &&
            doc.selectedNode >= 0 && !ImGui::GetIO().KeyShift) {
            doc.select(-1);
            changed = true;
        }
        ImGui::EndChild();
    }
    ImGui::End();
    return changed;
}

bool HierarchyPanel::carryOut(Document& doc, NodeAction action, glm::vec3 viewRight) {
    switch (action) {
        case NodeAction::None: return false;
        case NodeAction::Duplicate: doc.lastRefusal = duplicateSelection(doc, viewRight); break;
        case NodeAction::Delete: doc.lastRefusal = deleteSelection(doc); break;
        case NodeAction::MoveToRoot: doc.lastRefusal = reparentSelection(doc, -1); break;
    }
    return doc.lastRefusal.empty();
}

bool HierarchyPanel::drawNode(Document& doc, int index, int depth) {
    const Scene& scene = doc.scene;
    if (index < 0 || index >= static_cast<int>(scene.nodes.size()) || depth > kMaxDepth) return false;
    const Node& node = scene.nodes[static_cast<std::size_t>(index)];
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_OpenOnDoubleClick |
                               ImGuiTreeNodeFlags_SpanAvailWidth | ImGuiTreeNodeFlags_DefaultOpen;
    // A mesh of several primitives (a one-node scene's parts) lists them as rows below its node.
    const int primitives = doc.primitiveCount(index);
    const bool listsPrimitives = primitives > 1;
    if (node.children.empty() && !listsPrimitives) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (doc.isSelected(index) && !(doc.primitivePicked && index == doc.selectedNode)) flags |= ImGuiTreeNodeFlags_Selected;
    // A selection made elsewhere (script, viewport) opens the tree down to it, once.
    if (doc.selectedNode != revealedSelection_ && doc.selectedNode >= 0 && index != doc.selectedNode &&
        isAncestorOrSelf(scene, index, doc.selectedNode))
        ImGui::SetNextItemOpen(true);
    const std::string label = labelOf(node, index);
    const bool opened = ImGui::TreeNodeEx(label.c_str(), flags);
    if (index == doc.selectedNode && doc.selectedNode != revealedSelection_) ImGui::SetScrollHereY();
    bool changed = false;
    // Shift+click adds to (or takes from) the selection, as in Blender and Godot.
    // A plain click on a row of a multi-selection keeps the selection until the button comes up
    // without a drag, so the whole selection can be dragged onto a new parent.
    const ImGuiIO& io = ImGui::GetIO();
    const bool multiple = doc.selection().size() > 1;
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !ImGui::IsItemToggledOpen()) {
        if (io.KeyShift) {
            doc.select(index, /*additive=*/true);
            changed = true;
        } else if (!doc.isSelected(index) || (!multiple && doc.selectedNode != index)) {
            doc.select(index);
            changed = true;
        }
    }
    if (multiple && !io.KeyShift && doc.isSelected(index) && ImGui::IsItemHovered() &&
        ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 16.0f) {
        doc.select(index);
        changed = true;
    }
    // Drag a row onto another to parent it there (world transform kept).
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kDragPayload, &index, sizeof index);
        ImGui::Text("Parent %s to ...", node.name.empty() ? "node" : node.name.c_str());
        ImGui::EndDragDropSource();
    }
    changed |= acceptNodeDrop(doc, index);
    if (const NodeAction action = nodeContextMenu(doc, index); action != NodeAction::None) pendingAction_ = action;
    if (opened && (listsPrimitives || !node.children.empty())) {
        if (listsPrimitives) changed |= drawPrimitives(doc, index, primitives);
        for (const int child : node.children) changed |= drawNode(doc, child, depth + 1);
        ImGui::TreePop();
    }
    return changed;
}

bool HierarchyPanel::drawPrimitives(Document& doc, int index, int primitives) {
    bool changed = false;
    ImGui::PushID(index);
    for (int p = 0; p < primitives; ++p) {
        const bool picked = doc.primitivePicked && doc.selectedNode == index && doc.selectedPrimitive == p;
        ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen |
                                   ImGuiTreeNodeFlags_SpanAvailWidth;
        if (picked) flags |= ImGuiTreeNodeFlags_Selected;
        ImGui::PushID(p);
        ImGui::TreeNodeEx("primitive", flags, "%s", doc.primitiveLabel(index, p).c_str());
        ImGui::PopID();
        // A part picked in the viewport is scrolled to, once.
        if (picked && revealedPrimitive_ != p) {
            ImGui::SetScrollHereY();
            revealedPrimitive_ = p;
        }
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
            doc.selectPrimitive(index, p);
            revealedPrimitive_ = p;
            changed = true;
        }
    }
    if (!doc.primitivePicked) revealedPrimitive_ = -1;
    ImGui::PopID();
    return changed;
}

bool HierarchyPanel::drawFlatList(Document& doc) {
    bool changed = false;
    const Scene& scene = doc.scene;
    for (int index = 0; index < static_cast<int>(scene.nodes.size()); ++index) {
        const Node& node = scene.nodes[static_cast<std::size_t>(index)];
        if (!filter_.PassFilter(node.name.c_str())) continue;
        const std::string label = labelOf(node, index);
        if (ImGui::Selectable(label.c_str(), doc.isSelected(index))) {
            doc.select(index, ImGui::GetIO().KeyShift);
            changed = true;
        }
    }
    return changed;
}

}  // namespace lit::editor
