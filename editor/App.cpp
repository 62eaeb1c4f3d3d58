#include "App.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupToLevel: Escape closes menus

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <utility>

#include "DebugViewLegend.h"
#include "EditorViews.h"
#include "EscapeKey.h"
#include "FlyController.h"
#include "GizmoChoice.h"
#include "LayoutFile.h"
#include "ProcessMemory.h"
#include "SceneEdits.h"
#include "ViewportOverlay.h"
#include "animation/NodeAnimation.h"
#include "gl/Capabilities.h"
#include "panels/CameraPanel.h"
#include "panels/ErrorPanel.h"
#include "panels/Layout.h"
#include "panels/LegendPanel.h"
#include "panels/RenderSettingsPanel.h"
#include "panels/StatsOverlay.h"
#include "panels/ViewportBar.h"

namespace lit::editor {

namespace {

// How often changed shader files are looked for, in seconds.
constexpr double kShaderReloadInterval = 0.5;
// How often the editor hands freed heap pages back to the system (ProcessMemory::releaseFreeHeap).
constexpr double kHeapReleaseInterval = 5.0;
// Longest time step given to the camera, in seconds: after a stall (loading a scene) the
// camera must not jump by the whole stall.
constexpr float kMaxCameraStep = 1.0f;
// How often a loading scene's progress window is refreshed while nothing else happens, s.
constexpr double kLoadingRefreshSeconds = 0.1;
// Window background where the renderer has not drawn (before the first frame): dark grey, sRGB.
constexpr float kBackground[4] = {0.08f, 0.08f, 0.09f, 1.0f};

#ifdef NDEBUG
constexpr bool kDebugContext = false;
#else
constexpr bool kDebugContext = true;
#endif

// The window's context is current: checks that it can run the renderer, sends its errors to the
// log, then builds the renderer.
std::unique_ptr<Renderer> createRenderer(Log& log) {
    gl::requireCapabilities();
    // In every build type: GL errors reach the log panel (and stderr) in release builds too.
    gl::installDebugOutput(log);
    gl::injectGlErrorIfRequested();  // LIT_TEST_GL_ERROR=1: the test that it reaches the log
    log.info("OpenGL " + gl::contextDescription());
    return std::make_unique<Renderer>(defaultShaderRoot(), log);
}

}  // namespace

App::App(const EditorOptions& options, std::vector<ScriptCommand> script)
    : options_(options),
      doc_(loadInitialDocument(options_, log_)),
      window_(options.width, options.height, "Lit editor", kDebugContext,
              /*vsync=*/!options.screenshot && !options.script),
      renderer_(createRenderer(log_)),
      blitSource_("editor viewport blit source"),
      sceneUpload_(*renderer_),
      files_({
          .options = options_,
          .doc = doc_,
          .log = log_,
          .sceneError = sceneError_,
          .recent = recent_,
          .menu = mainMenu_,
          .upload = sceneUpload_,
          .exitCode = exitCode_,
          .documentReplaced = [this] { resetCamera(); },
      }),
      input_(window_, doc_, camera_, viewport_, gizmoTool_, *renderer_, log_),
      screenshots_(*renderer_, doc_, log_, sceneError_) {
    imgui_.emplace(window_.handle());
    if (const auto layout = layoutFilePath(!options_.interactive(), [](const char* name) -> const char* { return std::getenv(name); }))
        if (const std::string error = imgui_->rememberLayout(*layout, visible_, layoutDisplay_); !error.empty())
            log_.warning(error);
    sceneUpload_.upload(doc_.scene);
    resetCamera();
    updateTitle();
    files_.start();
    if (options_.script)
        script_.emplace(std::move(script), options_.script->string(),
                        ScriptTarget{
                            .doc = doc_,
                            .camera = camera_,
                            .viewport = viewport_,
                            .panels = visible_,
                            .playback = playback_,
                            .gizmo = gizmoTool_,
                            .input = input_,
                            .files = files_,
                            .screenshots = screenshots_,
                            .renderer = *renderer_,
                            .ui = uiReport_,
                            .log = log_,
                            .exitCode = exitCode_,
                        });
}

void App::resetCamera() {
    const glm::ivec2 size = window_.framebufferSize();
    const float aspect = size.x > 0 && size.y > 0
                             ? static_cast<float>(size.x) / static_cast<float>(size.y)
                             : static_cast<float>(options_.width) / static_cast<float>(options_.height);
    // The scene's first camera if it has one, else a view framing the whole scene.
    const int cameraIndex = doc_.scene.cameras.empty() ? -1 : 0;
    const CameraView view = sceneCameraView(doc_.scene, cameraIndex, aspect);
    camera_.setFromView(view);
    camera_.speed = flySpeedForBounds(doc_.scene.worldBounds());
    // A jump to another view (a new document, "Reset to scene camera") is no motion: the next
    // frame renders at the full scale rather than lowered, then held for the grace period.
    lastView_ = glm::mat4(0.0f);
}

void App::updateTitle() {
    // "*" marks unsaved changes, as most editors do.
    const std::string name = doc_.file.empty() && doc_.scene.nodes.empty() ? std::string("no scene")
                             : doc_.file.empty()                           ? std::string("untitled")
                                                                           : doc_.file.filename().string();
    std::string title = "Lit editor - " + name + (doc_.dirty() ? "*" : "");
    if (title == title_) return;
    title_ = std::move(title);
    window_.setTitle(title_);
}

// ---- frame -------------------------------------------------------------------------------------

int App::run() {
    double previousTime = glfwGetTime();
    double nextShaderCheck = previousTime + kShaderReloadInterval;
    double nextHeapRelease = previousTime + kHeapReleaseInterval;
    int framesDrawn = 0;
    double waitSeconds = 0.0;  // how long this frame may wait for events first (IdleWait)
    while (!exitCode_) {
        // An idle editor sleeps until the window system has news or something is due; the
        // sleep is no part of the frame's work (camera step, frame time in the overlay).
        double slept = 0.0;
        if (waitSeconds > 0.0) {
            const double before = glfwGetTime();
            glfwWaitEventsTimeout(waitSeconds);
            slept = glfwGetTime() - before;
        } else {
            glfwPollEvents();
        }
        if (window_.shouldClose()) {
            // The close button: ask first when there are unsaved changes.
            window_.cancelClose();
            files_.requestQuit();
        }
        if (!options_.scriptMode()) files_.openDropped(window_.takeDroppedPaths());
        files_.finishLoading();
        // Script commands run before the frame so the frame shows their effect.
        if (script_) script_->step();
        if (exitCode_) break;

        const glm::ivec2 framebuffer = window_.framebufferSize();
        if (framebuffer.x <= 0 || framebuffer.y <= 0 || window_.iconified()) {
            // Minimised: nothing to draw into. Sleep until the window system has news instead
            // of spinning, and do not count the sleep as frame time.
            glfwWaitEvents();
            previousTime = glfwGetTime();
            continue;
        }
        const double now = glfwGetTime();
        const double frameSeconds = now - previousTime;  // the previous frame, with its sleep
        const double workSeconds = std::max(frameSeconds - slept, 0.0);
        previousTime = now;
        frameTimer_.add(workSeconds);
        if (previousRendered_) lastRenderSeconds_ = workSeconds;
        if (previousRendered_ && !previousInjected_) renderEstimateSeconds_ = workSeconds;

        imgui_->beginFrame();
        input_.updateFlyCamera(std::min(static_cast<float>(workSeconds), kMaxCameraStep));
        updatePlayback(workSeconds);
        input_.handleMouse(input_.currentView());
        const glm::ivec2 previousRenderSize{doc_.settings.output.width, doc_.settings.output.height};
        drawUi(previousRenderSize);
        // The playhead poses the animated nodes: played, scrubbed, or after an undo or a load put
        // the nodes' stored poses back. A changed pose bumps the geometry revision, as a gizmo
        // move does, so the frame below re-voxelizes.
        applyNodeAnimations(doc_.scene, playback_.time);
        // The 2D views fill the free area between the panels; the camera views the whole window
        // (the panels float over it).
        const glm::vec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
        const glm::vec2 toPixels = display.x > 0.0f && display.y > 0.0f ? glm::vec2(framebuffer) / display : glm::vec2(1.0f);
        glm::ivec4 target{0, 0, framebuffer.x, framebuffer.y};  // x, y (bottom-up), width, height in pixels
        if (isFlatView(doc_.settings.debug.view) && viewportRect_.z > 1.0f && viewportRect_.w > 1.0f) {
            const glm::vec2 size = glm::vec2(viewportRect_.z, viewportRect_.w) * toPixels;
            const glm::vec2 topLeft = glm::vec2(viewportRect_.x, viewportRect_.y) * toPixels;
            target = glm::ivec4(glm::round(topLeft.x), glm::round(static_cast<float>(framebuffer.y) - topLeft.y - size.y),
                                glm::max(glm::ivec2(glm::round(size)), glm::ivec2(1)));
        }
        sceneUpload_.syncStructure(doc_.scene, log_);
        const CameraView view = input_.currentView();
        FrameInputs inputs = frameInputs(view, screenshots_.cleanViewportDue());
        // Lowered while the camera moves or a value is dragged (ViewportSettings::interactiveFpsTarget).
        const float renderScale = renderScaleFor(now, view.view, redraw_.editedSinceRender(inputs));
        const glm::ivec2 renderSize =
            glm::max(glm::ivec2(glm::round(glm::vec2(target.z, target.w) * renderScale)), glm::ivec2(1));
        doc_.settings.output.width = inputs.settings.output.width = renderSize.x;
        doc_.settings.output.height = inputs.settings.output.height = renderSize.y;

        // Redraw on demand: render only when the inputs changed or work is still in flight.
        const GiBudget budget = giBudget(now);
        const FrameStats& stats = renderer_->stats();  // of the last rendered frame
        const PendingWork pending{
            .giUpdating = stats.giUpdateDone < 1.0f,
            .giRefining = stats.giRefining && budget.refineVoxels > 0,
            .playing = playback_.playing,
            .screenshot = screenshots_.cleanViewportDue(),
            .shadersReloaded = std::exchange(shadersReloaded_, false),
        };
        const RedrawReason reason = redraw_.decide(inputs, pending, viewport_.redrawOnDemand);
        // When the GI update after the last edit began (the first frame that saw it under way).
        if (!pending.giUpdating)
            giUpdateSince_.reset();
        else if (!giUpdateSince_)
            giUpdateSince_ = now;
        const double updateSecondsLeft =
            giUpdateSince_ ? giSecondsLeft(now - *giUpdateSince_, stats.giUpdateDone) : 0.0;
        const FrameWork work = redraw_.work(reason, now, renderEstimateSeconds_, updateSecondsLeft);
        const bool render = work == FrameWork::Render;
        if (render) {
            renderer_->setOverlay(inputs.overlay);
            renderer_->render(doc_.scene, view, inputs.settings, budget);
        } else if (work == FrameWork::GiOnly) {
            renderer_->advanceGi(doc_.scene, view, inputs.settings, budget);
            redraw_.advancedGi(renderer_->stats().giUpdateCompleted);
        } else {
            // The last frame's GPU timings arrive without a new frame to collect them.
            renderer_->profiler().poll();
        }
        // The reference tracer runs on its own thread: its image is refreshed either way.
        referenceViewer_.update(doc_.scene, view, inputs.settings, *renderer_);
        if (render) redraw_.rendered(std::move(inputs), reason, now);
        previousRendered_ = render;
        previousInjected_ = render && (renderer_->stats().injected || renderer_->stats().voxelized);
        lastFrame_ = {
            .renderScale = renderScale,
            .rendered = render,
            .giOnly = work == FrameWork::GiOnly,
            .reason = redrawReasonName(reason),
            .framesReused = render ? 0 : lastFrame_.framesReused + 1,
            .renderFrameMs = lastRenderSeconds_ * 1000.0,
            .giBudgetMs = std::max(static_cast<double>(viewport_.giMillisecondsPerFrame), 0.0),
        };
        if (options_.frameLog) {
            frameLog_.add({now, renderScale, renderSize, cameraMoved_});
            frameLog_.last().refinedVoxels = work != FrameWork::Show ? renderer_->stats().refinedVoxels : 0;
            frameLog_.last().rendered = render;
            frameLog_.last().giOnly = work == FrameWork::GiOnly;
            frameLog_.last().giUpdateDone = renderer_->stats().giUpdateDone;
            frameLog_.last().playhead = playback_.time;
            frameLog_.last().playing = playback_.playing;
            frameLog_.last().camera = camera_.position;
            frameLog_.last().selectedNode = doc_.selectedNode;
        }
        takeScreenshots(/*withUi=*/false, framebuffer);
        presentViewport(framebuffer, target);
        imgui_->render();
        takeScreenshots(/*withUi=*/true, framebuffer);
        ++framesDrawn;

        if (options_.screenshot && framesDrawn >= options_.frames) {
            Screenshots::saveWindow(framebuffer, *options_.screenshot);
            return 0;
        }
        window_.swapBuffers();
        updateTitle();
        files_.autosave(now);  // glfwGetTime: a steady clock

        if (now >= nextShaderCheck) {
            shadersReloaded_ = renderer_->reloadChangedShaders();
            nextShaderCheck = now + kShaderReloadInterval;
        }
        if (now >= nextHeapRelease) {
            ProcessMemory::releaseFreeHeap();
            nextHeapRelease = now + kHeapReleaseInterval;
        }
        waitSeconds = idleWaitSeconds(render);
    }
    files_.exiting(*exitCode_);
    if (options_.frameLog) {
        try {
            frameLog_.write(*options_.frameLog, glfwGetTime());
        } catch (const std::exception& error) {
            log_.error(std::string("frame log: ") + error.what());
        }
    }
    return *exitCode_;
}

FrameInputs App::frameInputs(const CameraView& view, bool cleanViewport) const {
    FrameInputs inputs{
        .camera = view,
        .settings = doc_.settings,
        .geometryRevision = doc_.scene.geometryRevision,
        .materialRevision = doc_.scene.materialRevision,
        .lightRevision = doc_.scene.lightRevision,
        .sceneUploads = sceneUpload_.uploads(),
        .overlay = {},
    };
    if (inputs.settings.debug.view == View::ShadowMap) inputs.settings.debug.shadowMapLight = shownShadowLight();
    // The shadow map and the voxel slice are 2D images, not the camera's view: world-space
    // markers and outlines would land on them at random.
    if (!isFlatView(doc_.settings.debug.view)) {
        const ImGuiIO& io = ImGui::GetIO();
        inputs.overlay = buildViewportOverlay(doc_, view, {io.DisplaySize.x, io.DisplaySize.y},
                                              input_.overlayOptions(cleanViewport));
    }
    return inputs;
}

int App::shownShadowLight() const {
    // The shadow map view follows the selected light; the saved setting stays as it was.
    if (doc_.selectedNode >= 0 && doc_.selectedNode < static_cast<int>(doc_.scene.nodes.size())) {
        const int light = doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)].light;
        if (light >= 0) return light;
    }
    return doc_.settings.debug.shadowMapLight;
}

