#pragma once
// Editor scripts (lit-editor SCENE --script FILE): one action per line, run in order, one line
// per frame at most (wait N waits N frames). '#' starts a comment; blank lines are skipped.
// Parsing and checking are window-free (lit_editor_core) and driven by one command table in
// Script.cpp; ScriptRunner (the editor) executes the commands by their verb.
//
//   select NODE_NAME             select a node by name ("select -" clears the selection)
//   select+ NODE_NAME            add a node to the selection (Shift+click), or take it out
//   add KIND [X Y Z]             add a node: empty, directional, point, spot, camera, box, plane,
//                                sphere, at X Y Z (default: in front of the camera); selects it
//   delete | duplicate           the selected nodes (with their subtrees)
//   parent NODE_NAME             make NODE_NAME the parent of the selection ("-": the root)
//   material unique              give the selected primitive its own copy of its material
//   primitive I                  choose the primitive whose material the inspector edits
//   gizmo translate|rotate|scale the gizmo's mode (W / E / R)
//   space world|local            the gizmo's axes
//   snap on|off | snap M DEG F   snapping, or its steps (metres, degrees, scale factor) and on
//   drag X0 Y0 X1 Y1             press the left mouse at (X0, Y0), move to (X1, Y1), release:
//                                a gizmo drag when a handle is there (one undo step)
//   frame                        frame the selection (F)
//   orbit DX DY                  orbit around the selection by a mouse motion (Alt + left drag)
//   animation NAME               edit this camera animation of the file (the timeline's combo)
//   set PROPERTY VALUE...        Properties.h, as one undo step
//   setting KEY VALUE            a RenderSettings field by its JSON name (e.g. setting gi false)
//   view NAME                    the debug view, by the names parseView() takes, or
//                                cone-directions (then "pick X Y" chooses the pixel)
//   panel NAME on|off            hierarchy, inspector, settings, stats, stats-details (the
//                                overlay's graph and per-pass table), camera, log, timeline,
//                                legend (the debug view's legend)
//   layout                       log where the free viewport area, the legend and the performance
//                                overlay were drawn last frame (ImGui units: x y width height) and
//                                what the legend said
//   pick X Y                     click the viewport at window pixel (X, Y), top-left origin
//   screenshot PATH [ui|noui]    save the window (ui, default) or the viewport alone (noui)
//   save [PATH]                  save the scene (to PATH: Save As)
//   open PATH                    open another scene (discarding unsaved changes)
//   camera X Y Z TX TY TZ        put the fly camera at (X, Y, Z) looking at (TX, TY, TZ), metres
//   undo | redo
//   wait N                       let N frames render
//   wait gi                      let frames render until the GI update after the last edit is
//                                complete (FrameStats::giUpdateDone; refinement rounds do not count),
//                                at most 2000 frames
//   wait refined                 the same, then until the cached GI mode's refinement rounds after it
//                                are done too (FrameStats::giRefining), at most 20000 frames
//   wait play                    let frames render until the timeline's playback stops (the end
//                                of an open path or of the node animations), at most 20000 frames
//   interactive on|off           the interactive render scale (ViewportSettings::interactiveFpsTarget)
//                                also in the script (off by default: scripts render at the
//                                chosen scale, reproducibly)
//   key add|delete|select I|time I T|update I   camera path keys (the timeline's actions)
//   play [SPEED] | pause | time T   playback of the camera path and the node animations (SPEED:
//                                the rate, 0.1..4); time T poses the animated nodes at T
//   duration T                   the camera path's duration (keys spread in proportion)
//   memory                       log what the process holds (after handing free heap back)
//   loop                         start the script over from its first command
//   quit
//
// Unknown commands, a wrong number of arguments or values that do not parse stop the script
// with an error naming the file and line ("script.txt:7: unknown command 'selec'").

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "EditorViews.h"  // kConeDirectionsView

namespace lit::editor {

class ScriptError : public std::runtime_error {
public:
    explicit ScriptError(const std::string& message) : std::runtime_error(message) {}
};

// Every command a script can hold, one row each in Script.cpp's command table. The runner
// switches over these without a default, so a verb it does not carry out fails the build.
enum class ScriptVerb {
    Select,        // select NODE_NAME | -
    SelectToggle,  // select+ NODE_NAME
    Add,
    Delete,
    Duplicate,
    Parent,
    Material,
    Primitive,
    Gizmo,
    Space,
    Snap,
    Drag,
    Frame,
    Orbit,
    Animation,
    Set,
    Setting,
    View,
    Panel,
    Pick,
    Screenshot,
    Save,
    Open,
    Camera,
    Undo,
    Redo,
    Interactive,
    Wait,
    Key,  // key, play, pause and time: the timeline's actions (runPathCommand)
    Play,
    Pause,
    Time,
    Duration,
    Quit,
    Loop,
    Memory,
    Layout,
};

struct ScriptCommand {
    int line = 0;                    // 1-based line in the file, for messages
    ScriptVerb verb = ScriptVerb::Select;
    std::string name;                // "select", "set", ...
    std::vector<std::string> args;   // the rest of the line split on whitespace; for "set",
                                     // args[0] is the property and args[1] the rest of the line;
                                     // for "select", "select+", "parent" and "animation", args[0]
                                     // is the rest of the line (names may hold spaces, not '#')
};

// Parses and checks the whole script before anything runs: command names, argument counts,
// and the values that can be checked without a scene (numbers, on|off, view and panel names).
// `source` names the file in messages. Throws ScriptError.
std::vector<ScriptCommand> parseScript(std::string_view text, const std::string& source);
std::vector<ScriptCommand> loadScript(const std::filesystem::path& file);

// The seconds of a "wait 2.5s" (0 < N ≤ 3600), else nullopt.
std::optional<double> waitSeconds(const std::string& word);

// "script.txt:7: <message>" for an error found while running a command.
std::string scriptErrorAt(const ScriptCommand& command, const std::string& source, const std::string& message);

}  // namespace lit::editor
