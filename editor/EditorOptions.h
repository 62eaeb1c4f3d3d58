#pragma once
// lit-editor's command line:
//   lit-editor [SCENE] [--screenshot FILE.png [--frames N] | --script FILE] [--size WxH]
//              [--allow-external-uris]
//              [--frame-log FILE.csv]
// Parsed into plain data so it can be tested without a window.

#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lit::editor {

struct EditorOptions {
    // Scene to open; none = the built-in Cornell box (lit::defaultScenePath()).
    std::optional<std::filesystem::path> scene;
    // Screenshot mode: render `frames` frames (UI included), save the window as this PNG, exit.
    std::optional<std::filesystem::path> screenshot;
    // More than Profiler::kFramesInFlight by default, so the stats overlay in the capture
    // already shows GPU timings (they arrive that many frames late).
    int frames = 8;
    // Script mode: run the editor actions in this file (Script.h), one per frame, then exit.
    std::optional<std::filesystem::path> script;
    // Frame log: at exit, one CSV line per rendered frame (start time, duration, render size and
    // scale, whether the camera moved) is written to this file; for measuring frame rates.
    std::optional<std::filesystem::path> frameLog;
    int width = 1280;  // window size, screen coordinates
    int height = 720;
    // --allow-external-uris, as lit-render's: scenes may read buffers and images outside their
    // folder (absolute paths, "..", file:). Off, such a scene is refused (GltfLimits), so a file
    // from the internet cannot read, and a later Save copy, arbitrary files of the user. Applies
    // to every scene this run opens (command line, File > Open, recent files, script "open").
    bool allowExternalUris = false;
    bool help = false;

    bool scriptMode() const { return script.has_value(); }
    // A person at the window (neither --script nor --screenshot): scenes load in the background,
    // autosave runs, questions are asked.
    bool interactive() const { return !script && !screenshot; }
};

// A command line that cannot be used; the message says which argument and why.
class OptionsError : public std::runtime_error {
public:
    explicit OptionsError(const std::string& message) : std::runtime_error(message) {}
};

// `args` excludes the program name. Throws OptionsError.
EditorOptions parseEditorOptions(std::span<const std::string_view> args);

std::string editorUsage();

}  // namespace lit::editor