GiBudget App::giBudget(double now) const {
    GiBudget budget{viewport_.giUpdateVoxelsPerFrame > 0 ? static_cast<std::uint32_t>(viewport_.giUpdateVoxelsPerFrame)
                                                         : GiBudget::kAll,
                    static_cast<std::uint32_t>(std::max(viewport_.giRefineVoxelsPerFrame, 0)),
                    std::max(static_cast<double>(viewport_.giMillisecondsPerFrame), 0.0)};
    // The cached mode's refinement (more cone sets per voxel after an update) improves light
    // that is already right and costs the same at any render scale: while the camera moves or a
    // value is dragged, and for the interactive scale's grace period after, it waits, so the
    // frame's time goes to the frame rate (the Cornell box at 1280×720 moved at 4-5 FPS while it
    // ran, 11-12 FPS without it: docs/PERFORMANCE.md, "Editor"), and it goes on when the view is
    // still.
    if (interacting_ || interactiveScale_.holding(now)) {
        budget.refineVoxels = 0;
        return budget;
    }
    // An update under way with nothing touched: the edit's light may take more of the frame
    // (ViewportSettings::giIdleMillisecondsPerFrame). Not the refinement, which runs for minutes
    // while the user works on.
    if (!imgui_->sawInput() && renderer_->stats().giUpdateDone < 1.0f)
        budget = budget.widenedTo(viewport_.giIdleMillisecondsPerFrame);
    return budget;
}

