#pragma once
// A message the user must see (a scene that failed to load), shown near the top of the window
// until dismissed.

#include <imgui.h>

#include <string>

namespace lit::editor {

// Draws nothing when `message` is empty; clears it when the user dismisses it.
void drawErrorPanel(std::string& message, ImVec2 display, float menuHeight);

}  // namespace lit::editor
