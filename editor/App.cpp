#include "App.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <system_error>
#include <vector>

#include "FlyController.h"
#include "gl/Capabilities.h"
#include "image/ImageIO.h"
#include "panels/CameraPanel.h"
#include "panels/ErrorPanel.h"
#include "panels/Layout.h"
#include "panels/RenderSettingsPanel.h"
#include "panels/StatsOverlay.h"
#include "scene/GltfLoader.h"
#include "scene/SceneBuilder.h"

namespace lit::editor {

namespace {

// How often changed shader files are looked for, in seconds.
constexpr double kShaderReloadInterval = 0.5;
// Longest time step given to the camera, in seconds: after a stall (loading a scene) the
// camera must not jump by the whole stall.
constexpr float kMaxCameraStep = 1.0f;
// Window background where the renderer has not drawn (before the first frame): dark grey, sRGB.
constexpr float kBackground[4] = {0.08f, 0.08f, 0.09f, 1.0f};

#ifdef NDEBUG
constexpr bool kDebugContext = false;
#else
constexpr bool kDebugContext = true;
#endif

// Loads a glTF file, with a clear message for the commonest mistake (a wrong path) before the
// loader's own checks.
Scene loadSceneFile(const std::filesystem::path& path, Log& log) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw SceneLoadError("cannot open scene '" + path.string() + "': no such file");
    Scene scene = loadGltf(path, log);
    addDefaultLightAndCamera(scene, log);
    return scene;
}

}  // namespace

App::App(const EditorOptions& options)
    : options_(options),
      scene_(loadInitialScene()),
      window_(options.width, options.height, "Lit editor", kDebugContext, /*vsync=*/!options.screenshot) {
    // The window's context is current from here on.
    gl::requireCapabilities();
#ifndef NDEBUG
    gl::installDebugOutput(log_);
#endif
    log_.info("OpenGL " + gl::contextDescription());
    renderer_ = std::make_unique<Renderer>(defaultShaderRoot(), log_);
    imgui_.emplace(window_.handle());
    blitSource_ = gl::Framebuffer("editor viewport blit source");
    renderer_->setScene(scene_);
    if (sceneError_.empty()) recent_.add(options_.scene.value_or(defaultScenePath()));
    resetCamera();
    updateTitle();
}

App::~App() {
    // Give the cursor back if the editor closes in the middle of a right-drag.
    if (looking_) glfwSetInputMode(window_.handle(), GLFW_CURSOR, GLFW_CURSOR_NORMAL);
}

// Runs in the member initialiser list: only members declared before scene_ exist yet.
Scene App::loadInitialScene() {
    const std::filesystem::path path = options_.scene.value_or(defaultScenePath());
    try {
        Scene scene = loadSceneFile(path, log_);
        log_.info("opened scene " + path.string());
        return scene;
    } catch (const std::exception& error) {
        // A screenshot run exists to check a scene: fail loudly. Interactively, start empty and
        // let the user open another file.
        if (options_.screenshot) throw;
        sceneError_ = error.what();
        log_.error(sceneError_);
        return Scene{};
    }
}

void App::openScene(const std::filesystem::path& path) {
    Scene loaded;
    try {
        loaded = loadSceneFile(path, log_);
    } catch (const std::exception& error) {
        sceneError_ = error.what();
        log_.error(sceneError_);
        return;  // the current scene stays
    }
    scene_ = std::move(loaded);
    try {
        renderer_->setScene(scene_);
    } catch (const std::exception& error) {
        // The file parsed but the GPU copy failed (e.g. a texture over the driver's limits):
        // fall back to an empty scene rather than render a half-uploaded one.
        sceneError_ = "cannot upload scene '" + path.string() + "': " + error.what();
        log_.error(sceneError_);
        scene_ = Scene{};
        renderer_->setScene(scene_);
        resetCamera();
        updateTitle();
        return;
    }
    recent_.add(path);
    sceneError_.clear();
    log_.info("opened scene " + path.string());
    resetCamera();
    updateTitle();
}

void App::resetCamera() {
    const glm::ivec2 size = window_.framebufferSize();
    const float aspect = size.x > 0 && size.y > 0
                             ? static_cast<float>(size.x) / static_cast<float>(size.y)
                             : static_cast<float>(options_.width) / static_cast<float>(options_.height);
    // The scene's first camera if it has one, else a view framing the whole scene.
    const int cameraIndex = scene_.cameras.empty() ? -1 : 0;
    const CameraView view = sceneCameraView(scene_, cameraIndex, aspect);
    camera_.setFromView(view);
    camera_.speed = flySpeedForBounds(scene_.worldBounds());
    znear_ = view.znear;
    zfar_ = view.zfar;
}

