#pragma once
// The editor application: owns the window, the UI, the renderer and the Document (scene, camera
// path, settings, selection, undo), and runs the frame loop. Panels edit the Document and the
// editor state they are given; the App turns their requests (open, save, quit, screenshot)
// into actions, asks before unsaved changes are lost, runs --script files, and is the only
// place that talks to GL directly (presenting the renderer's output to the window).

#include <filesystem>
#include <future>
#include <mutex>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "DocumentIO.h"
#include "EditorOptions.h"
#include "ReferenceViewer.h"
#include "EditorState.h"
#include "FrameTimer.h"
#include "ImGuiLayer.h"
#include "InteractiveScale.h"
#include "Log.h"
#include "RecentFiles.h"
#include "Renderer.h"
#include "PathEditing.h"
#include "Script.h"
#include "EditorViews.h"
#include "LoadStages.h"
#include "SceneEdits.h"
#include "TransformGizmo.h"
#include "Window.h"
#include "gl/Objects.h"
#include "panels/Dialogs.h"
#include "panels/HierarchyPanel.h"
#include "panels/InspectorPanel.h"
#include "panels/LogPanel.h"
#include "panels/MainMenu.h"
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
    ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // Runs until the user quits (or, in screenshot mode, until the capture is written; in script
    // mode, until the script ends, quits or fails). Returns the process exit code: 0, or 1 when
    // a script command failed.
    int run();

