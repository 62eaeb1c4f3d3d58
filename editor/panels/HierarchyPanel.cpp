#include "panels/HierarchyPanel.h"

#include <string>

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

}  // namespace

bool HierarchyPanel::draw(Document& doc, const Placement& placement, bool* open) {
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
        // A click on empty space below the rows clears the selection.
        if (ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !ImGui::IsAnyItemHovered() &&
            doc.selectedNode >= 0) {
            doc.selectedNode = -1;
            changed = true;
        }
        ImGui::EndChild();
    }
    ImGui::End();
    return changed;
}

bool HierarchyPanel::drawNode(Document& doc, int index, int depth) {
    const Scene& scene = doc.scene;
    if (index < 0 || index >= static_cast<int>(scene.nodes.size()) || depth > kMaxDepth) return false;
    const Node& node = scene.nodes[static_cast<std::size_t>(index)];
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_OpenOnDoubleClick |
                               ImGuiTreeNodeFlags_SpanAvailWidth | ImGuiTreeNodeFlags_DefaultOpen;
    if (node.children.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (index == doc.selectedNode) flags |= ImGuiTreeNodeFlags_Selected;
    // A selection made elsewhere (script, viewport) opens the tree down to it, once.
    if (doc.selectedNode != revealedSelection_ && doc.selectedNode >= 0 && index != doc.selectedNode &&
        isAncestorOrSelf(scene, index, doc.selectedNode))
        ImGui::SetNextItemOpen(true);
    const std::string label = labelOf(node, index);
    const bool opened = ImGui::TreeNodeEx(label.c_str(), flags);
    if (index == doc.selectedNode && doc.selectedNode != revealedSelection_) ImGui::SetScrollHereY();
    bool changed = false;
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !ImGui::IsItemToggledOpen() && doc.selectedNode != index) {
        doc.selectedNode = index;
        changed = true;
    }
    if (opened && !node.children.empty()) {
        for (const int child : node.children) changed |= drawNode(doc, child, depth + 1);
        ImGui::TreePop();
    }
    return changed;
}

bool HierarchyPanel::drawFlatList(Document& doc) {
    bool changed = false;
    const Scene& scene = doc.scene;
    for (int index = 0; index < static_cast<int>(scene.nodes.size()); ++index) {
        const Node& node = scene.nodes[static_cast<std::size_t>(index)];
        if (!filter_.PassFilter(node.name.c_str())) continue;
        const std::string label = labelOf(node, index);
        if (ImGui::Selectable(label.c_str(), index == doc.selectedNode) && doc.selectedNode != index) {
            doc.selectedNode = index;
            changed = true;
        }
    }
    return changed;
}

}  // namespace lit::editor
