#pragma once
// Mouse and keyboard in the viewport. Right drag looks around and, while it does, W A S D Q E
// fly the fly camera (the wheel sets its speed); Alt + left drag orbits; a left click picks the
// node under the cursor (or, in the cone directions view, the surface whose cones to draw); a
// left drag on a gizmo handle moves, turns or scales the selection as one undo step. The
// script's pick, drag and view commands go through the same functions.

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "EditorState.h"
#include "Log.h"
#include "Renderer.h"
#include "TransformGizmo.h"
#include "ViewportOverlay.h"
#include "Window.h"
#include "scene/CameraView.h"

namespace lit::editor {

class ViewportInput {
public:
    ViewportInput(const Window& window, Document& doc, FlyCamera& camera, ViewportSettings& viewport,
                  GizmoTool& gizmoTool, const Renderer& renderer, Log& log);
    // Gives the cursor back if the editor closes in the middle of a right drag.
    ~ViewportInput();
    ViewportInput(const ViewportInput&) = delete;
    ViewportInput& operator=(const ViewportInput&) = delete;

    // The fly camera's view for the window, its near and far planes fitted to where it is.
    CameraView currentView() const;
    // Right drag and the flying keys (not while ImGui has the mouse or the keyboard).
    void updateFlyCamera(float dtSeconds);
    // Left mouse: orbit with Alt, grab and drag a gizmo handle, else pick what is under the cursor.
    void handleMouse(const CameraView& view);
    // The script's drag: grabs the handle under `from`, moves to `to` in steps as a mouse would
    // (so a rotation can be unwrapped past 180°), lets go. False when no handle is at `from`.
    bool dragGizmo(const CameraView& view, glm::vec2 from, glm::vec2 to);
    // Window pixel (top-left origin) → the renderer's last frame: select its node (Shift adds),
    // or sample its surface for the cone directions view. Returns "" or why nothing was picked.
    std::string pickAt(glm::vec2 windowPixel);
    // Shows the view called `name` (an EditorViews.h name). Returns "" or the error.
    std::string setView(const std::string& name);
    // Frame selected (F): the camera moves so the selection fills the visible viewport area.
    void frameSelection();
    // The visible viewport (ViewportArea.h; ImGui units: x, y, width, height; the viewport bar
    // computes it each frame): the mouse picks and grabs the gizmo only there, and Frame
    // selected centres the selection there.
    void setVisibleArea(glm::vec4 area) { visibleArea_ = area; }
    // Drops the cone directions view's pick (its view was left).
    void forgetConeSurface();

    // The gizmo mode for the active node: the tool's, or Move where scale means nothing
    // (GizmoChoice.h).
    GizmoMode gizmoMode() const;
    bool looking() const { return looking_; }  // the right mouse button looks around
    bool gizmoDragging() const { return gizmo_.active(); }
    // What this input adds to the overlay (gizmo hover, cones); `cleanViewport`: only the cones.
    OverlayOptions overlayOptions(bool cleanViewport) const;

private:
    bool beginGizmoDrag(const CameraView& view, glm::vec2 mouse);
    void continueGizmoDrag(const CameraView& view, glm::vec2 mouse, bool snap);
    void endGizmoDrag();

    const Window& window_;
    Document& doc_;
    FlyCamera& camera_;
    ViewportSettings& viewport_;
    GizmoTool& gizmoTool_;
    const Renderer& renderer_;
    Log& log_;

    bool looking_ = false;        // right mouse drag in progress
    glm::dvec2 lastCursor_{0.0};  // screen coordinates, while looking
    TransformGizmo gizmo_;
    int hoveredGizmoAxis_ = -1;
    // The nodes a gizmo drag moves (the top-level selected ones) as they were when it began.
    struct DraggedNode {
        int node;
        glm::mat4 world;
        glm::vec3 translation, scale;
    };
    std::vector<DraggedNode> dragged_;
    // Alt + left drag orbits the fly camera around the selection (or the point in front).
    bool orbiting_ = false;
    glm::vec3 orbitPivot_{0.0f};
    glm::dvec2 orbitCursor_{0.0};
    // Cone directions view: the surface last clicked and where the camera was then.
    std::optional<SurfaceSample> coneSurface_;
    glm::vec4 visibleArea_{0.0f};  // 0 until the UI has been laid out: the whole window
    glm::vec3 coneCameraPosition_{0.0f};
};

}  // namespace lit::editor
