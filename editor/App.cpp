#include "App.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "FlyController.h"
#include "ProcessMemory.h"
#include "Properties.h"
#include "ScreenshotNames.h"
#include "SettingCommand.h"
#include "TextParse.h"
#include "ViewportOverlay.h"
#include "gl/Capabilities.h"
#include "image/ImageIO.h"
#include "io/AtomicFile.h"
#include "panels/CameraPanel.h"
#include "panels/ErrorPanel.h"
#include "panels/Layout.h"
#include "panels/RenderSettingsPanel.h"
#include "panels/StatsOverlay.h"
#include "scene/SceneBuilder.h"

namespace lit::editor {

namespace {

// How often changed shader files are looked for, in seconds.
constexpr double kShaderReloadInterval = 0.5;
// How often the editor hands freed heap pages back to the system (ProcessMemory::releaseFreeHeap).
constexpr double kHeapReleaseInterval = 5.0;
// Longest time step given to the camera, in seconds: after a stall (loading a scene) the
// camera must not jump by the whole stall.
constexpr float kMaxCameraStep = 1.0f;
// Window background where the renderer has not drawn (before the first frame): dark grey, sRGB.
constexpr float kBackground[4] = {0.08f, 0.08f, 0.09f, 1.0f};
// Where F12 and the File menu put screenshots, relative to the working directory.
constexpr const char* kScreenshotFolder = "screenshots";

#ifdef NDEBUG
constexpr bool kDebugContext = false;
#else
constexpr bool kDebugContext = true;
#endif

bool isSceneFile(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

std::string displayName(const std::filesystem::path& file) {
    return file.empty() ? std::string("untitled") : file.filename().string();
}

// What the renderer's GpuScene depends on besides transforms and material values: the nodes'
// meshes, the meshes' primitives' materials and the material count (App::syncRendererStructure).
std::vector<int> structureOf(const Scene& scene) {
    std::vector<int> structure;
    structure.reserve(scene.nodes.size() + scene.meshes.size() * 2 + 4);
    structure.push_back(static_cast<int>(scene.nodes.size()));
    for (const Node& node : scene.nodes) structure.push_back(node.mesh);
    structure.push_back(static_cast<int>(scene.meshes.size()));
    for (const Mesh& mesh : scene.meshes) {
        structure.push_back(static_cast<int>(mesh.primitives.size()));
        for (const Primitive& p : mesh.primitives) structure.push_back(p.material);
    }
    structure.push_back(static_cast<int>(scene.materials.size()));
    return structure;
}

void createParentFolder(const std::filesystem::path& file) {
    const std::filesystem::path parent = file.parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
}

}  // namespace

App::App(const EditorOptions& options, std::vector<ScriptCommand> script)
    : options_(options),
      doc_(loadInitialDocument()),
      window_(options.width, options.height, "Lit editor", kDebugContext,
              /*vsync=*/!options.screenshot && !options.script),
      script_(std::move(script)),
      scriptSource_(options.script ? options.script->string() : std::string()) {
    // The window's context is current from here on.
    gl::requireCapabilities();
    // In every build type: GL errors reach the log panel (and stderr) in release builds too.
    gl::installDebugOutput(log_);
    gl::injectGlErrorIfRequested();  // LIT_TEST_GL_ERROR=1: the test that it reaches the log
    log_.info("OpenGL " + gl::contextDescription());
    renderer_ = std::make_unique<Renderer>(defaultShaderRoot(), log_);
    imgui_.emplace(window_.handle());
    blitSource_ = gl::Framebuffer("editor viewport blit source");
    renderer_->setScene(doc_.scene);
    uploadedStructure_ = structureOf(doc_.scene);
    std::optional<std::filesystem::path> initialLoad;
    if (interactive()) initialLoad = options_.scene.value_or(defaultScenePath());
    if (sceneError_.empty() && !initialLoad) recent_.add(options_.scene.value_or(defaultScenePath()));
    resetCamera();
    updateTitle();
    if (interactive()) {
        autosave_.emplace();
        // A recovered copy must not be replaced by the scene still loading: ask once it is in.
        if (initialLoad) recoveryAfterLoad_ = true; else offerRecovery();
    }
    if (initialLoad) startLoading(*initialLoad);
}

App::~App() {
    // Give the cursor back if the editor closes in the middle of a right-drag.
    if (looking_) glfwSetInputMode(window_.handle(), GLFW_CURSOR, GLFW_CURSOR_NORMAL);
}

// Runs in the member initialiser list: only members declared before doc_ exist yet.
Document App::loadInitialDocument() {
    const std::filesystem::path path = options_.scene.value_or(defaultScenePath());
    // Interactively the window opens at once and the scene loads behind a progress bar (the
    // constructor starts it: members after doc_ do not exist yet here).
    if (interactive()) return Document{};
    try {
        Document doc = openDocument(path, log_, {}, loadLimits());
        log_.info("opened scene " + path.string());
        return doc;
    } catch (const std::exception& error) {
        // Screenshot and script runs exist to check a scene: fail loudly. Interactively, start
        // empty and let the user open another file.
        if (!interactive()) throw;
        sceneError_ = error.what();
        log_.error(sceneError_);
        return Document{};
    }
}

// ---- files -------------------------------------------------------------------------------------

void App::requestOpen(const std::filesystem::path& path) {
    if (scriptMode() || !doc_.dirty()) {
        openScene(path);
        return;
    }
    askAboutUnsavedChanges({PendingAction::Kind::Open, path});
}

void App::requestQuit() {
    if (scriptMode() || !doc_.dirty()) {
        exitCode_ = 0;
        return;
    }
    askAboutUnsavedChanges({PendingAction::Kind::Quit, {}});
}

void App::askAboutUnsavedChanges(PendingAction action) {
    pending_ = std::move(action);
    const std::string name = displayName(doc_.file);
    const std::string before = pending_.kind == PendingAction::Kind::Quit
                                   ? "before quitting"
                                   : "before opening " + pending_.file.filename().string();
    unsavedQuestion_.ask({"Unsaved changes", name + " has unsaved changes. Save them " + before + "?", "Save",
                          "Discard", /*cancellable=*/true});
}

void App::answerUnsavedChanges(Answer answer) {
    switch (answer) {
    case Answer::None: return;
    case Answer::Cancel: pending_ = {}; return;
    case Answer::No: carryOut(std::exchange(pending_, {})); return;
    case Answer::Yes:
        if (doc_.file.empty()) {
            // No file yet: the Save As dialog finishes the job (or its Cancel drops it).
            saveAsForPending_ = true;
            mainMenu_.askSaveAs("untitled.gltf");
            return;
        }
        // A failed save loses nothing: the error is shown and the action is dropped.
        if (saveTo(doc_.file).empty()) carryOut(std::exchange(pending_, {}));
        else pending_ = {};
        return;
    }
}

void App::carryOut(PendingAction action) {
    switch (action.kind) {
    case PendingAction::Kind::None: break;
    case PendingAction::Kind::Quit: exitCode_ = 0; break;
    case PendingAction::Kind::Open: openScene(action.file); break;
    }
}

std::string App::openScene(const std::filesystem::path& path) {
    if (interactive()) {
        startLoading(path);
        return "";
    }
    Document loaded;
    try {
        loaded = openDocument(path, log_, {}, loadLimits());
    } catch (const std::exception& error) {
        sceneError_ = error.what();
        log_.error(sceneError_);
        return sceneError_;  // the current document stays
    }
    return adoptDocument(std::move(loaded), path);
}

void App::startLoading(const std::filesystem::path& path) {
    if (loading_) {
        log_.warning("still loading " + loading_->file.filename().string() + "; open " + path.filename().string() +
                     " when it is done");
        return;
    }
    Loading loading;
    loading.file = path;
    loading.status = std::make_shared<LoadStatus>();
    loading.startSeconds = glfwGetTime();
    // The worker gets its own copies: the path, the status it reports into, and the log, which
    // is thread-safe. The Document comes back through the future (or its exception does).
    loading.result = std::async(std::launch::async, [path, status = loading.status, &log = log_, limits = loadLimits()] {
        return openDocument(
            path, log,
            [status](const LoadProgress& progress) {
                const std::lock_guard lock(status->mutex);
                status->progress = progress;
            },
            limits);
    });
    loading_ = std::move(loading);
    log_.info("loading " + path.string());
}

void App::finishLoading() {
    if (!loading_ || loading_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    if (!loading_->uploading) {
        // The upload (Renderer::setScene) blocks this thread: show its stage for one frame first.
        loading_->uploading = true;
        const std::lock_guard lock(loading_->status->mutex);
        loading_->status->progress = {"upload", 0, 1};
        return;
    }
    Loading loading = std::move(*loading_);
    loading_.reset();
    try {
        adoptDocument(loading.result.get(), loading.file);
    } catch (const std::exception& error) {
        sceneError_ = error.what();
        log_.error(sceneError_);  // the current document stays
    }
    if (std::exchange(recoveryAfterLoad_, false)) offerRecovery();
}

void App::drawLoadingWindow() {
    if (!loading_) return;
    LoadProgress progress;
    {
        const std::lock_guard lock(loading_->status->mutex);
        progress = loading_->status->progress;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f), ImGuiCond_Always);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize;
    if (ImGui::Begin("Loading", nullptr, kFlags)) {
        ImGui::Text("Loading %s", loading_->file.filename().string().c_str());
        // Each stage with its own bar (done, running, waiting), then the whole load weighted by
        // stage (LoadStages.h), which stays short of 100 % until the document is in.
        const auto fractions = loadStageFractions(progress);
        const int current = loadStageIndex(progress.stage);
        for (std::size_t i = 0; i < kLoadStages.size(); ++i) {
            const int index = static_cast<int>(i);
            char overlay[64];
            if (index < current) std::snprintf(overlay, sizeof overlay, "done");
            else if (index > current) std::snprintf(overlay, sizeof overlay, "waiting");
            else if (progress.total > 1) std::snprintf(overlay, sizeof overlay, "%d / %d", progress.done, progress.total);
            else std::snprintf(overlay, sizeof overlay, "running");
            ImGui::TextUnformatted(kLoadStages[i].label);
            ImGui::SameLine(140.0f);
            ImGui::ProgressBar(fractions[i], ImVec2(-1.0f, 0.0f), overlay);
        }
        ImGui::Separator();
        char total[32];
        const float overall = overallLoadFraction(progress);
        std::snprintf(total, sizeof total, "%.0f %%", 100.0 * overall);
        ImGui::ProgressBar(overall, ImVec2(-1.0f, 0.0f), total);
        ImGui::TextDisabled("%.1f s", glfwGetTime() - loading_->startSeconds);
    }
    ImGui::End();
}

std::string App::adoptDocument(Document loaded, const std::filesystem::path& path) {
    // The settings come with the file (its sidecar), else they are the defaults.
    doc_ = std::move(loaded);
    try {
        renderer_->setScene(doc_.scene);
        uploadedStructure_ = structureOf(doc_.scene);
    } catch (const std::exception& error) {
        // The file parsed but the GPU copy failed (e.g. a texture over the driver's limits):
        // fall back to an empty scene rather than render a half-uploaded one.
        sceneError_ = "cannot upload scene '" + path.string() + "': " + error.what();
        log_.error(sceneError_);
        doc_ = Document{};
        renderer_->setScene(doc_.scene);
        uploadedStructure_ = structureOf(doc_.scene);
        resetCamera();
        updateTitle();
        return sceneError_;
    }
    if (!path.empty()) recent_.add(path);  // a recovered untitled document has no file
    sceneError_.clear();
    log_.info("opened scene " + (path.empty() ? std::string("(untitled)") : path.string()));
    resetCamera();
    updateTitle();
    return "";
}

std::string App::saveTo(const std::filesystem::path& target) {
    // A copy: `target` may be doc_.file itself, which saving updates.
    const std::filesystem::path path = target;
    try {
        saveDocument(doc_, path);
    } catch (const std::exception& error) {
        sceneError_ = std::string("Not saved: ") + error.what();
        log_.error(sceneError_);
        return error.what();
    }
    recent_.add(path);
    log_.info("saved " + path.string());
    updateTitle();
    return "";
}

void App::saveOrAskForName() {
    if (doc_.file.empty())
        mainMenu_.askSaveAs("untitled.gltf");
    else
        saveTo(doc_.file);
}

void App::offerRecovery() {
    const std::optional<AutosaveInfo> info = autosave_->recoverable();
    if (!info) return;
    recoverQuestion_.ask({"Recover autosave",
                          "The editor did not exit cleanly. Recover the autosave from " + info->timeText + " of " +
                              displayName(info->documentFile) + "?",
                          "Recover", "Discard", /*cancellable=*/false});
}

void App::answerRecovery(Answer answer) {
    switch (answer) {
    case Answer::None:
    case Answer::Cancel: return;  // left as it is: offered again next start
    case Answer::No: autosave_->discard(); return;
    case Answer::Yes: {
        try {
            Document recovered = autosave_->recover(log_);
            const std::filesystem::path file = recovered.file;
            if (adoptDocument(std::move(recovered), file).empty())
                log_.info("recovered the autosave of " + displayName(doc_.file));
        } catch (const std::exception& error) {
            sceneError_ = std::string("cannot recover the autosave: ") + error.what();
            log_.error(sceneError_);
        }
        return;
    }
    }
}

void App::handleDroppedFiles() {
    bool opened = false;
    for (const std::filesystem::path& path : window_.takeDroppedPaths()) {
        if (!isSceneFile(path)) {
            log_.error("cannot open dropped file '" + path.string() + "': only glTF scenes (.gltf, .glb) can be opened");
        } else if (opened) {
            log_.warning("dropped several scenes; opened the first, ignored '" + path.string() + "'");
        } else {
            opened = true;
            requestOpen(path);
        }
    }
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
}

void App::updateTitle() {
    // "*" marks unsaved changes, as most editors do.
    const std::string name = doc_.file.empty() && doc_.scene.nodes.empty() ? std::string("no scene")
                                                                           : displayName(doc_.file);
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
    int framesRendered = 0;
    while (!exitCode_) {
        glfwPollEvents();
        if (window_.shouldClose()) {
            // The close button: ask first when there are unsaved changes.
            window_.cancelClose();
            requestQuit();
        }
        if (!scriptMode()) handleDroppedFiles();
        finishLoading();
        // Script commands run before the frame so the frame shows their effect.
        if (scriptMode()) runScriptStep();
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
        const double frameSeconds = now - previousTime;
        previousTime = now;
        frameTimer_.add(frameSeconds);

        imgui_->beginFrame();
        updateCamera(std::min(static_cast<float>(frameSeconds), kMaxCameraStep));
        updatePlayback(frameSeconds);
        handleViewportMouse(currentView());
        const glm::ivec2 previousRenderSize{doc_.settings.output.width, doc_.settings.output.height};
        drawUi(previousRenderSize);
        // The 2D views fill the free area between the panels; the camera views the whole window
        // (the panels float over it).
        const glm::vec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
        const glm::vec2 toPixels = display.x > 0.0f && display.y > 0.0f ? glm::vec2(framebuffer) / display : glm::vec2(1.0f);
        glm::ivec4 target{0, 0, framebuffer.x, framebuffer.y};  // x, y (bottom-up), width, height in pixels
        if (flatView() && viewportRect_.z > 1.0f && viewportRect_.w > 1.0f) {
            const glm::vec2 size = glm::vec2(viewportRect_.z, viewportRect_.w) * toPixels;
            const glm::vec2 topLeft = glm::vec2(viewportRect_.x, viewportRect_.y) * toPixels;
            target = glm::ivec4(glm::round(topLeft.x), glm::round(static_cast<float>(framebuffer.y) - topLeft.y - size.y),
                                glm::max(glm::ivec2(glm::round(size)), glm::ivec2(1)));
        }
        // Lowered while the camera moves or a value is dragged (ViewportSettings::interactiveFpsTarget).
        const float renderScale = renderScaleFor(frameSeconds, currentView().view);
        const glm::ivec2 renderSize =
            glm::max(glm::ivec2(glm::round(glm::vec2(target.z, target.w) * renderScale)), glm::ivec2(1));
        syncRendererStructure();
        if (options_.frameLog) frameLog_.push_back({now, renderScale, renderSize, cameraMoved_});

        doc_.settings.output.width = renderSize.x;
        doc_.settings.output.height = renderSize.y;
        const CameraView view = currentView();
        // A screenshot of the viewport alone (F12, "screenshot PATH noui") is a clean render:
        // no selection outline, gizmo, markers or path, only what a debug view itself draws.
        const bool cleanViewport = std::any_of(screenshots_.begin(), screenshots_.end(), [](const ScreenshotRequest& r) {
            return !r.withUi && r.delayFrames == 0;
        });
        updateOverlay(view, cleanViewport);
        // The shadow map view follows the selected light; the saved setting stays as it was.
        RenderSettings frameSettings = doc_.settings;
        if (frameSettings.debug.view == View::ShadowMap && doc_.selectedNode >= 0 &&
            doc_.selectedNode < static_cast<int>(doc_.scene.nodes.size())) {
            const int light = doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)].light;
            if (light >= 0) frameSettings.debug.shadowMapLight = light;
        }
        // The cached mode's refinement (more cone sets per voxel after an update) improves light
        // that is already right and costs the same at any render scale: while the camera moves or a
        // value is dragged it waits, so the frame's time goes to the frame rate (the Cornell box at
        // 1280×720 moved at 4-5 FPS while it ran, 11-12 FPS without it: docs/PERFORMANCE.md,
        // "Editor"), and it goes on when the view is still.
        GiBudget budget{viewport_.giUpdateVoxelsPerFrame > 0
                            ? static_cast<std::uint32_t>(viewport_.giUpdateVoxelsPerFrame)
                            : GiBudget::kAll,
                        static_cast<std::uint32_t>(std::max(viewport_.giRefineVoxelsPerFrame, 0))};
        if (interacting_) budget.refineVoxels = 0;
        renderer_->render(doc_.scene, view, frameSettings, budget);
        if (options_.frameLog) frameLog_.back().refinedVoxels = renderer_->stats().refinedVoxels;
        referenceViewer_.update(doc_.scene, view, frameSettings, *renderer_);
        takeScreenshots(/*withUi=*/false, framebuffer);
        presentViewport(framebuffer, target);
        imgui_->render();
        takeScreenshots(/*withUi=*/true, framebuffer);
        ++framesRendered;

