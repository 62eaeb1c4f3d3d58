#pragma once
// The script's "setting KEY VALUE": one RenderSettings field by its JSON name, with the value
// as it would be written in JSON (numbers, true/false; a bare word such as a view name is taken
// as a string). Goes through renderSettingsFromJson so the script, the settings file and the
// panel agree on names and types. Window-free (lit_editor_core).

#include <string>
#include <string_view>

#include "RenderSettings.h"

namespace lit::editor {

// Sets the field and returns "", or returns a message naming the key and the problem ("unknown
// render setting 'voxelRes'", "render settings: 'gi' has the wrong type") and changes nothing.
// width and height are refused: the editor sets them from its window (--size).
std::string applySetting(RenderSettings& settings, std::string_view key, std::string_view value);

}  // namespace lit::editor