double App::idleWaitSeconds(bool rendered) {
    // Scripts and --screenshot run frame after frame; so does anything moving or converging.
    const bool busy = options_.scriptMode() || options_.screenshot || rendered || imgui_->sawInput() ||
                      ImGui::IsAnyItemActive() || input_.looking() || input_.gizmoDragging() || playback_.playing ||
                      shadersReloaded_;
    const double now = glfwGetTime();
    double wakeWithin = IdleWait::kMaxSeconds;
    // The full-size frame follows the grace period of the interactive scale without an event.
    if (interactiveScale_.holding(now)) wakeWithin = std::min(wakeWithin, interactiveScale_.graceLeft(now));
    // The reference image and a loading scene's progress change on other threads.
    if (referenceViewer_.accumulating()) wakeWithin = std::min(wakeWithin, ReferenceViewer::kRefreshSeconds);
    if (files_.loading()) wakeWithin = std::min(wakeWithin, kLoadingRefreshSeconds);
    return idleWait_.next(busy, wakeWithin);
}

float App::renderScaleFor(double now, const glm::mat4& view, bool edited) {
    // The first frame has no view to compare with: it does not count as a motion.
    const bool moving = view != lastView_ && lastView_ != glm::mat4(0.0f);
    lastView_ = view;
    cameraMoved_ = moving;
    // Scripts (unless "interactive on") and screenshots render what they ask for, at the chosen scale.
    const bool scripted = script_ && !script_->interactive();
    // A value dragged counts while it changes what is rendered: a click on a button or a row
    // is active too, and must not drop the scale for nothing.
    const bool dragging = edited && (ImGui::IsAnyItemActive() || input_.gizmoDragging());
    const bool interacting = !scripted && !options_.screenshot && (moving || dragging);
    interacting_ = interacting;
    return interactiveScale_.next({
        .full = viewport_.renderScale,
        .interacting = interacting,
        .targetFps = viewport_.interactiveFpsTarget,
        .now = now,
        .lastRenderSeconds = lastRenderSeconds_,
        .previousRendered = previousRendered_,
    });
}

