#include "ImGuiLayer.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ImGuiSettingsHandler: the editor's own section of the layout file

#include <algorithm>
#include <array>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "LayoutFile.h"
#include "Window.h"

namespace lit::editor {

namespace {

// Text size in pixels: the UI stays readable at 1280x720 and fits the panel layout.
constexpr float kFontPixels = 15.0f;

// Characters the fonts provide beyond ASCII: Latin-1 and Latin Extended-A (names in files),
// general punctuation (the driver string's em dash, ellipses), Greek and arrows (units, notes).
// Zero-terminated pairs of inclusive ranges; ImGui keeps the pointer until the atlas is built.
constexpr std::array<ImWchar, 11> kGlyphRanges = {
    0x0020, 0x017F, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0,
};

ImFont* addFontIfPresent(const char* path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return nullptr;
    return ImGui::GetIO().Fonts->AddFontFromFileTTF(path, kFontPixels, nullptr, kGlyphRanges.data());
}

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window) : window_(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // No imgui.ini in whatever directory the editor was started from: rememberLayout names the
    // user's file, and runs without one start from the computed layout.
    io.IniFilename = nullptr;
    // The first font added is the default one.
    uiFont_ = addFontIfPresent("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
    monoFont_ = addFontIfPresent("/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf");
    if (uiFont_ == nullptr) uiFont_ = io.Fonts->AddFontDefault();
    if (monoFont_ == nullptr) monoFont_ = uiFont_;
    io.FontDefault = uiFont_;
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 4.0f;
    style.FrameRounding = 3.0f;
    style.Colors[ImGuiCol_WindowBg].w = 0.90f;  // the viewport shows faintly behind panels

    if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
        ImGui::DestroyContext();
        throw std::runtime_error("cannot initialise Dear ImGui's GLFW backend");
    }
    if (!ImGui_ImplOpenGL3_Init("#version 450")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw std::runtime_error("cannot initialise Dear ImGui's OpenGL 3 backend");
    }
    // Ours wraps ImGui's key callback; ImGui_ImplGlfw_Shutdown puts the original back. The
    // window's GLFW user pointer is the Window's; it keeps ours.
    Window::setCallbackUser(window, this);
    glfwSetKeyCallback(window, &ImGuiLayer::keyCallback);
}

void ImGuiLayer::keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
    auto* self = static_cast<ImGuiLayer*>(Window::callbackUser(window));
    if (self != nullptr && action == GLFW_PRESS && key >= 0 && key < kKeyCount)
        self->pressedSinceFrame_[static_cast<std::size_t>(key)] = true;
}

void ImGuiLayer::latchShortKeyPresses() {
    ImGuiIO& io = ImGui::GetIO();
    for (int key = 0; key < kKeyCount; ++key) {
        const auto k = static_cast<std::size_t>(key);
        // A key latched last frame is released now unless it is really held.
        if (latched_[k] && glfwGetKey(window_, key) != GLFW_PRESS) io.KeysDown[k] = false;
        latched_[k] = false;
        // Pressed and already released since the last frame: ImGui would never have seen it.
        if (pressedSinceFrame_[k] && !io.KeysDown[k]) {
            io.KeysDown[k] = true;
            latched_[k] = true;
        }
        pressedSinceFrame_[k] = false;
    }
    // ImGui 1.86's GLFW backend sets the modifier flags in its key callback, from the keys down
    // then: a Ctrl pressed and released within one slow frame (Ctrl+S at one frame per second on
    // llvmpipe) would be latched above but not be a modifier. Derive them from the latched keys.
    auto down = [&io](int left, int right) {
        return io.KeysDown[static_cast<std::size_t>(left)] || io.KeysDown[static_cast<std::size_t>(right)];
    };
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
}

std::string ImGuiLayer::rememberLayout(const std::filesystem::path& file, PanelVisibility& panels, glm::vec2& display) {
    std::error_code error;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), error);
    if (error) return "cannot keep the layout in " + file.string() + ": " + error.message();
    layoutFile_ = file.string();
    layoutTarget_ = {&panels, &display};
    ImGuiSettingsHandler handler;
    handler.TypeName = "Lit";
    handler.TypeHash = ImHashStr("Lit");
    handler.UserData = &layoutTarget_;
    handler.ReadOpenFn = [](ImGuiContext*, ImGuiSettingsHandler* self, const char* name) -> void* {
        return std::string_view(name) == "Editor" ? self->UserData : nullptr;
    };
    handler.ReadLineFn = [](ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
        auto* target = static_cast<LayoutTarget*>(entry);
        readLayoutLine(line, *target->panels, *target->display);
    };
    handler.WriteAllFn = [](ImGuiContext*, ImGuiSettingsHandler* self, ImGuiTextBuffer* out) {
        const auto* target = static_cast<const LayoutTarget*>(self->UserData);
        const ImVec2 size = ImGui::GetIO().DisplaySize;
        out->appendf("[Lit][Editor]\n%s\n", layoutSectionText(*target->panels, {size.x, size.y}).c_str());
    };
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(handler);
    ImGui::GetIO().IniFilename = layoutFile_.c_str();
    return "";
}

void ImGuiLayer::layoutChanged() { ImGui::MarkIniSettingsDirty(); }

ImGuiLayer::~ImGuiLayer() {
    Window::setCallbackUser(window_, nullptr);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    latchShortKeyPresses();
    ImGui::NewFrame();
    // After NewFrame: it derives the mouse delta and the releases, and the typed characters
    // stay queued until the frame ends. A held key or button counts (the fly camera moves while
    // WASD is held, and holding sends no events).
    const ImGuiIO& io = ImGui::GetIO();
    const auto any = [](const auto& flags) {
        return std::any_of(std::begin(flags), std::end(flags), [](bool b) { return b; });
    };
    sawInput_ = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f || io.MouseWheelH != 0.0f ||
                !io.InputQueueCharacters.empty() || any(io.MouseDown) || any(io.MouseReleased) || any(io.KeysDown);
}

void ImGuiLayer::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace lit::editor
