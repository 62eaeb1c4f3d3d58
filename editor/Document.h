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
#include <utility>
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
    // Meshes are large and only the editor's own generated ones are ever added: the state keeps
    // their count (the Document keeps the meshes it added, to bring them back on redo) and each
    // primitive's material index (per mesh, per primitive), which "make unique" changes.
    std::size_t meshCount = 0;
    std::vector<std::vector<int>> primitiveMaterials;
    std::string cameraPathName;  // the glTF animation the camera path is saved as
    // What else names nodes, renumbered by a delete: each animation's channels, and each skin's
    // joints followed by its skeleton node.
    std::vector<std::vector<Animation::Channel>> animationChannels;
    std::vector<std::vector<int>> skinNodes;
    // Each other scene's roots, and each kept node's light and camera (scene/Scene.h: keptNodes;
    // a delete renumbers lights and cameras).
    std::vector<std::vector<int>> otherSceneRoots;
    std::vector<std::pair<int, int>> keptNodeItems;
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
    int selectedNode = -1;  // the active node (inspector, gizmo): index into scene.nodes, -1 = none
    // More nodes selected with Shift besides the active one; transform, delete and duplicate
    // apply to all of them. Kept free of selectedNode and of invalid indices by select().
    std::vector<int> alsoSelected;
    int selectedKey = -1;   // index into cameraPath keys, -1 = none
    // Which primitive of the active node's mesh the inspector's material section (and the
    // "material.*" properties) edit.
    int selectedPrimitive = 0;
    // The selection is that one primitive of the active node, not the whole node: a click on a
    // part of the active node's mesh, a primitive's row in the hierarchy, the inspector's choice.
    // The outline then shows the primitive alone (a part of a one-node scene such as Sponza).
    bool primitivePicked = false;

    // Selects `node` (-1: nothing). additive (Shift): toggles `node` in the selection and makes
    // it the active node when it is added. Always resets selectedPrimitive and primitivePicked.
    void select(int node, bool additive = false);
    // Selects primitive `primitive` of `node`'s mesh alone (nothing when either is out of range).
    void selectPrimitive(int node, int primitive);
    // A click (no Shift) on primitive `primitive` of `node` in the viewport: the first click on a
    // node selects it whole, with the part clicked as the inspector's primitive; a click on the
    // active node picks the part under the cursor when its mesh has several (as Unity's second
    // click selects a child), so a one-node scene's parts can be picked.
    void clickPrimitive(int node, int primitive);
    // "Primitive 3: <material name>" for the inspector and the hierarchy.
    std::string primitiveLabel(int node, int primitive) const;
    // The primitives of `node`'s mesh; 0 for a node without one or out of range.
    int primitiveCount(int node) const;
    // The active node first, then the others; empty when nothing is selected.
    std::vector<int> selection() const;
    bool isSelected(int node) const;

    // Why the last edit a panel asked for was refused ("cannot make Box a child of its own
    // child"); the App logs it as a warning and clears it. Not part of undo.
    std::string lastRefusal;

    // ---- camera animations -----------------------------------------------------------------
    // The glTF animation the camera path is read from and saved as ("camera path" unless the
    // file had other camera animations only), and every camera animation the file holds.
    std::string cameraPathName = "camera path";
    std::vector<std::string> cameraAnimations;

    // ---- meshes ----------------------------------------------------------------------------
    // Appends a mesh the editor made (a primitive, a copy for "make unique") and returns its
    // index; undo drops it and redo brings it back. Call inside an edit.
    int addMesh(Mesh mesh);

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
    // Every mesh addMesh() appended, by mesh index, so a redo can put it back after an undo
    // removed it. A new mesh at an index replaces the old one (the redo list is gone by then).
    std::vector<std::optional<Mesh>> addedMeshes_;
};

// Equality of editable states, ignoring the derived Node::world.
bool operator==(const EditableState& a, const EditableState& b);

}  // namespace lit::editor