void App::updatePlayback(double dtSeconds) {
    if (!playback_.playing) return;
    playback_.advance(doc_.cameraPath, dtSeconds, summarizeNodeAnimations(doc_.scene).endTime);
    if (!playback_.lookThrough) return;
    lookThroughPath(doc_.cameraPath, playback_.time, camera_);
}

void App::takeScreenshots(bool withUi, glm::ivec2 framebufferSize) {
    // Only a script's shot returns its failure, which fails the script.
    if (auto failure = screenshots_.take(withUi, framebufferSize); failure && script_)
        script_->fail(failure->command, failure->message);
}

// ---- UI ----------------------------------------------------------------------------------------

void App::drawUi(glm::ivec2 renderSize) {
    const std::string viewName(currentViewName(doc_.settings.debug.view, viewport_.coneDirections));
    float menuHeight = 0.0f;
    const MenuContext menuContext{
        .recent = recent_,
        .currentScene = doc_.file.empty() ? std::filesystem::path("untitled.gltf") : doc_.file,
        .documentFile = doc_.file,
        .undoLabel = doc_.undoLabel(),
        .redoLabel = doc_.redoLabel(),
        .currentView = viewName,
        .hasSelection = !doc_.selection().empty(),
    };
    const MenuRequests menu = mainMenu_.draw(visible_, menuContext, menuHeight);

    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const bool firstFrame = lastDisplaySize_ == glm::vec2(0.0f);
    const bool resized = display.x != lastDisplaySize_.x || display.y != lastDisplaySize_.y;
    lastDisplaySize_ = {display.x, display.y};
    // After a resize every panel goes to its place, and on the first frame too unless the layout
    // file holds an arrangement made for this window size; otherwise only panels appearing for
    // the first time do, and the user's arrangement stays.
    const bool keepRemembered = firstFrame && layoutDisplay_ == glm::vec2(display.x, display.y);
    const PanelLayout layout = computePanelLayout(display, menuHeight, cameraPanelHeight(),
                                                  resized && !keepRemembered ? ImGuiCond_Always : ImGuiCond_FirstUseEver);

    if (visible_.hierarchy) hierarchyPanel_.draw(doc_, camera_.right(), layout.hierarchy, &visible_.hierarchy);
    if (visible_.inspector) inspectorPanel_.draw(doc_, layout.inspector, &visible_.inspector);
    uiReport_.stats = visible_.stats ? drawStatsOverlay(frameTimer_, renderer_->profiler(), renderer_->stats(), renderSize,
                                                        imgui_->monoFont(), layout.stats, &visible_.stats,
                                                        &visible_.statsDetails, renderer_->voxels(), lastFrame_)
                                     : glm::vec4(0.0f);
    if (visible_.renderSettings) {
        const RenderSettingsRequests requests =
            drawRenderSettingsPanel(doc_.settings, viewport_, static_cast<int>(doc_.scene.lights.size()),
                                    layout.renderSettings, &visible_.renderSettings);
        // The renderer redoes the voxels when the geometry revision moves; nothing is edited.
        if (requests.revoxelize) ++doc_.scene.geometryRevision;
        if (!viewport_.coneDirections) input_.forgetConeSurface();
    }
    if (visible_.timeline) timelinePanel_.draw(doc_, playback_, camera_, layout.timeline, &visible_.timeline);
    if (visible_.camera && drawCameraPanel(camera_, layout.camera, &visible_.camera).resetToSceneCamera) resetCamera();
    if (visible_.log) logPanel_.draw(log_, imgui_->monoFont(), layout.log, &visible_.log);
    viewportRect_ = drawViewportBar(menuHeight, gizmoTool_, input_.gizmoMode(),
                                    scaleAppliesTo(doc_.scene, doc_.selectedNode), viewName, doc_.selection().size());
    input_.setVisibleArea(viewportRect_);
    drawViewLegend(viewName);
    constexpr float kViewportMargin = 8.0f;
    referenceViewer_.drawWindow(ImVec2(viewportRect_.x + viewportRect_.z - kViewportMargin, viewportRect_.y + kViewportMargin),
                                resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver);
    drawErrorPanel(sceneError_, display, menuHeight);
    files_.drawLoadingWindow();
    // An edit opened by a widget that never reported its deactivation (a colour picker popup)
    // ends once nothing is being dragged or typed into.
    if (doc_.editOpen() && !ImGui::IsAnyItemActive() && !input_.gizmoDragging()) doc_.endEdit();

    handleShortcuts();
    files_.drawQuestions();
    carryOutMenuRequests(menu);
    // A panel shown or hidden (menu, F2, a close button, the legend's x) is written to the
    // layout file within seconds, not only at exit.
    if (visible_ != layoutPanels_) {
        ImGuiLayer::layoutChanged();
        layoutPanels_ = visible_;
    }
}

