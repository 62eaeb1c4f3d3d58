#pragma once
// The editor application: owns the window, the UI, the renderer, the scene and the settings,
// and runs the frame loop. Panels edit the Scene / RenderSettings / editor state they are
// given; the App turns their requests (open a file, quit, reset the camera) into actions and is
// the only place that talks to GL directly (presenting the renderer's output to the window).

#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>

#include "EditorOptions.h"
#include "EditorState.h"
#include "FrameTimer.h"
#include "ImGuiLayer.h"
#include "Log.h"
#include "RecentFiles.h"
#include "RenderSettings.h"
#include "Renderer.h"
#include "Window.h"
#include "gl/Objects.h"
#include "panels/LogPanel.h"
#include "panels/MainMenu.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit::editor {

class App {
public:
    // Loads the scene, opens the window, checks the GL context and builds the renderer.
    // Throws (with a message meant for the user) when any of that fails; a scene that cannot
    // be loaded is fatal only in screenshot mode, otherwise the editor starts empty and says why.
    explicit App(const EditorOptions& options);
    ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // Runs until the window closes (or, in screenshot mode, until the capture is written).
    // Returns the process exit code.
    int run();

private:
    Scene loadInitialScene();
    void openScene(const std::filesystem::path& path);
    void resetCamera();
    void updateTitle();

    void updateCamera(float dtSeconds);
    void drawUi(glm::ivec2 renderSize);
    void presentViewport(glm::ivec2 framebufferSize);
    void saveScreenshot(glm::ivec2 framebufferSize, const std::filesystem::path& path);

    EditorOptions options_;
    // Declared before the window: the scene is loaded before there is one (loadInitialScene()
    // may use only the members above scene_), and the log outlives the GL context whose debug
    // callback writes into it.
    Log log_;
    std::string sceneError_;  // shown in the UI until dismissed
    Scene scene_;
    RenderSettings settings_;

    // GL context holders, in creation order (members are destroyed in reverse, so GL objects go
    // before ImGui, ImGui before the window, the window before glfwTerminate).
    GlfwLibrary glfw_;
    Window window_;
    std::optional<ImGuiLayer> imgui_;
    std::unique_ptr<Renderer> renderer_;
    gl::Framebuffer blitSource_;  // reads the renderer's output texture for the blit

    // Editor state edited by the panels.
    PanelVisibility visible_;
    ViewportSettings viewport_;
    FlyCamera camera_;
    float znear_ = 0.05f;  // metres, fitted to the scene when it is loaded
    float zfar_ = 100.0f;  // metres
    RecentFiles recent_;
    MainMenu mainMenu_;
    LogPanel logPanel_;
    FrameTimer frameTimer_;

    // Input and layout bookkeeping.
    bool looking_ = false;             // right mouse drag in progress
    glm::dvec2 lastCursor_{0.0};       // screen coordinates
    glm::vec2 lastDisplaySize_{0.0f};  // re-apply the panel layout when it changes
};

}  // namespace lit::editor
