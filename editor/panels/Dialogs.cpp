#include "panels/Dialogs.h"

#include <imgui.h>

#include <algorithm>
#include <utility>

namespace lit::editor {

void placeNextPopup(float width) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(width, display.x * 0.9f), 0.0f), ImGuiCond_Appearing);
}

bool cancelPressed() {
    return ImGui::Button("Cancel", ImVec2(kDialogButtonWidth, 0.0f)) ||
           ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
}

void QuestionDialog::ask(Question question) {
    question_ = std::move(question);
    asking_ = true;
    openPending_ = true;
}

Answer QuestionDialog::draw() {
    if (!asking_) return Answer::None;
    const std::string id = question_.title + "##question";
    if (openPending_) {
        ImGui::OpenPopup(id.c_str());
        openPending_ = false;
    }
    placeNextPopup(460.0f);
    Answer answer = Answer::None;
    if (ImGui::BeginPopupModal(id.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(question_.message.c_str());
        ImGui::PopTextWrapPos();
        ImGui::Spacing();
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        if (ImGui::Button(question_.yes.c_str(), ImVec2(kDialogButtonWidth, 0.0f))) answer = Answer::Yes;
        ImGui::SameLine();
        if (ImGui::Button(question_.no.c_str(), ImVec2(kDialogButtonWidth, 0.0f))) answer = Answer::No;
        if (question_.cancellable) {
            ImGui::SameLine();
            if (cancelPressed()) answer = Answer::Cancel;
        }
        if (answer != Answer::None) {
            ImGui::CloseCurrentPopup();
            asking_ = false;
        }
        ImGui::EndPopup();
    } else if (!ImGui::IsPopupOpen(id.c_str())) {
        // Closed some other way (another modal replaced it): Cancel, which loses nothing.
        asking_ = false;
        answer = Answer::Cancel;
    }
    return answer;
}

}  // namespace lit::editor
