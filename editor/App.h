#pragma once
// The editor application: owns the window, the UI, the renderer, the Document (scene, camera
// path, settings, selection, undo) and the editor's state, wires the parts that act on them
// (FileActions, ViewportInput, Screenshots, ScriptRunner, the panels) and runs the frame loop:
// input, UI, the 3D render when something in it changed (ViewportRedraw), present, and a sleep
// while nothing happens (IdleWait). Panels edit the Document and the state they are given; the App
// turns their requests and the keyboard shortcuts into actions.

#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "EditorOptions.h"
#include "EditorState.h"
#include "FileActions.h"
#include "FrameLog.h"
#include "FrameTimer.h"
#include "IdleWait.h"
#include "ImGuiLayer.h"
#include "InteractiveScale.h"
#include "Log.h"
#include "PathEditing.h"
#include "RecentFiles.h"
#include "ReferenceViewer.h"
#include "Renderer.h"
#include "SceneUpload.h"
#include "Screenshots.h"
#include "Script.h"
#include "ScriptRunner.h"
#include "TransformGizmo.h"
#include "ViewportInput.h"
#include "ViewportRedraw.h"
#include "Window.h"
#include "gl/Objects.h"
#include "panels/HierarchyPanel.h"
#include "panels/InspectorPanel.h"
#include "panels/LogPanel.h"
#include "panels/MainMenu.h"
#include "panels/StatsOverlay.h"
#include "panels/TimelinePanel.h"
#include "scene/CameraView.h"

namespace lit::editor {

class App {
public:
    // Loads the scene, opens the window, checks the GL context and builds the renderer.
    // Throws (with a message meant for the user) when any of that fails; a scene that cannot
    // be loaded is fatal only in screenshot and script mode, otherwise the editor starts empty
    // and says why. `script`: the parsed --script file (Script.h), run one command per frame.
    explicit App(const EditorOptions& options, std::vector<ScriptCommand> script = {});
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // Runs until the user quits (or, in screenshot mode, until the capture is written; in script
    // mode, until the script ends, quits or fails). Returns the process exit code: 0, or 1 when
    // a script command failed.
    int run();

private:
    void resetCamera();
    void updateTitle();
    // Plays the camera path and the node animations (one clock) and, when looking through the
    // path, moves the fly camera along.
    void updatePlayback(double dtSeconds);
    // The viewport's render scale this frame: viewport_.renderScale when still, lower while
    // interacting so the frame time meets the target. `edited`: the camera, the scene or the
    // render settings differ from the last rendered frame's (ViewportRedraw::editedSinceRender).
    float renderScaleFor(double now, const glm::mat4& view, bool edited);
    // What the viewport's frame is rendered from, its render size aside: the camera, the render
    // settings, the scene's revisions and the overlay (markers, gizmo, path, selection, cones;
    // with `cleanViewport` only the cones of the cone directions view, for viewport screenshots).
    FrameInputs frameInputs(const CameraView& view, bool cleanViewport) const;
    // The GI work this frame may do: the refinement waits while interacting.
    GiBudget giBudget(double now) const;
    // Whether the frame loop may sleep before the next frame (IdleWait), and how long.
    double idleWaitSeconds(bool rendered);
    // Writes the screenshots due at this point of the frame (`withUi`: after the UI is drawn).
    void takeScreenshots(bool withUi, glm::ivec2 framebufferSize);
    void drawUi(glm::ivec2 renderSize);
    // The debug view's legend in the free viewport area's corner (and uiReport_).
    void drawViewLegend(std::string_view viewName);
    // The light whose shadow map the shadow map view shows: the selected one, else the setting's.
    int shownShadowLight() const;
    void carryOutMenuRequests(const MenuRequests& menu);
    void handleShortcuts();
    void logRefusal(const std::string& message);
    // Blits the renderer's output into `target` (x, y bottom-up, width, height; pixels).
    void presentViewport(glm::ivec2 framebufferSize, glm::ivec4 target);

    EditorOptions options_;
    // Declared before the window: the scene is loaded before there is one, and the log outlives
    // the GL context whose debug callback writes into it.
    Log log_;
    std::string sceneError_;  // shown in the UI until dismissed
    Document doc_;

    // Which panels are shown and the window size their positions were arranged for: kept in the
    // layout file (LayoutFile.h), so declared before the ImGui layer that writes them at exit.
    PanelVisibility visible_;
    glm::vec2 layoutDisplay_{0.0f};
    PanelVisibility layoutPanels_;  // visible_ as last marked for writing

    // GL context holders, in creation order (members are destroyed in reverse, so GL objects go
    // before ImGui, ImGui before the window, the window before glfwTerminate).
    GlfwLibrary glfw_;
    Window window_;
    std::optional<ImGuiLayer> imgui_;
    std::unique_ptr<Renderer> renderer_;  // created once the context is checked
    gl::Framebuffer blitSource_;          // reads the renderer's output texture for the blit
    ReferenceViewer referenceViewer_;     // Reference / Difference views (path tracer in the background)

    // Editor state edited by the panels, the input and the scripts.
    ViewportSettings viewport_;
    FlyCamera camera_;
    GizmoTool gizmoTool_;
    PathPlayback playback_;
    RecentFiles recent_;
    MainMenu mainMenu_;
    HierarchyPanel hierarchyPanel_;
    InspectorPanel inspectorPanel_;
    TimelinePanel timelinePanel_;
    LogPanel logPanel_;
    FrameTimer frameTimer_;
    std::optional<int> exitCode_;  // set when the loop should end

    // The parts that act on all of the above.
    SceneUpload sceneUpload_;
    FileActions files_;
    ViewportInput input_;
    Screenshots screenshots_;
    std::optional<ScriptRunner> script_;  // --script only
    FrameLog frameLog_;                   // --frame-log only

    // The free viewport area between the panels this frame, ImGui units: x, y, width, height.
    glm::vec4 viewportRect_{0.0f};
    ViewportUiReport uiReport_;  // where the viewport's UI was drawn, for the script's "layout"
    glm::vec2 lastDisplaySize_{0.0f};  // re-apply the panel layout when it changes
    std::string title_;                // the window title last set
    // Interactive render scale (ViewportSettings::interactiveFpsTarget): the scale the viewport
    // uses while the camera moves or a value is dragged, and the last frame's view to detect motion.
    InteractiveScale interactiveScale_;
    glm::mat4 lastView_{0.0f};
    bool cameraMoved_ = false;  // this frame's view differs from the last one's
    bool interacting_ = false;  // the camera moves or a value is dragged (renderScaleFor)
    // Redraw on demand (ViewportSettings::redrawOnDemand): the 3D frame renders only when its
    // inputs changed or work is pending; the loop sleeps when nothing happens at all.
    ViewportRedraw redraw_;
    IdleWait idleWait_;
    ViewportFrameInfo lastFrame_;     // the last frame, for the performance overlay
    bool previousRendered_ = false;   // the previous frame rendered the 3D image
    double lastRenderSeconds_ = 0.0;  // how long the last frame that rendered took, s
    // What a render costs, s: the last rendered frame that did not voxelize or inject (an edit's
    // GI work, seconds on opening a scene, would space the images that frames working on the GI
    // render far apart: ViewportRedraw::work). 0 until one.
    double renderEstimateSeconds_ = 0.0;
    std::optional<double> giUpdateSince_;  // glfwGetTime() when the GI update under way was first seen
    bool previousInjected_ = false;  // the previous frame rendered and voxelized or injected
    bool shadersReloaded_ = false;    // changed shader files were reloaded after the last frame
};

}  // namespace lit::editor