void App::updateTitle() {
    const std::string name =
        scene_.sourcePath.empty() ? std::string("no scene") : scene_.sourcePath.filename().string();
    window_.setTitle("Lit editor - " + name);
}

int App::run() {
    double previousTime = glfwGetTime();
    double nextShaderCheck = previousTime + kShaderReloadInterval;
    int framesRendered = 0;
    while (!window_.shouldClose()) {
        glfwPollEvents();
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
        const glm::ivec2 renderSize =
            glm::max(glm::ivec2(glm::round(glm::vec2(framebuffer) * std::clamp(viewport_.renderScale, 0.1f, 1.0f))),
                     glm::ivec2(1));
        drawUi(renderSize);

        settings_.width = renderSize.x;
        settings_.height = renderSize.y;
        const float aspect = static_cast<float>(framebuffer.x) / static_cast<float>(framebuffer.y);
        renderer_->render(scene_, camera_.view(aspect, znear_, zfar_), settings_);
        presentViewport(framebuffer);
        imgui_->render();
        ++framesRendered;

        if (options_.screenshot && framesRendered >= options_.frames) {
            saveScreenshot(framebuffer, *options_.screenshot);
            return 0;
        }
        window_.swapBuffers();

        if (now >= nextShaderCheck) {
            renderer_->reloadChangedShaders();
            nextShaderCheck = now + kShaderReloadInterval;
        }
    }
    return 0;
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

    // Keys move the camera unless a text field or a dragged widget has the keyboard.
    if (!io.WantCaptureKeyboard) {
        auto held = [window](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
        input.move.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
        input.move.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
        input.fast = held(GLFW_KEY_LEFT_SHIFT) > 0.0f || held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    if (looking_ || !io.WantCaptureMouse) input.wheelSteps = io.MouseWheel;
    applyFlyInput(camera_, input, dtSeconds);
}

void App::drawUi(glm::ivec2 renderSize) {
    float menuHeight = 0.0f;
    const MenuRequests menu = mainMenu_.draw(visible_, recent_, scene_.sourcePath, menuHeight);

    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const bool resized = display.x != lastDisplaySize_.x || display.y != lastDisplaySize_.y;
    lastDisplaySize_ = {display.x, display.y};
    // On the first frame and after a resize every panel goes to its place; otherwise only panels
    // appearing for the first time do, and the user's arrangement stays.
    const PanelLayout layout = computePanelLayout(display, menuHeight, cameraPanelHeight(),
                                                  resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver);

    if (visible_.stats)
        drawStatsOverlay(frameTimer_, renderer_->profiler(), renderer_->stats(), renderSize, imgui_->monoFont(),
                         layout.stats, &visible_.stats);
    if (visible_.renderSettings)
        drawRenderSettingsPanel(settings_, viewport_, static_cast<int>(scene_.lights.size()), layout.renderSettings,
                                &visible_.renderSettings);
    if (visible_.camera && drawCameraPanel(camera_, layout.camera, &visible_.camera).resetToSceneCamera) resetCamera();
    if (visible_.log) logPanel_.draw(log_, imgui_->monoFont(), layout.log, &visible_.log);
    drawErrorPanel(sceneError_, display, menuHeight);

    if (menu.quit) window_.requestClose();
    if (menu.open) openScene(*menu.open);
}

void App::presentViewport(glm::ivec2 framebufferSize) {
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

    const gl::Texture& output = renderer_->outputTexture();
    if (!output) return;
    // Attached every frame: the renderer recreates the texture on resize, and a deleted texture
    // can come back under the same name.
    blitSource_.attach(GL_COLOR_ATTACHMENT0, output);
    glNamedFramebufferReadBuffer(blitSource_.id(), GL_COLOR_ATTACHMENT0);
    const glm::ivec2 source{output.desc().width, output.desc().height};
    const GLenum filter = source == framebufferSize ? GL_NEAREST : GL_LINEAR;
    glBlitNamedFramebuffer(blitSource_.id(), 0, 0, 0, source.x, source.y, 0, 0, framebufferSize.x, framebufferSize.y,
                           GL_COLOR_BUFFER_BIT, filter);
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

}  // namespace lit::editor
