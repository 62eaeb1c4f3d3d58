#include "Document.h"

#include <algorithm>
#include <utility>

namespace lit::editor {

namespace {

// Every field of a node except `world`, which updateWorldTransforms() derives from the others:
// comparing it would make a document whose world matrices were recomputed look edited.
bool sameNode(const Node& a, const Node& b) {
    return a.name == b.name && a.parent == b.parent && a.children == b.children &&
           a.translation == b.translation && a.rotation == b.rotation && a.scale == b.scale &&
           a.mesh == b.mesh && a.light == b.light && a.camera == b.camera;
}

bool sameNodes(const std::vector<Node>& a, const std::vector<Node>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameNode);
}

bool sameHierarchy(const std::vector<Node>& a, const std::vector<Node>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const Node& x, const Node& y) { return x.parent == y.parent; });
}

}  // namespace

bool operator==(const EditableState& a, const EditableState& b) {
    return sameNodes(a.nodes, b.nodes) && a.materials == b.materials && a.lights == b.lights &&
           a.cameras == b.cameras && a.pathKeys == b.pathKeys && a.pathOptions == b.pathOptions;
}

Document::Document(Scene scene_, CameraPath path, std::filesystem::path file_)
    : scene(std::move(scene_)), cameraPath(std::move(path)), file(std::move(file_)) {
    scene.updateWorldTransforms();
    saved_ = capture();
    rememberAlbedoTextures();
}

EditableState Document::capture() const {
    return EditableState{scene.nodes,         scene.materials,        scene.lights,
                         scene.cameras,       cameraPath.keys(),      cameraPath.options()};
}

bool Document::matches(const EditableState& state) const {
    return sameNodes(scene.nodes, state.nodes) && scene.materials == state.materials &&
           scene.lights == state.lights && scene.cameras == state.cameras &&
           cameraPath.keys() == state.pathKeys && cameraPath.options() == state.pathOptions;
}

void Document::restore(const EditableState& state) {
    // The camera path is the only part that can refuse the state (CameraPathError), so it is
    // built first, aside: when it throws, nothing has been changed yet.
    const bool pathDiffers = cameraPath.keys() != state.pathKeys || cameraPath.options() != state.pathOptions;
    std::optional<CameraPath> path;
    if (pathDiffers) path.emplace(state.pathKeys, state.pathOptions);

    const bool nodesDiffer = !sameNodes(scene.nodes, state.nodes);
    const bool hierarchyDiffers = !sameHierarchy(scene.nodes, state.nodes);
    const bool materialsDiffer = scene.materials != state.materials;
    const bool lightsDiffer = scene.lights != state.lights;

    if (path) cameraPath = std::move(*path);
    if (nodesDiffer) {
        scene.nodes = state.nodes;
        if (hierarchyDiffers) {
            scene.roots.clear();
            for (int i = 0; i < static_cast<int>(scene.nodes.size()); ++i)
                if (scene.nodes[i].parent < 0) scene.roots.push_back(i);
        }
        scene.updateWorldTransforms();
        ++scene.geometryRevision;
    }
    if (materialsDiffer) {
        scene.materials = state.materials;
        ++scene.materialRevision;
    }
    if (lightsDiffer) {
        scene.lights = state.lights;
        ++scene.lightRevision;
    }
    scene.cameras = state.cameras;

    if (selectedNode >= static_cast<int>(scene.nodes.size())) selectedNode = -1;
    if (selectedKey >= static_cast<int>(cameraPath.keys().size())) selectedKey = -1;
}

void Document::beginEdit(const std::string& label) {
    if (open_) return;
    rememberAlbedoTextures();
    open_ = Step{label, capture(), {}};
}

void Document::touched(Change change) {
    switch (change) {
    case Change::Transform:
        scene.updateWorldTransforms();
        ++scene.geometryRevision;
        break;
    case Change::Material: ++scene.materialRevision; break;
    case Change::Light: ++scene.lightRevision; break;
    case Change::Camera:      // cameras are read every frame
    case Change::CameraPath:  // the path is evaluated every frame
        break;
    }
}

void Document::endEdit() {
    if (!open_) return;
    Step step = std::move(*open_);
    open_.reset();
    if (matches(step.before)) return;
    step.after = capture();
    undo_.push_back(std::move(step));
    if (undo_.size() > kMaxUndoSteps) undo_.erase(undo_.begin());
    redo_.clear();
}

void Document::cancelEdit() {
    if (!open_) return;
    Step step = std::move(*open_);
    open_.reset();
    restore(step.before);
}

bool Document::editOpen() const { return open_.has_value(); }

bool Document::canUndo() const { return !undo_.empty() || (open_ && !matches(open_->before)); }

bool Document::canRedo() const { return !redo_.empty() && !(open_ && !matches(open_->before)); }

std::string Document::undoLabel() const {
    if (open_ && !matches(open_->before)) return open_->label;
    return undo_.empty() ? std::string() : undo_.back().label;
}

std::string Document::redoLabel() const { return canRedo() ? redo_.back().label : std::string(); }

bool Document::undo() {
    endEdit();
    if (undo_.empty()) return false;
    restore(undo_.back().before);
    redo_.push_back(std::move(undo_.back()));
    undo_.pop_back();
    return true;
}

bool Document::redo() {
    endEdit();
    if (redo_.empty()) return false;
    restore(redo_.back().after);
    undo_.push_back(std::move(redo_.back()));
    redo_.pop_back();
    return true;
}

namespace {
bool sameSettingsIgnoringSize(RenderSettings a, RenderSettings b) {
    a.width = b.width;
    a.height = b.height;
    return a == b;
}
}  // namespace

bool Document::dirty() const {
    return unsaved_ || !matches(saved_) || !sameSettingsIgnoringSize(settings, savedSettings_);
}

void Document::markSaved() {
    saved_ = capture();
    savedSettings_ = settings;
    unsaved_ = false;
}

void Document::markUnsaved() { unsaved_ = true; }

void Document::rememberAlbedoTextures() {
    if (albedoTextures_.size() < scene.materials.size()) albedoTextures_.resize(scene.materials.size(), -1);
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].baseColorTexture >= 0) albedoTextures_[i] = scene.materials[i].baseColorTexture;
}

int Document::rememberedAlbedoTexture(int material) const {
    if (material < 0 || material >= static_cast<int>(scene.materials.size())) return -1;
    if (scene.materials[material].baseColorTexture >= 0) return scene.materials[material].baseColorTexture;
    return material < static_cast<int>(albedoTextures_.size()) ? albedoTextures_[material] : -1;
}

}  // namespace lit::editor
