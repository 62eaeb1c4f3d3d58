#include "Screenshots.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "ScreenshotNames.h"
#include "image/ImageIO.h"

namespace lit::editor {

namespace {

// Where F12 and the File menu put screenshots, relative to the working directory.
constexpr const char* kScreenshotFolder = "screenshots";

void createParentFolder(const std::filesystem::path& file) {
    const std::filesystem::path parent = file.parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
}

}  // namespace

void Screenshots::requestTimestamped(bool withUi, int delayFrames) {
    const std::filesystem::path file =
        timestampedScreenshotPath(kScreenshotFolder, withUi, std::chrono::system_clock::now());
    requests_.push_back({file, withUi, delayFrames, std::nullopt});
}

bool Screenshots::cleanViewportDue() const {
    return std::any_of(requests_.begin(), requests_.end(),
                       [](const Request& r) { return !r.withUi && r.delayFrames == 0; });
}

std::optional<Screenshots::ScriptFailure> Screenshots::take(bool withUi, glm::ivec2 framebufferSize) {
    for (auto it = requests_.begin(); it != requests_.end();) {
        if (it->withUi != withUi) {
            ++it;
            continue;
        }
        if (it->delayFrames > 0) {
            --it->delayFrames;
            ++it;
            continue;
        }
        const Request request = std::move(*it);
        it = requests_.erase(it);
        try {
            createParentFolder(request.file);
            if (withUi)
                saveWindow(framebufferSize, request.file);
            else
                saveViewport(request.file);
            if (!request.command) log_.info("saved screenshot " + request.file.string());
        } catch (const std::exception& error) {
            const std::string message = "cannot save screenshot '" + request.file.string() + "': " + error.what();
            if (request.command) return ScriptFailure{*request.command, message};
            sceneError_ = message;
            log_.error(message);
        }
    }
    return std::nullopt;
}

void Screenshots::saveWindow(glm::ivec2 framebufferSize, const std::filesystem::path& path) {
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

void Screenshots::saveViewport(const std::filesystem::path& path) {
    // The renderer's own output at its render size: no UI, no stretching to the window.
    const int width = doc_.settings.output.width;
    const int height = doc_.settings.output.height;
    std::vector<std::uint8_t> rgba = renderer_.readOutputRgba8();
    if (rgba.size() != static_cast<std::size_t>(width) * height * 4)
        throw std::runtime_error("the renderer has no output to save yet");
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    writePng(path, width, height, rgba);  // bottom-up rows, flipped by writePng
    std::printf("lit-editor: wrote %s (%d x %d)\n", path.string().c_str(), width, height);
}

}  // namespace lit::editor