void App::drawViewLegend(std::string_view viewName) {
    const VoxelVolume* voxels = renderer_->shownVoxels(doc_.settings);
    std::vector<LegendVolume> levels;
    if (doc_.settings.debug.view == View::VoxelLevels)
        for (const VoxelVolume* v : renderer_->voxelLevels(doc_.settings))
            levels.push_back({v->resolution(), v->mipCount(), v->voxelSize()});
    ViewLegend legend = describeDebugView({
        .view = viewName,
        .settings = doc_.settings,
        .scene = doc_.scene,
        .exposureEv = renderer_->exposureEv(doc_.settings),
        .shadowMapLight = shownShadowLight(),
        .volume = voxels ? LegendVolume{voxels->resolution(), voxels->mipCount(), voxels->voxelSize()} : LegendVolume{},
        .levels = std::move(levels),
        .coneSurfacePicked = input_.overlayOptions(false).coneSurface.has_value(),
    });
    // The Difference view's own window carries its colour bar; the view's legend would describe
    // the picture the difference replaced.
    if (referenceViewer_.mode() == ReferenceMode::Difference) legend = {};
    uiReport_.area = viewportRect_;
    uiReport_.legendText = legendText(legend);
    uiReport_.legend = glm::vec4(0.0f);
    if (!visible_.legend) return;
    const LegendBox box =
        drawLegend(legend, doc_.settings.debug, voxels ? voxels->mipCount() : 0, viewportRect_, &visible_.legend);
    uiReport_.legend = box.rect;
}

