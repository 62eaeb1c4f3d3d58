#include "EditorOptions.h"

#include <tuple>
#include <utility>

#include "TextParse.h"

namespace lit::editor {

namespace {

// Largest window side accepted, in screen coordinates (GL_MAX_TEXTURE_SIZE on current drivers).
constexpr int kMaxWindowSide = 16384;
// Upper bound for --frames: a screenshot run is a test tool, not a benchmark.
constexpr int kMaxFrames = 100000;

int parseInt(std::string_view text, std::string_view what) {
    const auto value = parseNumber<int>(text);
    if (!value) throw OptionsError(std::string(what) + ": '" + std::string(text) + "' is not a whole number");
    return *value;
}

// "1280x720" → {1280, 720}.
std::pair<int, int> parseSize(std::string_view text) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos)
        throw OptionsError("--size: '" + std::string(text) + "' is not WIDTHxHEIGHT (e.g. 1280x720)");
    const int width = parseInt(text.substr(0, x), "--size width");
    const int height = parseInt(text.substr(x + 1), "--size height");
    if (width < 1 || height < 1 || width > kMaxWindowSide || height > kMaxWindowSide)
        throw OptionsError("--size: " + std::string(text) + " is outside 1x1.." + std::to_string(kMaxWindowSide) + "x" +
                           std::to_string(kMaxWindowSide));
    return {width, height};
}

}  // namespace

EditorOptions parseEditorOptions(std::span<const std::string_view> args) {
    EditorOptions options;
    bool framesGiven = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        auto value = [&]() -> std::string_view {
            if (i + 1 >= args.size()) throw OptionsError(std::string(arg) + " needs a value");
            return args[++i];
        };
        if (arg == "-h" || arg == "--help") {
            options.help = true;
        } else if (arg == "--screenshot") {
            const std::string_view file = value();
            if (file.empty()) throw OptionsError("--screenshot needs a file name");
            options.screenshot = std::filesystem::path(file);
        } else if (arg == "--script") {
            const std::string_view file = value();
            if (file.empty()) throw OptionsError("--script needs a file name");
            options.script = std::filesystem::path(file);
        } else if (arg == "--frames") {
            options.frames = parseInt(value(), "--frames");
            if (options.frames < 1 || options.frames > kMaxFrames)
                throw OptionsError("--frames must be in 1.." + std::to_string(kMaxFrames));
            framesGiven = true;
        } else if (arg == "--frame-log") {
            const std::string_view file = value();
            if (file.empty()) throw OptionsError("--frame-log needs a file name");
            options.frameLog = std::filesystem::path(file);
        } else if (arg == "--size") {
            std::tie(options.width, options.height) = parseSize(value());
        } else if (arg == "--allow-external-uris") {
            options.allowExternalUris = true;
        } else if (arg.starts_with("-") && arg.size() > 1) {
            throw OptionsError("unknown option '" + std::string(arg) + "'");
        } else {
            if (options.scene)
                throw OptionsError("more than one scene given ('" + options.scene->string() + "' and '" +
                                   std::string(arg) + "')");
            options.scene = std::filesystem::path(arg);
        }
    }
    if (framesGiven && !options.screenshot) throw OptionsError("--frames only applies with --screenshot");
    // Both would decide when the editor exits; a script takes its screenshots with "screenshot".
    if (options.script && options.screenshot)
        throw OptionsError("--script and --screenshot cannot be combined (use the script's screenshot command)");
    return options;
}

std::string editorUsage() {
    return "usage: lit-editor [SCENE.gltf|.glb] [--screenshot FILE.png [--frames N] | --script FILE] [--size WxH]\n"
           "                  [--allow-external-uris]\n"
           "                  [--frame-log FILE.csv]\n"
           "  SCENE              glTF scene to open (default: the built-in Cornell box)\n"
           "  --screenshot FILE  render N frames, save the window (UI included) as a PNG, exit\n"
           "  --frames N         frames to render before the screenshot (default 8)\n"
           "  --script FILE      run the editor actions in FILE, one per frame, then exit\n"
           "                     (select, select+, set, setting, view, panel, pick, camera,\n"
           "                     screenshot, save, open, undo, redo, add, delete, duplicate, parent,\n"
           "                     material unique, primitive, gizmo, space, snap, drag, frame, orbit,\n"
           "                     animation, key, play, pause, time, wait N, layout, quit;\n"
           "                     see docs/EDITOR.md)\n"
           "  --size WxH         window size in screen coordinates (default 1280x720)\n"
           "  --allow-external-uris  let scenes read buffers and images outside their folder\n"
           "                     (absolute paths, '..', file:); off: such a scene is refused\n"
           "  --frame-log FILE   at exit, write each frame's start, duration, render size and scale\n"
           "                     and whether the camera moved to FILE (CSV)\n"
           "Viewport: left click selects (Shift+click adds), drag a gizmo handle to move/rotate/scale,\n"
           "Alt+left drag orbits around the selection, right drag looks around and, while held,\n"
           "WASD moves, Q/E down/up, Shift faster, mouse wheel changes the speed.\n"
           "Keys: W/E/R translate/rotate/scale gizmo, T world/local axes, Ctrl while dragging snaps,\n"
           "F frame selected, Del or X delete, Ctrl+D duplicate, 1-9 0 Shift+1 Shift+2 debug views,\n"
           "Ctrl+Z/Ctrl+Y undo/redo, Ctrl+S save, F12 screenshot, F2 performance overlay,\n"
           "Space play the camera path, Esc clear the selection. Add menu: empty, lights, camera,\n"
           "box, plane, sphere; drag nodes in the hierarchy to parent them.\n"
           "Layout (panel positions, shown panels) is kept in $XDG_CONFIG_HOME/lit/imgui.ini\n"
           "(~/.config/lit/imgui.ini); LIT_EDITOR_LAYOUT=FILE names another ('' none). --script and\n"
           "--screenshot runs keep none unless LIT_EDITOR_LAYOUT is set.\n";
}

}  // namespace lit::editor
