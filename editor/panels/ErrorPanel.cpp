#include "panels/ErrorPanel.h"

#include <algorithm>

namespace lit::editor {

void drawErrorPanel(std::string& message, ImVec2 display, float menuHeight) {
    if (message.empty()) return;
    // Centred at the top, over the viewport, narrower than the space between the stats overlay
    // and the settings column at 1280 wide.
    const float width = std::min(520.0f, display.x * 0.8f);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, menuHeight + 40.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.55f, 0.12f, 0.12f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.70f, 0.15f, 0.15f, 1.0f));
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin("Error", nullptr, kFlags)) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(message.c_str());
        ImGui::PopTextWrapPos();
        ImGui::Spacing();
        if (ImGui::Button("Dismiss")) message.clear();
    }
    ImGui::End();
    ImGui::PopStyleColor(2);
}

}  // namespace lit::editor
