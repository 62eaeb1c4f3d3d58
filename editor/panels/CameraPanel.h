#pragma once
// Edits the editor's fly camera: speed, field of view, position and orientation.

#include "panels/Layout.h"
#include "scene/CameraView.h"

namespace lit::editor {

struct CameraPanelRequests {
    bool resetToSceneCamera = false;  // the user asked to go back to the scene's camera
};

// Height the panel needs for its content with the current style and font, screen coordinates.
float cameraPanelHeight();

CameraPanelRequests drawCameraPanel(FlyCamera& camera, const Placement& placement, bool* open);

}  // namespace lit::editor
