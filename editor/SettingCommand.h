#pragma once
// The script's "setting KEY VALUE": one RenderSettings field by its JSON key ("gi.voxelResolution";
// an older flat key such as "voxelResolution" still works and adds a deprecation message to
// `warnings`), with the value as it would be written in JSON (numbers, true/false; a bare word such
// as a view name is taken as a string). Goes through setRenderSetting so the script, the settings
// file and lit-render's --set agree on names and types. Window-free (lit_editor_core).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "EditorState.h"
#include "RenderSettings.h"

namespace lit::editor {

// Sets the field and returns "", or returns a message naming the key and the problem ("unknown
// render setting 'gi.voxelRes'", "render settings: 'gi.enabled' has the wrong type") and changes
// nothing. output.width and output.height are refused: the editor sets them from its window (--size).
std::string applySetting(RenderSettings& settings, std::string_view key, std::string_view value,
                         std::vector<std::string>* warnings = nullptr);

// The editor's own settings by key (editor.interactiveFpsTarget, editor.giUpdateVoxelsPerFrame,
// editor.giRefineVoxelsPerFrame, editor.giMillisecondsPerFrame, editor.giIdleMillisecondsPerFrame, editor.redrawOnDemand,
// or the older render-settings names of the
// first three with a deprecation message):
// "" when set, a message when the value is bad, nullopt when `key` is not one of them.
std::optional<std::string> applyEditorSetting(ViewportSettings& viewport, std::string_view key, std::string_view value,
                                              std::vector<std::string>* warnings = nullptr);

}  // namespace lit::editor
