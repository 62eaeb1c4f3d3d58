#pragma once
// Edits RenderSettings (view, exposure, terms, shadows, GI) and the editor's viewport settings.
// Only fields change here; the renderer notices by comparing settings.

#include "EditorState.h"
#include "RenderSettings.h"
#include "panels/Layout.h"

namespace lit::editor {

// Returns true when any field changed this frame. width/height are not shown: the editor sets
// them from the window.
struct RenderSettingsRequests {
    bool changed = false;     // any RenderSettings field changed
    bool revoxelize = false;  // "Re-voxelize" was pressed: rebuild the voxel volume now
};

RenderSettingsRequests drawRenderSettingsPanel(RenderSettings& settings, ViewportSettings& viewport, int lightCount,
                                               const Placement& placement, bool* open);

}  // namespace lit::editor
