#include "panels/ViewportBar.h"

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName: where the panels are this frame

#include <algorithm>
#include <string>
#include <vector>

#include "EditorViews.h"
#include "ViewportArea.h"

namespace lit::editor {

namespace {
// The panels that dock against the window's sides (their ImGui window names).
constexpr const char* kDockablePanels[] = {"Hierarchy", "Inspector", "Render settings", "Camera", "Log", "Timeline"};
}  // namespace

glm::vec4 drawViewportBar(float menuHeight, GizmoTool& gizmo, GizmoMode shownMode,
                          bool scaleApplies, std::string_view view, std::size_t selected) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Where the panels drawn this frame are (after the user moved, resized or collapsed them).
    std::vector<glm::vec4> panels;
    for (const char* name : kDockablePanels)
        if (const ImGuiWindow* window = ImGui::FindWindowByName(name); window != nullptr && window->Active && !window->Hidden)
            panels.emplace_back(window->Pos.x, window->Pos.y, window->Size.x, window->Size.y);
    const glm::vec4 area = visibleViewportArea({display.x, display.y}, menuHeight, panels);

    // Flush in the area's bottom-right corner: part of the viewport's frame, not over the middle
    // of the picture.
    ImGui::SetNextWindowPos(ImVec2(area.x + area.z, area.y + area.w), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("Viewport bar", nullptr, kFlags)) {
        auto modeButton = [&gizmo, shownMode](const char* label, GizmoMode mode, const char* tip, bool enabled) {
            const bool current = shownMode == mode;
            if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
            ImGui::BeginDisabled(!enabled);
            if (ImGui::Button(label)) gizmo.mode = mode;
            ImGui::EndDisabled();
            if (current) ImGui::PopStyleColor();
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tip);
            ImGui::SameLine();
        };
        modeButton("Move", GizmoMode::Translate, "Translate gizmo (W)", true);
        modeButton("Rotate", GizmoMode::Rotate, "Rotate gizmo (E)", true);
        modeButton("Scale", GizmoMode::Scale,
                   scaleApplies ? "Scale gizmo (R), always along the node's own axes"
                                : "Lights and cameras have no size to scale: the Move gizmo stands in",
                   scaleApplies);
        if (ImGui::Button(gizmo.space == GizmoSpace::World ? "World" : "Local"))
            gizmo.space = gizmo.space == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo axes: the world's or the node's own (T)");
        ImGui::SameLine();
        GizmoSnap& snap = gizmo.snap;
        ImGui::Checkbox("Snap", &snap.enabled);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Snap gizmo drags to the steps below (or hold Ctrl while dragging)");
        ImGui::SameLine();
        if (ImGui::Button("Steps...")) ImGui::OpenPopup("snap steps");
        if (ImGui::BeginPopup("snap steps")) {
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Move (m)", &snap.translateStep, 0.01f, 0.001f, 100.0f, "%.3f",
                             ImGuiSliderFlags_Logarithmic);
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Rotate (deg)", &snap.rotateStepDegrees, 0.5f, 0.1f, 180.0f, "%.1f");
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Scale (factor)", &snap.scaleStep, 0.01f, 0.001f, 10.0f, "%.3f",
                             ImGuiSliderFlags_Logarithmic);
            snap.translateStep = std::max(snap.translateStep, 0.001f);
            snap.rotateStepDegrees = std::max(snap.rotateStepDegrees, 0.1f);
            snap.scaleStep = std::max(snap.scaleStep, 0.001f);
            ImGui::EndPopup();
        }
        const EditorView* entry = findEditorView(view);
        ImGui::Text("View: %s (%s)", entry ? std::string(entry->label).c_str() : std::string(view).c_str(),
                    entry ? std::string(entry->shortcut).c_str() : "-");
        if (selected > 1) {
            ImGui::SameLine();
            ImGui::TextDisabled("| %zu selected", selected);
        }
    }
    ImGui::End();
    return area;
}

}  // namespace lit::editor