        if (options_.screenshot && framesRendered >= options_.frames) {
            saveScreenshot(framebuffer, *options_.screenshot);
            return 0;
        }
        window_.swapBuffers();
        updateTitle();
        if (autosave_) {
            autosave_->maybeSave(doc_, now);  // glfwGetTime: a steady clock
            // Say once per new problem why there is no autosave copy (another editor holds the
            // folder, a full disk...).
            if (autosave_->lastError() != lastAutosaveError_) {
                lastAutosaveError_ = autosave_->lastError();
                if (!lastAutosaveError_.empty()) log_.warning(lastAutosaveError_);
            }
        }

        if (now >= nextShaderCheck) {
            renderer_->reloadChangedShaders();
            nextShaderCheck = now + kShaderReloadInterval;
        }
        if (now >= nextHeapRelease) {
            ProcessMemory::releaseFreeHeap();
            nextHeapRelease = now + kHeapReleaseInterval;
        }
    }
    // A normal quit: the autosave copy is not needed at the next start.
    if (autosave_ && *exitCode_ == 0) autosave_->cleanExit();
    if (options_.frameLog) writeFrameLog(glfwGetTime());
    return *exitCode_;
}

void App::writeFrameLog(double end) {
    std::ostringstream out;
    out << "frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels\n";
    char line[160];
    for (std::size_t i = 0; i < frameLog_.size(); ++i) {
        const FrameLogRow& row = frameLog_[i];
        // A frame lasts until the next one begins (the loop's own frame time: update, render,
        // present); the last one until the editor ends.
        const double next = i + 1 < frameLog_.size() ? frameLog_[i + 1].start : end;
        std::snprintf(line, sizeof line, "%zu,%.4f,%.2f,%d,%d,%.2f,%d,%u\n", i, row.start - frameLog_.front().start,
                      (next - row.start) * 1000.0, row.renderSize.x, row.renderSize.y, row.renderScale,
                      row.cameraMoved ? 1 : 0, static_cast<unsigned>(row.refinedVoxels));
        out << line;
    }
    try {
        writeFileAtomically(*options_.frameLog, out.str());
    } catch (const std::exception& e) {
        log_.error(std::string("frame log: ") + e.what());
    }
}

