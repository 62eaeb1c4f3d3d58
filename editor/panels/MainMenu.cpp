#include "panels/MainMenu.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace lit::editor {

namespace {
constexpr const char* kOpenPopup = "Open scene";
}

MenuRequests MainMenu::draw(PanelVisibility& visible, const RecentFiles& recent,
                            const std::filesystem::path& currentScene, float& height) {
    MenuRequests requests;
    height = 0.0f;
    if (ImGui::BeginMainMenuBar()) {
        if (ImGui::BeginMenu("File")) {
            if (ImGui::MenuItem("Open...")) {
                openRequested_ = true;
                pathInput_ = currentScene.string();
            }
            if (ImGui::BeginMenu("Open recent", !recent.empty())) {
                for (const std::filesystem::path& path : recent.paths())
                    if (ImGui::MenuItem(path.string().c_str())) requests.open = path;
                ImGui::EndMenu();
            }
            ImGui::Separator();
            if (ImGui::MenuItem("Quit")) requests.quit = true;
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("View")) {
            ImGui::MenuItem("Stats", nullptr, &visible.stats);
            ImGui::MenuItem("Render settings", nullptr, &visible.renderSettings);
            ImGui::MenuItem("Camera", nullptr, &visible.camera);
            ImGui::MenuItem("Log", nullptr, &visible.log);
            ImGui::EndMenu();
        }
        height = ImGui::GetWindowSize().y;
        ImGui::EndMainMenuBar();
    }
    // Popups opened from inside a menu live in the menu's ID scope; open it from the top level
    // so BeginPopupModal below finds it.
    if (openRequested_) {
        ImGui::OpenPopup(kOpenPopup);
        openRequested_ = false;
    }
    drawOpenPopup(recent, requests);
    return requests;
}

void MainMenu::drawOpenPopup(const RecentFiles& recent, MenuRequests& requests) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(560.0f, display.x * 0.9f), 0.0f), ImGuiCond_Appearing);
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
    if ((ImGui::Button("Open", ImVec2(100.0f, 0.0f)) || entered) && canOpen) {
        requests.open = std::filesystem::path(pathInput_);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100.0f, 0.0f)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace lit::editor
