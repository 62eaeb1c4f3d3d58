#pragma once
// Editor scripts (lit-editor SCENE --script FILE): one action per line, run in order, one line
// per frame at most (wait N waits N frames). '#' starts a comment; blank lines are skipped.
// Parsing is window-free (lit_editor_core); the App executes the commands.
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
//   panel NAME on|off            hierarchy, inspector, settings, stats, camera, log, timeline
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
//   interactive on|off           the interactive render scale (RenderSettings::interactiveFpsTarget)
//                                also in the script (off by default: scripts render at the
//                                chosen scale, reproducibly)
//   key add|delete|select I|time I T|update I   camera path keys (the timeline's actions)
//   play | pause | time T        camera path playback
//   quit
//
// Unknown commands, a wrong number of arguments or values that do not parse stop the script
// with an error naming the file and line ("script.txt:7: unknown command 'selec'").

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lit::editor {

// The editor-only view name: the final image with the cones of a picked pixel drawn over it.
inline constexpr const char* kConeDirectionsView = "cone-directions";

class ScriptError : public std::runtime_error {
public:
    explicit ScriptError(const std::string& message) : std::runtime_error(message) {}
};

struct ScriptCommand {
    int line = 0;                    // 1-based line in the file, for messages
    std::string name;                // "select", "set", ...
    std::vector<std::string> args;   // the rest of the line split on whitespace; for "set",
                                     // args[0] is the property and args[1] the rest of the line;
                                     // for "select", args[0] is the rest of the line (node names
                                     // may hold spaces, though not '#')
};

// Parses and checks the whole script before anything runs: command names, argument counts,
// and the values that can be checked without a scene (numbers, on|off, view and panel names).
// `source` names the file in messages. Throws ScriptError.
std::vector<ScriptCommand> parseScript(std::string_view text, const std::string& source);
std::vector<ScriptCommand> loadScript(const std::filesystem::path& file);

// "script.txt:7: <message>" for an error found while running a command.
std::string scriptErrorAt(const ScriptCommand& command, const std::string& source, const std::string& message);

}  // namespace lit::editor