float App::renderScaleFor(double frameSeconds, const glm::mat4& view) {
    // The first frame has no view to compare with: it does not count as a motion.
    const bool moving = view != lastView_ && lastView_ != glm::mat4(0.0f);
    lastView_ = view;
    cameraMoved_ = moving;
    // Scripts (unless "interactive on") and screenshots render what they ask for, at the chosen scale.
    const bool interacting = !(scriptMode() && !scriptInteractive_) && !options_.screenshot &&
                             (moving || ImGui::IsAnyItemActive());
    interacting_ = interacting;
    frameScale_ =
        interactiveScale_.next(viewport_.renderScale, interacting, viewport_.interactiveFpsTarget, frameSeconds);
    return frameScale_;
}

void App::updateCamera(float dtSeconds) {
    const ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* window = window_.handle();
    FlyInput input;

    // Right-drag looks around. The drag starts only over the viewport (not over a panel) and
    // then keeps going wherever the cursor goes, which is hidden and unbounded meanwhile.
    const bool rightDown = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (!looking_ && rightDown && !io.WantCaptureMouse) {
        looking_ = true;
        // GLFW locks the cursor only for a focused window (X11 without a window manager gives
        // none focus); otherwise the visible cursor's motion is used, which works as well until
        // it reaches the screen's edge.
        if (glfwGetWindowAttrib(window, GLFW_FOCUSED) == GLFW_TRUE)
            glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        glfwGetCursorPos(window, &lastCursor_.x, &lastCursor_.y);  // after the mode change, which moves it
        ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NoMouse;    // panels ignore the hidden cursor
    } else if (looking_ && !rightDown) {
        looking_ = false;
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
        ImGui::GetIO().ConfigFlags &= ~ImGuiConfigFlags_NoMouse;
    }
    if (looking_) {
        glm::dvec2 cursor;
        glfwGetCursorPos(window, &cursor.x, &cursor.y);
        input.lookPixels = glm::vec2(cursor - lastCursor_);
        lastCursor_ = cursor;
    }

    // Keys fly the camera only while the right mouse button looks around (as in Unity, Godot
    // and Unreal), so W / E / R are free to pick the gizmo otherwise; not while a text field or
    // a dragged widget has the keyboard, nor with Ctrl (Ctrl+S saves rather than backing away).
    if (looking_ && !io.WantCaptureKeyboard && !io.KeyCtrl) {
        auto held = [window](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
        input.move.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
        input.move.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
        input.fast = held(GLFW_KEY_LEFT_SHIFT) > 0.0f || held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    if (looking_ || !io.WantCaptureMouse) input.wheelSteps = io.MouseWheel;
    applyFlyInput(camera_, input, dtSeconds);
}

void App::handleShortcuts() {
    // Only when no text field, dragged widget or modal dialog has the keyboard.
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard || unsavedQuestion_.asking() || recoverQuestion_.asking()) return;
    // ImGui 1.86 indexes keys by the backend's codes (GLFW's); repeats are not wanted here.
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, /*repeat=*/false); };
    if (io.KeyCtrl && pressed(GLFW_KEY_S)) saveOrAskForName();
    if (io.KeyCtrl && !io.KeyShift && pressed(GLFW_KEY_Z)) doc_.undo();
    if (io.KeyCtrl && ((io.KeyShift && pressed(GLFW_KEY_Z)) || pressed(GLFW_KEY_Y))) doc_.redo();
    if (pressed(GLFW_KEY_F12)) requestTimestampedScreenshot(/*withUi=*/false, 0);
    if (pressed(GLFW_KEY_F2)) visible_.stats = !visible_.stats;
    if (pressed(GLFW_KEY_SPACE) && !doc_.cameraPath.empty()) {
        if (playback_.playing) playback_.playing = false; else playback_.play(doc_.cameraPath);
    }
    if (pressed(GLFW_KEY_ESCAPE)) doc_.select(-1);
    if (io.KeyCtrl && pressed(GLFW_KEY_D)) logRefusal(duplicateSelection(doc_));
    // Editing keys; while the right mouse button is held the letters fly the camera instead.
    if (looking_ || io.KeyCtrl || io.KeyAlt) return;
    if (pressed(GLFW_KEY_DELETE) || pressed(GLFW_KEY_X)) logRefusal(deleteSelection(doc_));
    if (pressed(GLFW_KEY_W)) gizmoMode_ = GizmoMode::Translate;
    if (pressed(GLFW_KEY_E)) gizmoMode_ = GizmoMode::Rotate;
    if (pressed(GLFW_KEY_R)) gizmoMode_ = GizmoMode::Scale;
    if (pressed(GLFW_KEY_T)) gizmoSpace_ = gizmoSpace_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
    if (pressed(GLFW_KEY_F)) frameSelection();
    for (int digit = 0; digit <= 9; ++digit)
        if (pressed(GLFW_KEY_0 + digit))
            if (const EditorView* view = editorViewForKey(digit, io.KeyShift)) setView(std::string(view->name));
}

