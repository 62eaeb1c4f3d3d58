#pragma once
// Names for screenshots taken from the editor (F12 / the menu): one file per shot, named by the
// local time it was taken, so a folder of them sorts by time. Window-free (lit_editor_core).

#include <chrono>
#include <filesystem>

namespace lit::editor {

// "<folder>/lit_2026-12-01_16-05-09.png", with "_ui" before ".png" when the shot includes the
// UI. Never names an existing file: a second shot in the same second gets "_2", then "_3"...
// (lit_2026-12-01_16-05-09_ui_2.png). The folder is not created here.
std::filesystem::path timestampedScreenshotPath(const std::filesystem::path& folder, bool withUi,
                                                std::chrono::system_clock::time_point time);

}  // namespace lit::editor
