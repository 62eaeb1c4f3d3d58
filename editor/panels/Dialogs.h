#pragma once
// Modal questions the editor asks before it loses work: "Save changes to box.gltf?" (Save /
// Discard / Cancel) and "Recover the autosave?" (Recover / Discard). FileActions asks, draws the
// dialog every frame and acts on the answer when one comes.

#include <string>

namespace lit::editor {

struct Question {
    std::string title;     // window title, also the popup's ID
    std::string message;
    std::string yes;       // "Save", "Recover"
    std::string no;        // "Discard"
    bool cancellable = true;  // shows Cancel (and Escape cancels)
};

enum class Answer { None, Yes, No, Cancel };

// Shared by the editor's modal popups (these questions, the menu's Open and Save As).
inline constexpr float kDialogButtonWidth = 100.0f;
// Centres the next popup on the display, `width` wide (at most 90% of the display).
void placeNextPopup(float width);
// Draws a modal's Cancel button; true when it or Escape was pressed.
bool cancelPressed();

class QuestionDialog {
public:
    // Shows `question` from the next draw() on, replacing any question still open.
    void ask(Question question);
    bool asking() const { return asking_; }
    // Draws the dialog while a question is open. Returns the answer on the frame it is given
    // (the dialog closes then), else Answer::None. A dialog closed by anything but its buttons
    // answers Cancel, even when it shows no Cancel button.
    Answer draw();

private:
    Question question_;
    bool asking_ = false;
    bool openPending_ = false;  // ImGui::OpenPopup still to be called (outside any menu scope)
};

}  // namespace lit::editor