void App::logRefusal(const std::string& message) {
    if (!message.empty()) log_.warning(message);
}

std::string App::setView(const std::string& name) {
    viewport_.coneDirections = name == kConeDirectionsView;
    if (viewport_.coneDirections) {
        doc_.settings.debug.view = View::Final;
        return "";
    }
    coneSurface_.reset();
    const std::optional<View> view = parseView(name);
    if (!view) return "unknown view '" + name + "'";
    doc_.settings.debug.view = *view;
    return "";
}

bool App::flatView() const {
    return doc_.settings.debug.view == View::ShadowMap || doc_.settings.debug.view == View::VoxelSlice;
}

void App::addNodeInFront(NodeKind kind) {
    // Two metres (or a tenth of the scene) in front of the camera; lights and cameras look the
    // way the camera does, so a new spot light lights what is in view.
    const Aabb bounds = doc_.scene.worldBounds();
    const float distance = bounds.empty() ? 2.0f : std::clamp(0.1f * glm::length(bounds.size()), 1.0f, 10.0f);
    const glm::vec3 forward = camera_.forward();
    const glm::vec3 direction = kind == NodeKind::DirectionalLight ? glm::normalize(forward + glm::vec3(0.0f, -1.0f, 0.0f)) : forward;
    addNode(doc_, kind, camera_.position + forward * distance, direction);
}

void App::frameSelection() {
    const std::vector<int> selected = doc_.selection();
    if (selected.empty()) return;
    Aabb bounds;
    for (const int node : selected) {
        const Aabb b = nodeWorldBounds(doc_.scene, node);
        bounds.extend(b.min);
        bounds.extend(b.max);
    }
    // The near plane follows the camera each frame (currentView, depthRangeFor), so the framed
    // object is never clipped.
    frameBounds(camera_, bounds);
}

void App::syncRendererStructure() {
    std::vector<int> structure = structureOf(doc_.scene);
    if (structure == uploadedStructure_) return;
    try {
        renderer_->setScene(doc_.scene);
    } catch (const std::exception& error) {
        log_.error(std::string("cannot upload the edited scene: ") + error.what());
    }
    uploadedStructure_ = std::move(structure);
}