void App::carryOutMenuRequests(const MenuRequests& menu) {
    if (menu.undo) doc_.undo();
    if (menu.redo) doc_.redo();
    if (menu.save) files_.saveOrAskForName();
    if (menu.saveAs) files_.saveAs(*menu.saveAs);
    if (menu.saveAsCancelled) files_.saveAsCancelled();
    if (menu.screenshot) screenshots_.requestTimestamped(/*withUi=*/false, 0);
    // One frame later, once the menu that was clicked has closed.
    if (menu.screenshotWithUi) screenshots_.requestTimestamped(/*withUi=*/true, 1);
    if (menu.quit) files_.requestQuit();
    if (menu.open) files_.requestOpen(*menu.open);
    if (menu.add) addNodeInFront(doc_, *menu.add, camera_.position, camera_.forward());
    if (menu.deleteSelection) logRefusal(deleteSelection(doc_));
    if (menu.duplicateSelection) logRefusal(duplicateSelection(doc_, camera_.right()));
    if (menu.frameSelection) input_.frameSelection();
    if (menu.view) input_.setView(*menu.view);
    logRefusal(std::exchange(doc_.lastRefusal, {}));
}

void App::handleShortcuts() {
    // Only when no text field, dragged widget or modal dialog has the keyboard.
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard || files_.asking()) return;
    // ImGui 1.86 indexes keys by the backend's codes (GLFW's); repeats are not wanted here.
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, /*repeat=*/false); };
    if (io.KeyCtrl && pressed(GLFW_KEY_S)) files_.saveOrAskForName();
    if (io.KeyCtrl && !io.KeyShift && pressed(GLFW_KEY_Z)) doc_.undo();
    if (io.KeyCtrl && ((io.KeyShift && pressed(GLFW_KEY_Z)) || pressed(GLFW_KEY_Y))) doc_.redo();
    if (pressed(GLFW_KEY_F12)) screenshots_.requestTimestamped(/*withUi=*/false, 0);
    if (pressed(GLFW_KEY_F2)) visible_.stats = !visible_.stats;
    const double animationEnd = summarizeNodeAnimations(doc_.scene).endTime;
    if (pressed(GLFW_KEY_SPACE) && hasTimeline(doc_.cameraPath, animationEnd)) {
        if (playback_.playing)
            playback_.playing = false;
        else
            playback_.play(doc_.cameraPath, animationEnd);
    }
    if (pressed(GLFW_KEY_ESCAPE)) {
        const bool popupOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
        if (escapeAction(popupOpen) == EscapeAction::ClosePopups)
            ImGui::ClosePopupToLevel(0, /*restore_focus_to_window_under_popup=*/true);
        else
            doc_.select(-1);
    }
    if (io.KeyCtrl && pressed(GLFW_KEY_D)) logRefusal(duplicateSelection(doc_, camera_.right()));
    // Editing keys; while the right mouse button is held the letters fly the camera instead.
    if (input_.looking() || io.KeyCtrl || io.KeyAlt) return;
    if (pressed(GLFW_KEY_DELETE) || pressed(GLFW_KEY_X)) logRefusal(deleteSelection(doc_));
    if (pressed(GLFW_KEY_W)) gizmoTool_.mode = GizmoMode::Translate;
    if (pressed(GLFW_KEY_E)) gizmoTool_.mode = GizmoMode::Rotate;
    if (pressed(GLFW_KEY_R)) gizmoTool_.mode = GizmoMode::Scale;
    if (pressed(GLFW_KEY_T))
        gizmoTool_.space = gizmoTool_.space == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
    if (pressed(GLFW_KEY_F)) input_.frameSelection();
    for (int digit = 0; digit <= 9; ++digit)
        if (pressed(GLFW_KEY_0 + digit))
            if (const EditorView* view = editorViewForKey(digit, io.KeyShift)) input_.setView(std::string(view->name));
}

