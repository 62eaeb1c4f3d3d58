#pragma once
// Runs a --script (Script.h) in the editor: one command per frame, before the frame is rendered
// so that the frame shows its effect, or waits (N frames, or until the GI update is done). The
// commands come from parseScript, which chose each one's verb and checked every value that needs
// no scene; what needs the scene or the editor (a node name, a gizmo handle under a pixel) is
// checked here. The first failure ends the editor with status 1 and "script.txt:7: message" on
// stderr.

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "EditorState.h"
#include "FileActions.h"
#include "Log.h"
#include "PathEditing.h"
#include "Renderer.h"
#include "Screenshots.h"
#include "Script.h"
#include "TransformGizmo.h"
#include "ViewportInput.h"
#include "scene/CameraView.h"

namespace lit::editor {

// What the commands act on.
struct ScriptTarget {
    Document& doc;
    FlyCamera& camera;
    ViewportSettings& viewport;
    PanelVisibility& panels;
    PathPlayback& playback;
    GizmoTool& gizmo;
    ViewportInput& input;  // pick, drag, view, frame
    FileActions& files;    // open, save
    Screenshots& screenshots;
    const Renderer& renderer;  // the last frame's GI progress (wait gi, wait refined)
    const ViewportUiReport& ui;  // the last frame's legend and overlay (layout)
    Log& log;
    std::optional<int>& exitCode;  // 0 at the end or on quit, 1 on a failure
};

class ScriptRunner {
public:
    // `source` names the script file in messages.
    ScriptRunner(std::vector<ScriptCommand> commands, std::string source, ScriptTarget target);

    // Once a frame: runs the next command unless waiting; sets the exit code at the end of the
    // script, on quit or on a failure.
    void step();
    // Ends the script: prints `message` with the command's file and line, exit status 1.
    void fail(const ScriptCommand& command, const std::string& message);
    // "interactive on": the interactive render scale applies to the script's frames too.
    bool interactive() const { return interactive_; }

private:
    // Carries out one command; returns "" or the error message for its line.
    std::string run(const ScriptCommand& command);
    std::string select(const ScriptCommand& command);
    std::string add(const ScriptCommand& command);
    std::string primitive(const ScriptCommand& command);
    std::string snap(const ScriptCommand& command);
    std::string drag(const ScriptCommand& command);
    std::string orbit(const ScriptCommand& command);
    std::string setting(const ScriptCommand& command);
    std::string camera(const ScriptCommand& command);
    std::string wait(const ScriptCommand& command);

    std::vector<ScriptCommand> commands_;
    std::string source_;
    ScriptTarget target_;
    std::size_t next_ = 0;
    int waitFrames_ = 0;  // frames still to let pass before the next command
    // wait Ns: the next command runs in the first frame at or after this time (input from outside
    // the script, as a test's real mouse and keyboard, takes wall time whatever the frame rate).
    std::optional<std::chrono::steady_clock::time_point> waitUntil_;
    // wait gi / wait refined: frames still allowed for the GI update (with "refined", and then its
    // refinement rounds: ~180 frames at 128³ with the editor's budget) to finish (0: not waiting).
    static constexpr int kGiWaitFrames = 2000;
    static constexpr int kRefineWaitFrames = 20000;
    int waitForGi_ = 0;
    bool waitForRefinement_ = false;
    // wait play: frames still allowed for the camera path's playback to end (0: not waiting).
    static constexpr int kPlaybackWaitFrames = 20000;
    int waitForPlayback_ = 0;
    bool interactive_ = false;
};

}  // namespace lit::editor