void App::drawViewportBar(float menuHeight) {
    // The free area between the panels shown (from the layout; a moved panel is not followed).
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const PanelLayout layout = computePanelLayout(display, menuHeight, cameraPanelHeight(), ImGuiCond_Always);
    constexpr float kMargin = 8.0f;
    float left = 0.0f, right = display.x, top = menuHeight, bottom = display.y;
    if (visible_.hierarchy || visible_.inspector) left = layout.hierarchy.position.x + layout.hierarchy.size.x + kMargin;
    if (visible_.renderSettings || visible_.camera) right = layout.renderSettings.position.x - kMargin;
    if (visible_.log || visible_.timeline) bottom = layout.log.position.y - kMargin;
    viewportRect_ = {left, top, std::max(right - left, 1.0f), std::max(bottom - top, 1.0f)};

    // Bottom right of the free area: the stats overlay has the top left.
    ImGui::SetNextWindowPos(ImVec2(right - kMargin, bottom - kMargin), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    constexpr ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                                        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("Viewport bar", nullptr, kFlags)) {
        auto modeButton = [this](const char* label, GizmoMode mode, const char* tip) {
            const bool current = gizmoMode_ == mode;
            if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
            if (ImGui::Button(label)) gizmoMode_ = mode;
            if (current) ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
            ImGui::SameLine();
        };
        modeButton("Move", GizmoMode::Translate, "Translate gizmo (W)");
        modeButton("Rotate", GizmoMode::Rotate, "Rotate gizmo (E)");
        modeButton("Scale", GizmoMode::Scale, "Scale gizmo (R), always along the node's own axes");
        if (ImGui::Button(gizmoSpace_ == GizmoSpace::World ? "World" : "Local"))
            gizmoSpace_ = gizmoSpace_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo axes: the world's or the node's own (T)");
        ImGui::SameLine();
        ImGui::Checkbox("Snap", &snap_.enabled);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Snap gizmo drags to the steps below (or hold Ctrl while dragging)");
        ImGui::SameLine();
        if (ImGui::Button("Steps...")) ImGui::OpenPopup("snap steps");
        if (ImGui::BeginPopup("snap steps")) {
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Move (m)", &snap_.translateStep, 0.01f, 0.001f, 100.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Rotate (deg)", &snap_.rotateStepDegrees, 0.5f, 0.1f, 180.0f, "%.1f");
            ImGui::SetNextItemWidth(120.0f);
            ImGui::DragFloat("Scale (factor)", &snap_.scaleStep, 0.01f, 0.001f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
            snap_.translateStep = std::max(snap_.translateStep, 0.001f);
            snap_.rotateStepDegrees = std::max(snap_.rotateStepDegrees, 0.1f);
            snap_.scaleStep = std::max(snap_.scaleStep, 0.001f);
            ImGui::EndPopup();
        }
        // The current view, so a data view is never mistaken for the final image.
        const std::string name = viewport_.coneDirections ? std::string(kConeDirectionsView)
                                                          : std::string(toString(doc_.settings.debug.view));
        const EditorView* view = findEditorView(name);
        ImGui::Text("View: %s (%s)", view ? std::string(view->label).c_str() : name.c_str(),
                    view ? std::string(view->shortcut).c_str() : "-");
        const std::size_t selected = doc_.selection().size();
        if (selected > 1) {
            ImGui::SameLine();
            ImGui::TextDisabled("| %zu selected", selected);
        }
    }
    ImGui::End();
}