void App::logRefusal(const std::string& message) {
    if (!message.empty()) log_.warning(message);
}

void App::presentViewport(glm::ivec2 framebufferSize, glm::ivec4 target) {
    // Draw into the window's back buffer, over all of it, whatever state the passes left.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferSize.x, framebufferSize.y);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // The output texture already holds sRGB-encoded values. With GL_FRAMEBUFFER_SRGB off a blit
    // neither decodes the source nor encodes into the (sRGB-capable) window, so the encoded
    // values are copied unchanged, and ImGui's sRGB-authored colours are drawn as they are.
    glDisable(GL_FRAMEBUFFER_SRGB);
    const gl::Texture& output = referenceViewer_.output() ? *referenceViewer_.output() : renderer_->outputTexture();
    // Cleared only where the image does not cover the window (a 2D view, no image yet): a clear
    // of the whole window costs 0.5-1 ms on llvmpipe, in every frame.
    if (!output || target != glm::ivec4(0, 0, framebufferSize.x, framebufferSize.y))
        glClearNamedFramebufferfv(0, GL_COLOR, 0, kBackground);
    if (!output) return;
    // Attached every frame: the renderer recreates the texture on resize, and a deleted texture
    // can come back under the same name.
    blitSource_.attach(GL_COLOR_ATTACHMENT0, output);
    glNamedFramebufferReadBuffer(blitSource_.id(), GL_COLOR_ATTACHMENT0);
    const glm::ivec2 source{output.desc().width, output.desc().height};
    const GLenum filter = source == glm::ivec2(target.z, target.w) ? GL_NEAREST : GL_LINEAR;
    glBlitNamedFramebuffer(blitSource_.id(), 0, 0, 0, source.x, source.y, target.x, target.y, target.x + target.z,
                           target.y + target.w, GL_COLOR_BUFFER_BIT, filter);
}

}  // namespace lit::editor
