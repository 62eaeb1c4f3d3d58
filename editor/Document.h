#pragma once
// The document the editor works on: the scene, its camera path and render settings, the file it
// came from, the selection, and the undo history. Window-free and ImGui-free (lit_editor_core)
// so the CPU tests drive it exactly as the panels and the --script runner do.
//
// Undo works on snapshots of the editable part of the scene (nodes, materials, lights, cameras,
// camera path): small next to meshes and images, and a snapshot cannot get an inverse wrong.
// An edit is bracketed: beginEdit() snapshots the state before, the caller changes the scene
// (as often as it likes: a slider drag changes it every frame), endEdit() compares and pushes
// one undo step if anything changed. So a whole slider drag is one step.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "RenderSettings.h"
#include "animation/CameraPath.h"
#include "scene/Scene.h"

namespace lit::editor {

// What undo/redo restores. Everything else in the Scene (meshes, images, textures) is never
// edited by the editor.
struct EditableState {
    std::vector<Node> nodes;
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<CameraKey> pathKeys;
    CameraPathOptions pathOptions;
};

// Which revision counters an edit must bump so the renderer redoes the right work.
enum class Change : std::uint8_t {
    Transform,  // a node moved: world transforms, BVH, shadows, voxels
    Material,   // re-voxelize albedo/emission
    Light,      // re-render shadows, re-inject
    Camera,     // nothing for the renderer (cameras are read per frame)
    CameraPath, // the path's keys or options
};

class Document {
public:
    Document() = default;
    // Takes a freshly loaded scene (and its camera path, possibly empty).
    Document(Scene scene, CameraPath path, std::filesystem::path file);

    Scene scene;
    CameraPath cameraPath;
    RenderSettings settings;
    std::filesystem::path file;  // where Save writes; empty for an unsaved new document

    // ---- selection (not part of undo) ----------------------------------------------------
    int selectedNode = -1;  // index into scene.nodes, -1 = none
    int selectedKey = -1;   // index into cameraPath keys, -1 = none

    // ---- editing ---------------------------------------------------------------------------
    // Starts an edit named `label` ("Roughness", "Move Light") unless one is open.
    void beginEdit(const std::string& label);
    // Call after changing the scene during an edit: bumps the revision counters `change` needs
    // (a Transform change also recomputes world transforms). Works outside an edit too.
    void touched(Change change);
    // Ends the open edit: one undo step when the state differs from the snapshot, none when
    // the edit changed nothing. Clears the redo list when a step is pushed.
    void endEdit();
    bool editOpen() const;

    // A one-shot edit: beginEdit(label), apply, touched(change), endEdit().
    // When `apply` throws (a CameraPathError from a bad key, say), the edit is cancelled: the
    // state goes back to before it and the exception propagates.
    template <class Fn>
    void edit(const std::string& label, Change change, Fn&& apply) {
        beginEdit(label);
        try {
            apply(scene);
        } catch (...) {
            cancelEdit();
            throw;
        }
        touched(change);
        endEdit();
    }
    // Ends the open edit without an undo step, restoring the state from before it.
    void cancelEdit();

    bool canUndo() const;
    bool canRedo() const;
    std::string undoLabel() const;  // "" when there is nothing to undo
    std::string redoLabel() const;
    // Restore the state before / after the last step. Ends an open edit first. Bump every
    // revision counter whose data differs. Return false when there is nothing to do.
    bool undo();
    bool redo();
    static constexpr std::size_t kMaxUndoSteps = 256;

    // ---- saving ----------------------------------------------------------------------------
    // True when the editable state differs from the one last saved (or loaded). Undoing back to
    // the saved state makes the document clean again.
    // Render settings count too (they are saved beside the scene), except the output size, which
    // follows the window; they are not undo steps.
    bool dirty() const;
    void markSaved();
    // Dirty until the next markSaved() whatever the state: for a document that is not what its
    // file holds although no edit was made here (a recovered autosave).
    void markUnsaved();

    EditableState capture() const;
    void restore(const EditableState& state);

    // The albedo (base colour) texture material `material` has, or had before it was switched
    // off in this session (Properties: material.albedoTexture on); -1 when it never had one.
    int rememberedAlbedoTexture(int material) const;

private:
    struct Step {
        std::string label;
        EditableState before, after;
    };
    // The state equals `state` (Node::world is derived and left out of the comparison).
    bool matches(const EditableState& state) const;
    void rememberAlbedoTextures();

    std::vector<Step> undo_, redo_;  // oldest first
    std::optional<Step> open_;       // the edit in progress ("after" unused until it ends)
    // What was last saved or loaded. Comparing the state itself (rather than counting steps)
    // makes an edit that is undone by hand, or undone back to the saved point, clean again.
    EditableState saved_;
    RenderSettings savedSettings_;  // the settings saved in the sidecar, to tell when they change
    bool unsaved_ = false;  // markUnsaved()
    // Per material, the last albedo texture it had in this session (-1 = none), so that
    // "material.albedoTexture off" can be turned on again.
    std::vector<int> albedoTextures_;
};

// Equality of editable states, ignoring the derived Node::world.
bool operator==(const EditableState& a, const EditableState& b);

}  // namespace lit::editor