void App::drawUi(glm::ivec2 renderSize) {
    float menuHeight = 0.0f;
    const MenuContext menuContext{
        recent_,
        doc_.file.empty() ? std::filesystem::path("untitled.gltf") : doc_.file,
        doc_.undoLabel(),
        doc_.redoLabel(),
        viewport_.coneDirections ? std::string(kConeDirectionsView) : std::string(toString(doc_.settings.debug.view)),
        !doc_.selection().empty()};
    const MenuRequests menu = mainMenu_.draw(visible_, menuContext, menuHeight);

    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const bool resized = display.x != lastDisplaySize_.x || display.y != lastDisplaySize_.y;
    lastDisplaySize_ = {display.x, display.y};
    // On the first frame and after a resize every panel goes to its place; otherwise only panels
    // appearing for the first time do, and the user's arrangement stays.
    const PanelLayout layout = computePanelLayout(display, menuHeight, cameraPanelHeight(),
                                                  resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver);

    if (visible_.hierarchy) hierarchyPanel_.draw(doc_, layout.hierarchy, &visible_.hierarchy);
    if (visible_.inspector) inspectorPanel_.draw(doc_, layout.inspector, &visible_.inspector);
    if (visible_.stats)
        drawStatsOverlay(frameTimer_, renderer_->profiler(), renderer_->stats(), renderSize, imgui_->monoFont(),
                         layout.stats, &visible_.stats, renderer_->voxels(), frameScale_);
    if (visible_.renderSettings) {
        const RenderSettingsRequests requests =
            drawRenderSettingsPanel(doc_.settings, viewport_, static_cast<int>(doc_.scene.lights.size()),
                                    layout.renderSettings, &visible_.renderSettings);
        // The renderer redoes the voxels when the geometry revision moves; nothing is edited.
        if (requests.revoxelize) ++doc_.scene.geometryRevision;
        if (!viewport_.coneDirections) coneSurface_.reset();
    }
    if (visible_.timeline) timelinePanel_.draw(doc_, playback_, camera_, layout.timeline, &visible_.timeline);
    if (visible_.camera && drawCameraPanel(camera_, layout.camera, &visible_.camera).resetToSceneCamera) resetCamera();
    if (visible_.log) logPanel_.draw(log_, imgui_->monoFont(), layout.log, &visible_.log);
    drawViewportBar(menuHeight);  // computes viewportRect_
    constexpr float kViewportMargin = 8.0f;
    referenceViewer_.drawWindow(ImVec2(viewportRect_.x + viewportRect_.z - kViewportMargin, viewportRect_.y + kViewportMargin),
                                resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver);
    drawErrorPanel(sceneError_, display, menuHeight);
    drawLoadingWindow();
    // An edit opened by a widget that never reported its deactivation (a colour picker popup)
    // ends once nothing is being dragged or typed into.
    if (doc_.editOpen() && !ImGui::IsAnyItemActive() && !gizmo_.active()) doc_.endEdit();
    if (!gizmo_.active()) dragged_.clear();

    handleShortcuts();
    answerUnsavedChanges(unsavedQuestion_.draw());
    answerRecovery(recoverQuestion_.draw());

    if (menu.undo) doc_.undo();
    if (menu.redo) doc_.redo();
    if (menu.save) saveOrAskForName();
    if (menu.saveAs) {
        const bool saved = saveTo(*menu.saveAs).empty();
        if (std::exchange(saveAsForPending_, false)) {
            if (saved) carryOut(std::exchange(pending_, {}));
            else pending_ = {};
        }
    }
    if (menu.saveAsCancelled && std::exchange(saveAsForPending_, false)) pending_ = {};
    if (menu.screenshot) requestTimestampedScreenshot(/*withUi=*/false, 0);
    // One frame later, once the menu that was clicked has closed.
    if (menu.screenshotWithUi) requestTimestampedScreenshot(/*withUi=*/true, 1);
    if (menu.quit) requestQuit();
    if (menu.open) requestOpen(*menu.open);
    if (menu.add) addNodeInFront(*menu.add);
    if (menu.deleteSelection) logRefusal(deleteSelection(doc_));
    if (menu.duplicateSelection) logRefusal(duplicateSelection(doc_));
    if (menu.frameSelection) frameSelection();
    if (menu.view) setView(*menu.view);
    logRefusal(std::exchange(doc_.lastRefusal, {}));
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
    glClearNamedFramebufferfv(0, GL_COLOR, 0, kBackground);

    const gl::Texture& output = referenceViewer_.output() ? *referenceViewer_.output() : renderer_->outputTexture();
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

void App::saveScreenshot(glm::ivec2 framebufferSize, const std::filesystem::path& path) {
    // The back buffer, before the swap: it holds this frame's viewport and UI.
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(framebufferSize.x) * framebufferSize.y * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glReadPixels(0, 0, framebufferSize.x, framebufferSize.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // The window's alpha channel is whatever blending left there; a screenshot is opaque.
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    writePng(path, framebufferSize.x, framebufferSize.y, rgba);
    std::printf("lit-editor: wrote %s (%d x %d)\n", path.string().c_str(), framebufferSize.x, framebufferSize.y);
}

void App::saveViewportScreenshot(const std::filesystem::path& path) {
    // The renderer's own output at its render size: no UI, no stretching to the window.
    const int width = doc_.settings.output.width;
    const int height = doc_.settings.output.height;
    std::vector<std::uint8_t> rgba = renderer_->readOutputRgba8();
    if (rgba.size() != static_cast<std::size_t>(width) * height * 4)
        throw std::runtime_error("the renderer has no output to save yet");
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    writePng(path, width, height, rgba);  // bottom-up rows, flipped by writePng
    std::printf("lit-editor: wrote %s (%d x %d)\n", path.string().c_str(), width, height);
}

void App::requestTimestampedScreenshot(bool withUi, int delayFrames) {
    const std::filesystem::path file =
        timestampedScreenshotPath(kScreenshotFolder, withUi, std::chrono::system_clock::now());
    screenshots_.push_back({file, withUi, delayFrames, std::nullopt});
}

void App::takeScreenshots(bool withUi, glm::ivec2 framebufferSize) {
    for (auto it = screenshots_.begin(); it != screenshots_.end();) {
        if (it->withUi != withUi) {
            ++it;
            continue;
        }
        if (it->delayFrames > 0) {
            --it->delayFrames;
            ++it;
            continue;
        }
        const ScreenshotRequest request = std::move(*it);
        it = screenshots_.erase(it);
        try {
            createParentFolder(request.file);
            if (withUi)
                saveScreenshot(framebufferSize, request.file);
            else
                saveViewportScreenshot(request.file);
            if (!request.command) log_.info("saved screenshot " + request.file.string());
        } catch (const std::exception& error) {
            const std::string message = "cannot save screenshot '" + request.file.string() + "': " + error.what();
            if (request.command) {
                failScript(*request.command, message);
                return;
            }
            sceneError_ = message;
            log_.error(message);
        }
    }
}

// ---- scripts -----------------------------------------------------------------------------------

void App::runScriptStep() {
    if (scriptWaitFrames_ > 0) {
        --scriptWaitFrames_;
        return;
    }
    if (scriptWaitForGi_ > 0) {
        // The frame just rendered tells how far the update is (renderer stats of the last frame).
        const bool busy = renderer_ && (renderer_->stats().giUpdateDone < 1.0f ||
                                        (scriptWaitForRefinement_ && renderer_->stats().giRefining));
        if (busy) {
            if (--scriptWaitForGi_ == 0) {
                failScript(script_[scriptNext_ - 1],
                           scriptWaitForRefinement_
                               ? "wait refined: the GI refinement did not finish in " +
                                     std::to_string(kScriptRefineWaitFrames) + " frames"
                               : "wait gi: the GI update did not finish in " + std::to_string(kScriptGiWaitFrames) +
                                     " frames");
            }
            return;
        }
        scriptWaitForGi_ = 0;
    }
    if (scriptNext_ >= script_.size()) {
        exitCode_ = 0;  // the end of the script: like quit
        return;
    }
    const ScriptCommand& command = script_[scriptNext_++];
    const std::string error = runScriptCommand(command);
    if (!error.empty()) failScript(command, error);
}

void App::failScript(const ScriptCommand& command, const std::string& message) {
    std::fprintf(stderr, "lit-editor: %s\n", scriptErrorAt(command, scriptSource_, message).c_str());
    exitCode_ = 1;
}

std::string App::runScriptCommand(const ScriptCommand& command) {
    const std::string& name = command.name;
    const std::vector<std::string>& args = command.args;
    // parseScript has checked the argument counts and the values it can; the checks below are
    // the ones that need the scene or the editor.
    auto arg = [&](std::size_t i) -> const std::string& {
        static const std::string kNone;
        return i < args.size() ? args[i] : kNone;
    };
    if (name == "select" || name == "select+") {
        if (name == "select" && arg(0) == "-") {
            doc_.select(-1);
            return "";
        }
        const int node = findNode(doc_.scene, arg(0));
        if (node < 0) return "no node called '" + arg(0) + "'";
        doc_.select(node, name == "select+");
        return "";
    }
    if (name == "add") {
        const std::optional<NodeKind> kind = parseNodeKind(arg(0));
        if (!kind) return "unknown kind '" + arg(0) + "'";
        if (args.size() == 4) {
            const auto x = parseNumber<float>(arg(1)), y = parseNumber<float>(arg(2)), z = parseNumber<float>(arg(3));
            if (!x || !y || !z) return "add: expected X Y Z";
            addNode(doc_, *kind, {*x, *y, *z}, kind == NodeKind::DirectionalLight ? glm::vec3(0.3f, -1.0f, -0.2f) : camera_.forward());
        } else {
            addNodeInFront(*kind);
        }
        return "";
    }
    if (name == "delete") return deleteSelection(doc_);
    if (name == "duplicate") return duplicateSelection(doc_);
    if (name == "parent") {
        int parent = -1;
        if (arg(0) != "-") {
            parent = findNode(doc_.scene, arg(0));
            if (parent < 0) return "no node called '" + arg(0) + "'";
        }
        return reparentSelection(doc_, parent);
    }
    if (name == "material") {
        if (doc_.selectedNode < 0) return "no node is selected";
        return makeMaterialUnique(doc_, doc_.selectedNode, doc_.selectedPrimitive);
    }
    if (name == "primitive") {
        if (doc_.selectedNode < 0) return "no node is selected";
        const int mesh = doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)].mesh;
        const int count = mesh >= 0 ? static_cast<int>(doc_.scene.meshes[static_cast<std::size_t>(mesh)].primitives.size()) : 0;
        const int index = parseNumber<int>(arg(0)).value_or(-1);
        if (index < 0 || index >= count)
            return "primitive: the selected node has " + std::to_string(count) + " primitives, not " + arg(0);
        doc_.selectedPrimitive = index;
        return "";
    }
    if (name == "gizmo") {
        gizmoMode_ = parseGizmoMode(arg(0)).value_or(GizmoMode::Translate);
        return "";
    }
    if (name == "space") {
        gizmoSpace_ = arg(0) == "local" ? GizmoSpace::Local : GizmoSpace::World;
        return "";
    }
    if (name == "snap") {
        if (args.size() == 1) {
            snap_.enabled = arg(0) == "on";
            return "";
        }
        snap_.translateStep = parseNumber<float>(arg(0)).value_or(snap_.translateStep);
        snap_.rotateStepDegrees = parseNumber<float>(arg(1)).value_or(snap_.rotateStepDegrees);
        snap_.scaleStep = parseNumber<float>(arg(2)).value_or(snap_.scaleStep);
        snap_.enabled = true;
        return "";
    }
    if (name == "drag") {
        float v[4] = {};
        for (std::size_t i = 0; i < 4; ++i) v[i] = parseNumber<float>(arg(i)).value_or(0.0f);
        if (doc_.selectedNode < 0) return "drag: no node is selected";
        const CameraView view = currentView();
        if (!beginGizmoDrag(view, {v[0], v[1]}))
            return "drag: no " + std::string(gizmoModeName(gizmoMode_)) + " gizmo handle at (" + arg(0) + ", " + arg(1) + ")";
        // In steps, as a mouse would move, so a rotation can be unwrapped past 180°.
        constexpr int kSteps = 16;
        for (int i = 1; i <= kSteps; ++i) {
            const float t = static_cast<float>(i) / kSteps;
            continueGizmoDrag(view, {v[0] + t * (v[2] - v[0]), v[1] + t * (v[3] - v[1])}, false);
        }
        endGizmoDrag();
        return "";
    }
    if (name == "frame") {
        if (doc_.selection().empty()) return "frame: no node is selected";
        frameSelection();
        return "";
    }
    if (name == "orbit") {
        const std::optional<float> dx = parseNumber<float>(arg(0)), dy = parseNumber<float>(arg(1));
        if (!dx || !dy) return "orbit: expected DX DY pixels";
        const Aabb bounds = doc_.scene.worldBounds();
        const glm::vec3 pivot = doc_.selectedNode >= 0 ? nodeWorldPosition(doc_.scene, doc_.selectedNode)
                                : bounds.empty()       ? camera_.position + camera_.forward() * 2.0f
                                                       : bounds.center();
        orbitAround(camera_, pivot, {*dx, *dy});
        return "";
    }
    if (name == "animation") return chooseCameraAnimation(doc_, arg(0));
    if (name == "set") return setProperty(doc_, arg(0), arg(1));
    if (name == "setting") {
        std::vector<std::string> deprecated;
        std::optional<std::string> result = applyEditorSetting(viewport_, arg(0), arg(1), &deprecated);
        if (!result) result = applySetting(doc_.settings, arg(0), arg(1), &deprecated);
        for (const std::string& message : deprecated) log_.warning(message);
        return *result;
    }
    if (name == "view") return setView(arg(0));
    if (name == "panel") {
        bool* flag = panelFlag(visible_, arg(0));
        if (flag == nullptr) return "unknown panel '" + arg(0) + "'";
        *flag = arg(1) == "on";
        return "";
    }
    if (name == "pick") {
        const std::optional<float> x = parseNumber<float>(arg(0)), y = parseNumber<float>(arg(1));
        if (!x || !y) return "pick: expected window pixels X Y";
        return pickAt({*x, *y});
    }
    if (name == "screenshot") {
        screenshots_.push_back({arg(0), arg(1) == "ui" || arg(1).empty(), 0, command});
        return "";
    }
    if (name == "save") {
        const std::filesystem::path file = args.empty() ? doc_.file : std::filesystem::path(arg(0));
        if (file.empty()) return "the document has no file yet: give one (save PATH)";
        return saveTo(file);
    }
    if (name == "open") return openScene(arg(0));
    if (name == "camera") {
        float v[6] = {};
        for (std::size_t i = 0; i < 6; ++i) {
            const std::optional<float> number = parseNumber<float>(arg(i));
            if (!number) return "camera: expected 6 numbers";
            v[i] = *number;
        }
        const glm::vec3 position(v[0], v[1], v[2]);
        const glm::vec3 target(v[3], v[4], v[5]);
        if (glm::length(target - position) < 1e-6f) return "camera: the target is the camera's own position";
        const glm::vec3 d = glm::normalize(target - position);
        // Inverse of FlyCamera::forward(): (−sin yaw · cos pitch, sin pitch, −cos yaw · cos pitch).
        camera_.position = position;
        camera_.pitch = std::asin(std::clamp(d.y, -1.0f, 1.0f));
        camera_.yaw = std::atan2(-d.x, -d.z);
        return "";
    }
    if (name == "undo") return doc_.undo() ? "" : "nothing to undo";
    if (name == "redo") return doc_.redo() ? "" : "nothing to redo";
    if (name == "interactive") {
        scriptInteractive_ = arg(0) == "on";
        return "";
    }
    if (name == "wait" && (arg(0) == "gi" || arg(0) == "refined")) {
        scriptWaitForRefinement_ = arg(0) == "refined";
        scriptWaitForGi_ = scriptWaitForRefinement_ ? kScriptRefineWaitFrames : kScriptGiWaitFrames;
        return "";
    }
    if (name == "wait") {
        const std::optional<int> frames = parseNumber<int>(arg(0));
        if (!frames || *frames < 1) return "wait: expected a whole number of frames, got '" + arg(0) + "'";
        scriptWaitFrames_ = *frames - 1;  // this frame is the first
        return "";
    }
    // The timeline's actions (PathEditing.h).
    if (name == "key" || name == "play" || name == "pause" || name == "time")
        return runPathCommand(doc_, playback_, camera_, name, args);
    if (name == "quit") {
        exitCode_ = 0;
        return "";
    }
    if (name == "loop") {
        scriptNext_ = 0;  // the next frame runs the first command again
        return "";
    }
    if (name == "memory") {
        // After the release the editor does every 5 s anyway: the figures are what it holds, not
        // what happens to wait for the next release (up to a freed voxel volume or two).
        ProcessMemory::releaseFreeHeap();
        log_.info(ProcessMemory::query().describe());
        return "";
    }
    return "unknown command '" + name + "'";
}

