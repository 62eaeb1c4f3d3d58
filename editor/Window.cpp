#include "Window.h"

#include <GLFW/glfw3.h>

#include <utility>

namespace lit::editor {

namespace {
// GLFW's description of its most recent error, or a fallback when it recorded none.
std::string lastGlfwError() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR || description == nullptr) return "unknown GLFW error";
    return description;
}
}  // namespace

GlfwLibrary::GlfwLibrary() {
    if (glfwInit() != GLFW_TRUE) throw WindowError("cannot create an OpenGL 4.5 core window: " + lastGlfwError());
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

void Window::Destroy::operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }

Window::Window(int width, int height, const char* title, bool debugContext, bool vsync) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugContext ? GLFW_TRUE : GLFW_FALSE);
    // The viewport is a blit of the renderer's output, so the window needs no depth or stencil.
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    window_.reset(glfwCreateWindow(width, height, title, nullptr, nullptr));
    if (!window_) throw WindowError("cannot create an OpenGL 4.5 core window: " + lastGlfwError());
    glfwMakeContextCurrent(window_.get());
    glfwSwapInterval(vsync ? 1 : 0);
    glfwSetWindowUserPointer(window_.get(), this);
    glfwSetDropCallback(window_.get(), &Window::dropCallback);
}

Window::~Window() {
    if (window_) glfwSetWindowUserPointer(window_.get(), nullptr);
}

void Window::dropCallback(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (self == nullptr) return;
    for (int i = 0; i < count; ++i)
        if (paths[i] != nullptr) self->dropped_.emplace_back(paths[i]);
}

std::vector<std::filesystem::path> Window::takeDroppedPaths() { return std::exchange(dropped_, {}); }

void Window::setCallbackUser(GLFWwindow* window, void* user) {
    if (auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window))) self->callbackUser_ = user;
}

void* Window::callbackUser(GLFWwindow* window) {
    const auto* self = static_cast<const Window*>(glfwGetWindowUserPointer(window));
    return self != nullptr ? self->callbackUser_ : nullptr;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_.get()) == GLFW_TRUE; }

void Window::requestClose() { glfwSetWindowShouldClose(window_.get(), GLFW_TRUE); }

void Window::cancelClose() { glfwSetWindowShouldClose(window_.get(), GLFW_FALSE); }

glm::ivec2 Window::framebufferSize() const {
    glm::ivec2 size{0};
    glfwGetFramebufferSize(window_.get(), &size.x, &size.y);
    return size;
}

bool Window::iconified() const { return glfwGetWindowAttrib(window_.get(), GLFW_ICONIFIED) == GLFW_TRUE; }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_.get(), title.c_str()); }

void Window::swapBuffers() { glfwSwapBuffers(window_.get()); }

}  // namespace lit::editor
