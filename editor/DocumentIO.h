#pragma once
// Documents on disk: opening a scene file into a Document (scene, camera path, render settings),
// saving it back, and periodic autosaves offered for recovery after a crash. Window-free
// (lit_editor_core).
//
// A document is stored as
//   <file>            the glTF scene (.gltf + .bin, or .glb) with the camera path as the glTF
//                     animation "camera path" (animation/CameraPathIO.h), so other tools see it;
//   <file>.lit.json   the render settings (RenderSettings JSON), the editor's sidecar.

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "Document.h"
#include "scene/GltfLoader.h"

namespace lit {
class Log;
}

namespace lit::editor {

// "<file>.lit.json": the render settings saved beside a scene.
std::filesystem::path settingsSidecarPath(const std::filesystem::path& sceneFile);

// Loads the scene (loadGltf; throws SceneLoadError), gives it a light and a camera when it has
// none (logged), reads its "camera path" animation when present and its settings sidecar when
// present. A bad camera path or sidecar is a warning in `log` (the document opens with an empty
// path / default settings), not a failure. The document is clean, its file `file`. Logs a
// summary line (meshes, triangles, textures, MB, milliseconds). `progress` (optional) is called
// on the calling thread as loading goes (GltfLoader.h). `limits` bound what the file may make
// the loader read and allocate (io/GltfGuard.h; lit-editor --allow-external-uris sets
// allowExternalUris).
Document openDocument(const std::filesystem::path& file, Log& log,
                      const std::function<void(const LoadProgress&)>& progress = {}, const GltfLimits& limits = {});

// Makes camera animation `name` the one the camera path edits (the timeline's animation combo,
// script "animation NAME"): read from the document's file when the file has it, else a new
// empty path under that name. One undo step. The path edited before stays in the file as it was
// last saved; its unsaved key edits are dropped (undo brings them back). Returns "" or why not.
std::string chooseCameraAnimation(Document& doc, const std::string& name);

// Writes the scene and camera path to `file` (saveGltf: .gltf or .glb) and the settings sidecar
// as one commit (io/AtomicFile.h: after a crash, all old or all new once recovered); sets
// doc.file and marks the document saved. Throws (SceneSaveError or
// std::runtime_error naming the file) and leaves the document as it was when anything fails.
void saveDocument(Document& doc, const std::filesystem::path& file);

// An autosave that a session which did not exit cleanly left behind.
struct AutosaveInfo {
    std::filesystem::path autosaveFile;  // <folder>/autosave-1.glb or autosave-2.glb
    std::filesystem::path documentFile;  // the document's own file ("" = never saved)
    std::string timeText;                // when it was written, local time: "2026-12-01 16:05"
};

// Periodic copies of a dirty document into a state folder, and recovery after a crash.
//
// A session writes "<folder>/session.lock" (its pid) when it starts and removes it in
// cleanExit(). Finding a lock whose process is gone (or this process: an earlier Autosave
// object that was never cleanly closed) together with an autosave means the last session
// crashed: recoverable() offers it. Until the user recovers or discards it, this session
// writes no autosave of its own (it would overwrite the copy). A lock held by another running
// editor leaves this session without autosave (both would write the same files).
//
// Files: the copy "<folder>/autosave-1.glb" or "autosave-2.glb" (scene + camera path, saveGltf),
// and "<folder>/autosave.json" ({"version", "scene", "document", "savedAt", "settings"}), which
// names the copy. A save writes the copy the marker does NOT name, then replaces the marker
// atomically (the single commit point: the copy and its settings change together), then removes
// the other copy. A crash at any moment leaves the marker naming a complete copy: the last
// autosave that finished. Leftovers of an interrupted autosave (a copy the marker does not name,
// temporaries) are removed when the next session starts. Failures never throw out of
// maybeSave(): they are kept in lastError() and tried again after the next interval.
class Autosave {
public:
    static constexpr double kDefaultIntervalSeconds = 60.0;

    // $XDG_STATE_HOME/lit, else ~/.local/state/lit (else <temp>/lit when there is no HOME).
    static std::filesystem::path defaultFolder();

    Autosave();  // defaultFolder()
    explicit Autosave(std::filesystem::path folder, double intervalSeconds = kDefaultIntervalSeconds);
    Autosave(const Autosave&) = delete;
    Autosave& operator=(const Autosave&) = delete;
    // Leaves the lock: only cleanExit() says the session ended well.
    ~Autosave() = default;

    // Call every frame. Writes a copy when the document is dirty, differs from the last copy,
    // and `intervalSeconds` have passed since the last write (or since the first call). A
    // document that has become clean (saved) has its old copy removed. `nowSeconds` is any
    // steadily increasing clock.
    void maybeSave(const Document& doc, double nowSeconds);
    void maybeSave(const Document& doc, std::chrono::system_clock::time_point now);
    // Writes a copy now; throws on failure (maybeSave catches).
    void saveNow(const Document& doc);

    std::optional<AutosaveInfo> recoverable() const;
    // Loads the recoverable copy: its file is the original document's, its settings those of the
    // copy, and it is dirty (it differs from that file). Throws when the copy cannot be read.
    Document recover(Log& log);
    // Deletes the copy (recoverable or this session's).
    void discard();
    // The session ends normally: deletes the copy and the lock. A crash's copy that was neither
    // recovered nor discarded is kept, and offered again at the next start.
    void cleanExit();

    const std::filesystem::path& folder() const { return folder_; }
    // The copy the marker names (autosave-1.glb when there is none yet).
    std::filesystem::path autosaveFile() const { return folder_ / (copyName_.empty() ? "autosave-1.glb" : copyName_); }
    std::filesystem::path markerFile() const { return folder_ / "autosave.json"; }
    std::filesystem::path lockFile() const { return folder_ / "session.lock"; }
    bool active() const { return active_; }       // false: another editor holds the lock, or no folder
    const std::string& lastError() const { return lastError_; }

private:
    std::filesystem::path folder_;
    double interval_;
    bool active_ = false;
    std::optional<AutosaveInfo> recoverable_;
    std::optional<double> lastWrite_;           // nowSeconds of the last write (or the first call)
    // What the copy on disk holds.
    struct Copy {
        EditableState state;
        RenderSettings settings;
        std::filesystem::path file;
        bool operator==(const Copy&) const = default;
    };
    static Copy copyOf(const Document& doc) { return {doc.capture(), doc.settings, doc.file}; }
    std::optional<Copy> written_;
    std::string lastError_;
    std::string copyName_;  // file name of the copy the marker names; "" = none
};

}  // namespace lit::editor