// ---- viewport interaction ----------------------------------------------------------------------

CameraView App::currentView() const {
    const glm::ivec2 framebuffer = window_.framebufferSize();
    const float aspect = framebuffer.x > 0 && framebuffer.y > 0
                             ? static_cast<float>(framebuffer.x) / static_cast<float>(framebuffer.y)
                             : 1.0f;
    // Near/far follow the camera: fitted to where it is in the scene, not to where it started
    // (a framing camera's near plane of metres would clip everything once inside a building).
    const glm::vec2 range = depthRangeFor(camera_.position, doc_.scene.worldBounds());
    return camera_.view(aspect, range.x, range.y);
}

void App::updatePlayback(double dtSeconds) {
    if (!playback_.playing) return;
    playback_.advance(doc_.cameraPath, dtSeconds);
    if (!playback_.lookThrough) return;
    lookThroughPath(doc_.cameraPath, playback_.time, camera_);
}

std::string App::pickAt(glm::vec2 windowPixel) {
    // Window pixels → the renderer's output, which is the window scaled by the render scale.
    const glm::vec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
    const glm::vec2 output(static_cast<float>(doc_.settings.output.width),
                           static_cast<float>(doc_.settings.output.height));
    if (display.x <= 0.0f || display.y <= 0.0f || windowPixel.x < 0.0f || windowPixel.y < 0.0f ||
        windowPixel.x >= display.x || windowPixel.y >= display.y)
        return "pick: (" + std::to_string(windowPixel.x) + ", " + std::to_string(windowPixel.y) +
               ") is outside the window";
    const glm::ivec2 pixel(glm::floor(windowPixel * output / display));
    if (viewport_.coneDirections) {
        coneSurface_ = renderer_->surfaceAt(pixel);
        coneCameraPosition_ = camera_.position;
        if (!coneSurface_) log_.info("cone directions: no surface under the cursor");
        return "";
    }
    const int node = renderer_->pickNode(pixel);
    // Shift+click adds to (or takes from) the selection; a click on nothing with Shift keeps it.
    doc_.select(node, ImGui::GetIO().KeyShift);
    return "";
}

