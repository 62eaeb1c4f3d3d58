#pragma once
// The editor's GLFW window with its OpenGL 4.5 core context (current on the creating thread).

#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace lit::editor {

// The window system or the driver cannot give us what we need; the message says why.
class WindowError : public std::runtime_error {
public:
    explicit WindowError(const std::string& message) : std::runtime_error(message) {}
};

// glfwInit / glfwTerminate. Outlives every Window.
class GlfwLibrary {
public:
    GlfwLibrary();  // throws WindowError
    ~GlfwLibrary();
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

class Window {
public:
    // Requests a 4.5 core, forward-compatible context (a debug context when `debugContext`),
    // makes it current and sets the swap interval. Throws WindowError naming GLFW's reason.
    Window(int width, int height, const char* title, bool debugContext, bool vsync);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_.get(); }
    bool shouldClose() const;
    void requestClose();
    // Takes back a close request (the window's close button) so the App can ask about unsaved
    // changes first.
    void cancelClose();
    glm::ivec2 framebufferSize() const;  // pixels; 0×0 while minimized on some platforms
    // X11 keeps reporting the old framebuffer size while a window is iconified, so the size
    // alone does not tell whether there is anything to draw.
    bool iconified() const;
    void setTitle(const std::string& title);
    void swapBuffers();

    // Files dropped onto the window since the last call, in the order they arrived.
    std::vector<std::filesystem::path> takeDroppedPaths();

    // GLFW has one user pointer per window, and callbacks have no other way to find their
    // object. Window keeps it (its drop callback needs it) and holds one more pointer here for
    // the UI layer's key callback.
    static void setCallbackUser(GLFWwindow* window, void* user);
    static void* callbackUser(GLFWwindow* window);

private:
    struct Destroy {
        void operator()(GLFWwindow* window) const;
    };
    static void dropCallback(GLFWwindow* window, int count, const char** paths);

    std::unique_ptr<GLFWwindow, Destroy> window_;
    std::vector<std::filesystem::path> dropped_;
    void* callbackUser_ = nullptr;
};

}  // namespace lit::editor
