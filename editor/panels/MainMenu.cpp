#include "panels/MainMenu.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "EditorViews.h"
#include "SaveAsName.h"
#include "panels/Dialogs.h"

namespace lit::editor {

namespace {
constexpr const char* kOpenPopup = "Open scene";
constexpr const char* kSaveAsPopup = "Save scene as";

// Wide enough for a long path.
void placePathPopup() { placeNextPopup(560.0f); }
}  // namespace

MenuRequests MainMenu::draw(PanelVisibility& visible, const MenuContext& context, float& height) {
    MenuRequests requests;
    height = 0.0f;
    if (ImGui::BeginMainMenuBar()) {
        if (ImGui::BeginMenu("File")) {
            if (ImGui::MenuItem("Open...")) {
                openRequested_ = true;
                pathInput_ = context.currentScene.string();
            }
            if (ImGui::BeginMenu("Open recent", !context.recent.empty())) {
                for (const std::filesystem::path& path : context.recent.paths())
                    if (ImGui::MenuItem(path.string().c_str())) requests.open = path;
                ImGui::EndMenu();
            }
            ImGui::Separator();
            if (ImGui::MenuItem("Save", "Ctrl+S")) requests.save = true;
            if (ImGui::MenuItem("Save As...")) askSaveAs(suggestSaveAsName(context.documentFile));
            ImGui::Separator();
            if (ImGui::MenuItem("Screenshot", "F12")) requests.screenshot = true;
            if (ImGui::MenuItem("Screenshot with UI")) requests.screenshotWithUi = true;
            ImGui::Separator();
            if (ImGui::MenuItem("Quit")) requests.quit = true;
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Edit")) {
            const std::string undo = context.undoLabel.empty() ? "Undo" : "Undo " + context.undoLabel;
            const std::string redo = context.redoLabel.empty() ? "Redo" : "Redo " + context.redoLabel;
            if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, !context.undoLabel.empty())) requests.undo = true;
            if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, !context.redoLabel.empty())) requests.redo = true;
            ImGui::Separator();
            if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, context.hasSelection)) requests.duplicateSelection = true;
            if (ImGui::MenuItem("Delete", "Del", false, context.hasSelection)) requests.deleteSelection = true;
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Add")) {
            const char* labels[] = {"Empty", "Directional light (sun)", "Point light", "Spot light", "Camera",
                                    "Box", "Plane", "Sphere"};
            int i = 0;
            for (const NodeKind kind : allNodeKinds()) {
                if (kind == NodeKind::DirectionalLight || kind == NodeKind::Camera || kind == NodeKind::Box) ImGui::Separator();
                if (ImGui::MenuItem(labels[i++])) requests.add = kind;
            }
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("View")) {
            for (const EditorView& view : editorViews()) {
                const std::string label(view.label), shortcut(view.shortcut);
                if (ImGui::MenuItem(label.c_str(), shortcut.c_str(), view.name == context.currentView))
                    requests.view = std::string(view.name);
            }
            ImGui::Separator();
            if (ImGui::MenuItem("Frame selected", "F", false, context.hasSelection)) requests.frameSelection = true;
            ImGui::Separator();
            ImGui::MenuItem("Hierarchy", nullptr, &visible.hierarchy);
            ImGui::MenuItem("Inspector", nullptr, &visible.inspector);
            ImGui::MenuItem("Render settings", nullptr, &visible.renderSettings);
            ImGui::MenuItem("Camera", nullptr, &visible.camera);
            ImGui::MenuItem("Timeline", nullptr, &visible.timeline);
            ImGui::MenuItem("Log", nullptr, &visible.log);
            ImGui::MenuItem("Stats", "F2", &visible.stats);
            ImGui::MenuItem("Stats details", nullptr, &visible.statsDetails);
            ImGui::MenuItem("Legend", nullptr, &visible.legend);
            ImGui::EndMenu();
        }
        height = ImGui::GetWindowSize().y;
        ImGui::EndMainMenuBar();
    }
    // Popups opened from inside a menu live in the menu's ID scope; open them from the top level
    // so BeginPopupModal below finds them.
    if (openRequested_) {
        ImGui::OpenPopup(kOpenPopup);
        openRequested_ = false;
    }
    if (saveAsRequested_) {
        ImGui::OpenPopup(kSaveAsPopup);
        saveAsRequested_ = false;
    }
    drawOpenPopup(context.recent, requests);
    drawSaveAsPopup(requests);
    return requests;
}

void MainMenu::askSaveAs(const std::filesystem::path& suggestion) {
    saveAsRequested_ = true;
    saveAsInput_ = suggestion.string();
}

void MainMenu::drawOpenPopup(const RecentFiles& recent, MenuRequests& requests) {
    placePathPopup();
    if (!ImGui::BeginPopupModal(kOpenPopup, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;

    ImGui::TextUnformatted("glTF scene (.gltf or .glb):");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1.0f);
    // Selected on entry, so typing replaces the pre-filled path and editing it is one click away.
    const bool entered = ImGui::InputText("##path", &pathInput_,
                                          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (!recent.empty()) {
        ImGui::TextDisabled("Recent:");
        for (const std::filesystem::path& path : recent.paths()) {
            const std::string text = path.string();
            if (ImGui::Selectable(text.c_str(), text == pathInput_, ImGuiSelectableFlags_AllowDoubleClick)) {
                pathInput_ = text;
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
                    requests.open = path;
                    ImGui::CloseCurrentPopup();
                }
            }
        }
    }
    ImGui::Spacing();
    const bool canOpen = !pathInput_.empty();
    ImGui::BeginDisabled(!canOpen);
    if ((ImGui::Button("Open", ImVec2(kDialogButtonWidth, 0.0f)) || entered) && canOpen) {
        requests.open = std::filesystem::path(pathInput_);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (cancelPressed()) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void MainMenu::drawSaveAsPopup(MenuRequests& requests) {
    placePathPopup();
    if (!ImGui::BeginPopupModal(kSaveAsPopup, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;

    ImGui::TextUnformatted("Save as glTF (.gltf with a .bin beside it, or one .glb):");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1.0f);
    const bool entered = ImGui::InputText("##path", &saveAsInput_,
                                          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    const std::filesystem::path path(saveAsInput_);
    const std::string extension = path.extension().string();
    const bool validName = extension == ".gltf" || extension == ".glb";
    if (!saveAsInput_.empty() && !validName) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "The name must end in .gltf or .glb");
    ImGui::Spacing();
    ImGui::BeginDisabled(!validName);
    if ((ImGui::Button("Save", ImVec2(kDialogButtonWidth, 0.0f)) || entered) && validName) {
        requests.saveAs = path;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (cancelPressed()) {
        requests.saveAsCancelled = true;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace lit::editor