void App::handleViewportMouse(const CameraView& view) {
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
    const bool selection = doc_.selectedNode >= 0 && doc_.selectedNode < static_cast<int>(doc_.scene.nodes.size());
    const bool gizmoShown = selection && viewport_.markers && !viewport_.coneDirections;

    // Alt + left drag orbits around the selection (Blender's and Godot's orbit), whatever view.
    if (orbiting_) {
        if (!io.MouseDown[ImGuiMouseButton_Left]) {
            orbiting_ = false;
        } else {
            orbitAround(camera_, orbitPivot_, glm::vec2(glm::dvec2(io.MousePos.x, io.MousePos.y) - orbitCursor_));
            orbitCursor_ = glm::dvec2(io.MousePos.x, io.MousePos.y);
        }
        return;
    }
    if (gizmo_.active()) {
        if (io.MouseDown[ImGuiMouseButton_Left] && selection) continueGizmoDrag(view, mouse, io.KeyCtrl);
        else endGizmoDrag();
        return;
    }
    hoveredGizmoAxis_ = -1;
    if (io.WantCaptureMouse || looking_) return;
    if (io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        orbiting_ = true;
        orbitCursor_ = glm::dvec2(io.MousePos.x, io.MousePos.y);
        // Around the selection; without one, around the point as far ahead as the scene's centre.
        const Aabb bounds = doc_.scene.worldBounds();
        const float ahead = bounds.empty() ? 2.0f : std::max(glm::length(bounds.center() - camera_.position), 0.5f);
        orbitPivot_ = selection ? nodeWorldPosition(doc_.scene, doc_.selectedNode) : camera_.position + camera_.forward() * ahead;
        return;
    }
    // The shadow map and the voxel slice are 2D images: clicks there point at nothing.
    if (flatView()) return;
    if (gizmoShown) {
        const glm::vec2 display(io.DisplaySize.x, io.DisplaySize.y);
        const glm::mat3 axes =
            gizmoAxes(gizmoMode_, gizmoSpace_, doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)].world);
        hoveredGizmoAxis_ = TransformGizmo::hitTest(gizmoMode_, view, display, nodeWorldPosition(doc_.scene, doc_.selectedNode),
                                                    axes, mouse);
    }
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    if (hoveredGizmoAxis_ >= 0 && beginGizmoDrag(view, mouse)) return;
    pickAt(mouse);
}

bool App::beginGizmoDrag(const CameraView& view, glm::vec2 mouse) {
    if (doc_.selectedNode < 0 || doc_.selectedNode >= static_cast<int>(doc_.scene.nodes.size())) return false;
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 display(io.DisplaySize.x, io.DisplaySize.y);
    const Node& active = doc_.scene.nodes[static_cast<std::size_t>(doc_.selectedNode)];
    const glm::vec3 origin = nodeWorldPosition(doc_.scene, doc_.selectedNode);
    const glm::mat3 axes = gizmoAxes(gizmoMode_, gizmoSpace_, active.world);
    const int handle = TransformGizmo::hitTest(gizmoMode_, view, display, origin, axes, mouse);
    if (handle < 0 || !gizmo_.begin(gizmoMode_, handle, view, display, origin, axes, mouse)) return false;
    dragged_.clear();
    for (const int node : topLevelSelection(doc_)) {
        const Node& n = doc_.scene.nodes[static_cast<std::size_t>(node)];
        dragged_.push_back({node, n.world, n.translation, n.scale});
    }
    const std::vector<int> top = topLevelSelection(doc_);
    const std::string what = top.size() == 1 ? (active.name.empty() ? std::string("node") : active.name)
                                             : std::to_string(top.size()) + " nodes";
    const char* verb = gizmoMode_ == GizmoMode::Translate ? "Move " : gizmoMode_ == GizmoMode::Rotate ? "Rotate " : "Scale ";
    doc_.beginEdit(verb + what);
    hoveredGizmoAxis_ = handle;
    return true;
}

void App::continueGizmoDrag(const CameraView& view, glm::vec2 mouse, bool snap) {
    const ImGuiIO& io = ImGui::GetIO();
    GizmoSnap steps = snap_;
    steps.enabled = snap_.enabled || snap;
    const GizmoDelta delta = gizmo_.drag(view, {io.DisplaySize.x, io.DisplaySize.y}, mouse, steps);
    Scene& scene = doc_.scene;
    for (const DraggedNode& d : dragged_) {
        if (d.node >= static_cast<int>(scene.nodes.size())) continue;
        Node& node = scene.nodes[static_cast<std::size_t>(d.node)];
        const glm::mat4 parentWorld =
            node.parent >= 0 ? scene.nodes[static_cast<std::size_t>(node.parent)].world : glm::mat4(1.0f);
        switch (gizmo_.mode()) {
        case GizmoMode::Translate:
            // Only the translation changes: no rotation or scale noise from a matrix round trip.
            node.translation = d.translation + glm::vec3(glm::inverse(parentWorld) * glm::vec4(delta.translation, 0.0f));
            break;
        case GizmoMode::Scale: node.scale = d.scale * delta.scale; break;
        case GizmoMode::Rotate:
            setWorldMatrix(scene, d.node, applyGizmoDelta(GizmoMode::Rotate, delta, gizmo_.origin(), d.world));
            node.scale = d.scale;  // a rotation changes no scale; keep it exact
            break;
        }
    }
    doc_.touched(Change::Transform);
}

void App::endGizmoDrag() {
    gizmo_.end();
    dragged_.clear();
    doc_.endEdit();
}

void App::updateOverlay(const CameraView& view, bool cleanViewport) {
    // The shadow map and the voxel slice are 2D images, not the camera's view: world-space
    // markers and outlines would land on them at random.
    if (doc_.settings.debug.view == View::ShadowMap || doc_.settings.debug.view == View::VoxelSlice) {
        renderer_->setOverlay({});
        return;
    }
    OverlayOptions options;
    options.markers = viewport_.markers && !cleanViewport;
    options.gizmo = viewport_.markers && !viewport_.coneDirections && !cleanViewport;
    options.cameraPath = viewport_.markers && !cleanViewport;
    options.selectionOutline = !cleanViewport;
    options.hoveredGizmoAxis = gizmo_.active() ? gizmo_.handle() : hoveredGizmoAxis_;
    options.gizmoMode = gizmo_.active() ? gizmo_.mode() : gizmoMode_;
    options.gizmoSpace = gizmoSpace_;
    if (viewport_.coneDirections && coneSurface_) {
        options.coneSurface = coneSurface_;
        options.coneCameraPosition = coneCameraPosition_;
    }
    const ImGuiIO& io = ImGui::GetIO();
    renderer_->setOverlay(buildViewportOverlay(doc_, view, {io.DisplaySize.x, io.DisplaySize.y}, options));
}

}  // namespace lit::editor
