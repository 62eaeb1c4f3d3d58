#pragma once
// Dear ImGui's context and its GLFW + OpenGL3 backends, created and destroyed together.

#include <array>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>

#include "EditorState.h"

struct GLFWwindow;
struct ImFont;

namespace lit::editor {

class ImGuiLayer {
public:
    // Needs the window's GL context current. Installs ImGui's GLFW callbacks (chaining any
    // installed before) and keeps itself in Window::setCallbackUser for its key callback.
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Keeps the layout in `file` (LayoutFile.h): ImGui's window positions plus which `panels`
    // are shown and the `display` size they were arranged for, read at the first frame and
    // written every few seconds after a change and at exit. Both must outlive this layer. Returns
    // "" or why the file's folder cannot be made (the layout is then not kept).
    std::string rememberLayout(const std::filesystem::path& file, PanelVisibility& panels, glm::vec2& display);
    // Marks the layout changed (a panel shown or hidden), so it is written within seconds.
    static void layoutChanged();

    // Proportional font for the UI and a monospaced one for numbers and logs. Both are
    // DejaVu (Debian's fonts-dejavu-core) when installed, else Dear ImGui's built-in font.
    ImFont* uiFont() const { return uiFont_; }
    ImFont* monoFont() const { return monoFont_; }

    void beginFrame();
    // The frame begun last saw input: the mouse moved, a button or key is held or was released,
    // the wheel turned, text was typed. The frame loop sleeps only after frames without any.
    bool sawInput() const { return sawInput_; }
    // Builds the draw lists and draws them into the current framebuffer (the window's).
    void render();

private:
    static constexpr int kKeyCount = 512;  // size of ImGuiIO::KeysDown in 1.86 (GLFW key codes)

    static void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods);
    void latchShortKeyPresses();

    GLFWwindow* window_;
    // Dear ImGui 1.86 samples key state once per frame (its input queue came in 1.87), so a key
    // pressed and released between two frames is lost; with llvmpipe's frames of a second that
    // is most key presses (Enter, Backspace in text fields). Presses are recorded here and such
    // keys read as down for one frame.
    std::array<bool, kKeyCount> pressedSinceFrame_{};
    std::array<bool, kKeyCount> latched_{};
    ImFont* uiFont_ = nullptr;
    ImFont* monoFont_ = nullptr;
    bool sawInput_ = false;
    std::string layoutFile_;  // ImGuiIO::IniFilename points into it
    struct LayoutTarget {
        PanelVisibility* panels = nullptr;
        glm::vec2* display = nullptr;
    } layoutTarget_;
};

}  // namespace lit::editor