private:
    // An action that waits for the answer to "save changes?".
    struct PendingAction {
        enum class Kind { None, Quit, Open } kind = Kind::None;
        std::filesystem::path file;  // Open: the scene to open
    };
    struct ScreenshotRequest {
        std::filesystem::path file;
        bool withUi = false;
        int delayFrames = 0;                   // frames to let pass first (a menu must close)
        std::optional<ScriptCommand> command;  // the script line that asked, for error messages
    };

    bool scriptMode() const { return options_.script.has_value(); }
    // A person at the window (neither --script nor --screenshot): scenes load in the background,
    // autosave runs, questions are asked.
    bool interactive() const { return !options_.script && !options_.screenshot; }
    // What a scene this session opens may make the loader read (--allow-external-uris).
    GltfLimits loadLimits() const {
        GltfLimits limits;
        limits.allowExternalUris = options_.allowExternalUris;
        return limits;
    }
    Document loadInitialDocument();

    // ---- files -----------------------------------------------------------------------------
    // Open/quit as the user asks: with unsaved changes (and not in a script) ask first.
    void requestOpen(const std::filesystem::path& path);
    void requestQuit();
    void askAboutUnsavedChanges(PendingAction action);
    void answerUnsavedChanges(Answer answer);
    void carryOut(PendingAction action);
    // Open without asking. Returns "" or the error, which is also shown and logged; on error
    // the current document stays. Interactively the file loads on a worker thread (startLoading)
    // while the UI shows its progress; scripts and screenshots load at once.
    std::string openScene(const std::filesystem::path& path);
    void startLoading(const std::filesystem::path& path);
    // Once the worker is done: takes its document (or shows its error).
    void finishLoading();
    void drawLoadingWindow();
    // Makes `loaded` the document: uploads it (falls back to an empty one when that fails).
    std::string adoptDocument(Document loaded, const std::filesystem::path& path);
    // Save to `path` (Save As) or the document's file. Returns "" or the error, which is also
    // shown and logged; a failed save changes nothing on disk or in the document.
    std::string saveTo(const std::filesystem::path& path);
    void saveOrAskForName();
    void offerRecovery();
    void answerRecovery(Answer answer);
    void handleDroppedFiles();
    void resetCamera();
    void updateTitle();

    // ---- frame -----------------------------------------------------------------------------
    void updateCamera(float dtSeconds);
    // Left mouse in the viewport: grab and drag the gizmo, else select what is under the cursor
    // (or, with the cone directions view, pick the pixel whose cones to draw).
    void handleViewportMouse(const CameraView& view);
    // Gizmo drags (mouse and script "drag"): grab the handle under `mouse`, follow it, let go.
    // beginGizmoDrag returns false when no handle is there.
    bool beginGizmoDrag(const CameraView& view, glm::vec2 mouse);
    void continueGizmoDrag(const CameraView& view, glm::vec2 mouse, bool snap);
    void endGizmoDrag();
    // The edits of the menus, keys and scripts that need the camera or the renderer.
    void addNodeInFront(NodeKind kind);
    void frameSelection();
    std::string setView(const std::string& name);  // an EditorViews.h name
    void logRefusal(const std::string& message);
    // Rebuilds the renderer's GPU copy when nodes, meshes or materials were added or removed (a
    // structural edit, or its undo): the GpuScene's draw items are per node and primitive.
    void syncRendererStructure();
    // The mode / space / snap bar and the current view's name, in the bottom-right corner of
    // the free viewport area; computes viewportRect_.
    void drawViewportBar(float menuHeight);
    // The 2D views (shadow map, voxel slice) are drawn into the free viewport area between the
    // panels rather than the whole window.
    bool flatView() const;
    // Window pixel (top-left origin) → the renderer's last frame: select its node, or sample its
    // surface for the cone directions view. Returns "" or why nothing could be picked.
    std::string pickAt(glm::vec2 windowPixel);
    // Plays the camera path and, when looking through it, moves the fly camera along.
    void updatePlayback(double dtSeconds);
    // Markers, gizmo, path, selection and cones for this frame, handed to the renderer; with
    // `cleanViewport` only the cones of the cone directions view (for viewport screenshots).
    void updateOverlay(const CameraView& view, bool cleanViewport);
    CameraView currentView() const;
    void handleShortcuts();
    void drawUi(glm::ivec2 renderSize);
    // Blits the renderer's output into `target` (x, y bottom-up, width, height; pixels).
    void presentViewport(glm::ivec2 framebufferSize, glm::ivec4 target);
    void saveScreenshot(glm::ivec2 framebufferSize, const std::filesystem::path& path);
    void saveViewportScreenshot(const std::filesystem::path& path);
    // Writes the requests due this frame (`withUi` ones after the UI is drawn); returns false
    // when a script's screenshot failed (the App is then exiting with status 1).
    void takeScreenshots(bool withUi, glm::ivec2 framebufferSize);
    void requestTimestampedScreenshot(bool withUi, int delayFrames);

    // ---- scripts ---------------------------------------------------------------------------
    // Runs the next command unless waiting; sets exitCode_ at the end, on quit or on an error.
    void runScriptStep();
    // Returns "" or the error message for the command's line.
    std::string runScriptCommand(const ScriptCommand& command);
    void failScript(const ScriptCommand& command, const std::string& message);

    EditorOptions options_;
    // Declared before the window: the scene is loaded before there is one (loadInitialDocument()
    // may use only the members above doc_), and the log outlives the GL context whose debug
    // callback writes into it.
    Log log_;
    std::string sceneError_;  // shown in the UI until dismissed
    Document doc_;

    // GL context holders, in creation order (members are destroyed in reverse, so GL objects go
    // before ImGui, ImGui before the window, the window before glfwTerminate).
    GlfwLibrary glfw_;
    Window window_;
    std::optional<ImGuiLayer> imgui_;
    std::unique_ptr<Renderer> renderer_;
    gl::Framebuffer blitSource_;  // reads the renderer's output texture for the blit
    ReferenceViewer referenceViewer_;  // Reference / Difference views (path tracer in the background)

    // Editor state edited by the panels.
    PanelVisibility visible_;
    ViewportSettings viewport_;
    FlyCamera camera_;
    RecentFiles recent_;
    MainMenu mainMenu_;
    HierarchyPanel hierarchyPanel_;
    InspectorPanel inspectorPanel_;
    TimelinePanel timelinePanel_;
    PathPlayback playback_;
    TransformGizmo gizmo_;
    int hoveredGizmoAxis_ = -1;
    GizmoMode gizmoMode_ = GizmoMode::Translate;
    GizmoSpace gizmoSpace_ = GizmoSpace::World;
    GizmoSnap snap_;  // snap_.enabled: always on; Ctrl snaps during a drag either way
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
    // What the renderer's GpuScene was built from: per node its mesh, per mesh its primitives'
    // materials, and the material count (syncRendererStructure).
    std::vector<int> uploadedStructure_;
    // The free viewport area between the panels this frame, ImGui units: x, y, width, height.
    glm::vec4 viewportRect_{0.0f};
    // Cone directions view: the surface last clicked and where the camera was then.
    std::optional<SurfaceSample> coneSurface_;
    glm::vec3 coneCameraPosition_{0.0f};
    LogPanel logPanel_;
    FrameTimer frameTimer_;
    QuestionDialog unsavedQuestion_;
    QuestionDialog recoverQuestion_;
    PendingAction pending_;
    bool saveAsForPending_ = false;  // the Save As dialog was opened by "Save" in the question
    // Periodic copies of the document, offered after a crash. Not in script mode: a script must
    // neither be interrupted by an old crash's offer nor leave copies behind.
    std::optional<Autosave> autosave_;
    std::string lastAutosaveError_;  // logged once when it changes
    std::vector<ScreenshotRequest> screenshots_;

    // Script state.
    std::vector<ScriptCommand> script_;
    std::string scriptSource_;  // the script file, as error messages name it
    std::size_t scriptNext_ = 0;
    int scriptWaitFrames_ = 0;  // frames still to let pass before the next command
    // wait gi / wait refined: frames still allowed for the GI update (with "refined", and then its
    // refinement rounds: ~180 frames at 128³ with the editor's budget) to finish (0: not waiting).
    static constexpr int kScriptGiWaitFrames = 2000;
    static constexpr int kScriptRefineWaitFrames = 20000;
    int scriptWaitForGi_ = 0;
    bool scriptWaitForRefinement_ = false;

    // A scene loading on a worker thread; its progress is written there and read by the UI.
    struct LoadStatus {
        std::mutex mutex;
        LoadProgress progress;
    };
    struct Loading {
        std::filesystem::path file;
        std::shared_ptr<LoadStatus> status;
        std::future<Document> result;
        double startSeconds = 0.0;
        bool uploading = false;  // the worker is done; the GPU upload runs after one more frame
    };
    std::optional<Loading> loading_;
    bool recoveryAfterLoad_ = false;  // offer the autosave once the initial scene is in

    std::optional<int> exitCode_;  // set when the loop should end
    std::string title_;            // the window title last set

    // Input and layout bookkeeping.
    bool looking_ = false;             // right mouse drag in progress
    // Interactive render scale (RenderSettings::interactiveFpsTarget): the scale the viewport uses
    // while the camera moves or a value is dragged, and the last frame's view to detect motion.
    InteractiveScale interactiveScale_;
    float frameScale_ = 1.0f;           // the render scale of the last frame (for the overlay)
    glm::mat4 lastView_{0.0f};
    bool cameraMoved_ = false;          // this frame's view differs from the last one's
    bool interacting_ = false;          // the camera moves or a value is dragged (renderScaleFor)
    bool scriptInteractive_ = false;    // script command "interactive on"
    // --frame-log: one row per rendered frame, written at exit.
    struct FrameLogRow {
        double start = 0.0;  // s, glfwGetTime() when the frame began
        float renderScale = 1.0f;
        glm::ivec2 renderSize{0};
        bool cameraMoved = false;
        std::uint32_t refinedVoxels = 0;  // FrameStats::refinedVoxels of the frame
    };
    std::vector<FrameLogRow> frameLog_;
    void writeFrameLog(double end);
    // The viewport's render scale this frame: viewport_.renderScale when still, lower while
    // interacting so the frame time meets the target.
    float renderScaleFor(double frameSeconds, const glm::mat4& view);
    glm::dvec2 lastCursor_{0.0};       // screen coordinates
    glm::vec2 lastDisplaySize_{0.0f};  // re-apply the panel layout when it changes
};

}  // namespace lit::editor
