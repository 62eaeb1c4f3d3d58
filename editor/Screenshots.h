#pragma once
// Screenshots: of the window (viewport and UI, the back buffer before the swap) or of the
// viewport alone (the renderer's output at its render size, without the editor's markers). F12
// and the File menu ask for timestamped ones in screenshots/, the script's "screenshot" for a
// named one, --screenshot for one at the end. Requests wait in a queue until their point of the
// frame: viewport shots after rendering, window shots after the UI is drawn.

#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "Log.h"
#include "Renderer.h"
#include "Script.h"

namespace lit::editor {

class Screenshots {
public:
    struct Request {
        std::filesystem::path file;
        bool withUi = false;
        int delayFrames = 0;                   // frames to let pass first (a menu must close)
        std::optional<ScriptCommand> command;  // the script line that asked, for error messages
    };
    // A script's screenshot that could not be written: the script fails with this message.
    struct ScriptFailure {
        ScriptCommand command;
        std::string message;
    };

    // `doc` gives the render size; another shot's failure is shown through `sceneError` and the log.
    Screenshots(const Renderer& renderer, const Document& doc, Log& log, std::string& sceneError)
        : renderer_(renderer), doc_(doc), log_(log), sceneError_(sceneError) {}

    void request(Request request) { requests_.push_back(std::move(request)); }
    // A shot named by the time, in screenshots/ under the working directory.
    void requestTimestamped(bool withUi, int delayFrames);
    // A viewport shot is written this frame: the frame is rendered without selection outline,
    // gizmo, markers or path, only what a debug view itself draws.
    bool cleanViewportDue() const;
    // Writes the requests of this point of the frame (`withUi`: after the UI is drawn) that are
    // due. Stops at a script's shot that fails and returns it.
    std::optional<ScriptFailure> take(bool withUi, glm::ivec2 framebufferSize);
    // Writes the window's back buffer (pixels); throws when the file cannot be written.
    static void saveWindow(glm::ivec2 framebufferSize, const std::filesystem::path& path);

private:
    void saveViewport(const std::filesystem::path& path);

    const Renderer& renderer_;
    const Document& doc_;
    Log& log_;
    std::string& sceneError_;
    std::vector<Request> requests_;
};

}  // namespace lit::editor
