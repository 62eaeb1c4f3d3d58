#include "Document.h"

#include <algorithm>
#include <tuple>
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

std::vector<std::vector<int>> primitiveMaterialsOf(const Scene& scene) {
    std::vector<std::vector<int>> materials(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        for (const Primitive& p : scene.meshes[m].primitives) materials[m].push_back(p.material);
    return materials;
}

bool operator==(const EditableState& a, const EditableState& b) {
    return sameNodes(a.nodes, b.nodes) && a.materials == b.materials && a.lights == b.lights &&
           a.cameras == b.cameras && a.pathKeys == b.pathKeys && a.pathOptions == b.pathOptions &&
           a.meshCount == b.meshCount && a.primitiveMaterials == b.primitiveMaterials &&
           a.cameraPathName == b.cameraPathName && a.animationChannels == b.animationChannels &&
           a.skinNodes == b.skinNodes && a.otherSceneRoots == b.otherSceneRoots && a.keptNodeItems == b.keptNodeItems;
}

std::vector<std::vector<int>> otherSceneRootsOf(const Scene& scene) {
    std::vector<std::vector<int>> roots;
    for (const Scene::OtherScene& other : scene.otherScenes) roots.push_back(other.roots);
    return roots;
}

std::vector<std::pair<int, int>> keptNodeItemsOf(const Scene& scene) {
    std::vector<std::pair<int, int>> items;
    for (const Node& node : scene.keptNodes) items.emplace_back(node.light, node.camera);
    return items;
}

std::vector<std::vector<Animation::Channel>> animationChannelsOf(const Scene& scene) {
    std::vector<std::vector<Animation::Channel>> channels;
    for (const Animation& animation : scene.animations) channels.push_back(animation.channels);
    return channels;
}

std::vector<std::vector<int>> skinNodesOf(const Scene& scene) {
    std::vector<std::vector<int>> nodes;
    for (const Skin& skin : scene.skins) {
        nodes.push_back(skin.joints);
        nodes.back().push_back(skin.skeleton);
    }
    return nodes;
}

Document::Document(Scene scene_, CameraPath path, std::filesystem::path file_)
    : scene(std::move(scene_)), cameraPath(std::move(path)), file(std::move(file_)) {
    scene.updateWorldTransforms();
    saved_ = capture();
    rememberAlbedoTextures();
}

EditableState Document::capture() const {
    return EditableState{scene.nodes,       scene.materials,      scene.lights,        scene.cameras,
                         cameraPath.keys(), cameraPath.options(), scene.meshes.size(), primitiveMaterialsOf(scene),
                         cameraPathName,    animationChannelsOf(scene), skinNodesOf(scene),
                         otherSceneRootsOf(scene), keptNodeItemsOf(scene)};
}

bool Document::matches(const EditableState& state) const {
    return sameNodes(scene.nodes, state.nodes) && scene.materials == state.materials &&
           scene.lights == state.lights && scene.cameras == state.cameras &&
           cameraPath.keys() == state.pathKeys && cameraPath.options() == state.pathOptions &&
           scene.meshes.size() == state.meshCount && primitiveMaterialsOf(scene) == state.primitiveMaterials &&
           cameraPathName == state.cameraPathName && animationChannelsOf(scene) == state.animationChannels &&
           skinNodesOf(scene) == state.skinNodes && otherSceneRootsOf(scene) == state.otherSceneRoots &&
           keptNodeItemsOf(scene) == state.keptNodeItems;
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
    const bool meshesDiffer =
        scene.meshes.size() != state.meshCount || primitiveMaterialsOf(scene) != state.primitiveMaterials;

    if (path) cameraPath = std::move(*path);
    cameraPathName = state.cameraPathName;
    if (meshesDiffer) {
        // Meshes past the count are the editor's own (addMesh); those the state has and the
        // scene lacks come back from addedMeshes_.
        if (scene.meshes.size() > state.meshCount) scene.meshes.resize(state.meshCount);
        for (std::size_t m = scene.meshes.size(); m < state.meshCount; ++m) {
            if (m < addedMeshes_.size() && addedMeshes_[m]) scene.meshes.push_back(*addedMeshes_[m]);
            else scene.meshes.push_back(Mesh{});  // cannot happen: only addMesh grows the list
        }
        for (std::size_t m = 0; m < scene.meshes.size() && m < state.primitiveMaterials.size(); ++m) {
            std::vector<Primitive>& primitives = scene.meshes[m].primitives;
            for (std::size_t p = 0; p < primitives.size() && p < state.primitiveMaterials[m].size(); ++p)
                primitives[p].material = state.primitiveMaterials[m][p];
        }
        ++scene.geometryRevision;
        ++scene.materialRevision;
    }
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
    // Edits never add or remove animations or skins, only renumber the nodes they name.
    for (std::size_t a = 0; a < scene.animations.size() && a < state.animationChannels.size(); ++a)
        scene.animations[a].channels = state.animationChannels[a];
    for (std::size_t s = 0; s < scene.skins.size() && s < state.skinNodes.size(); ++s) {
        const std::vector<int>& nodes = state.skinNodes[s];
        if (nodes.empty()) continue;
        scene.skins[s].joints.assign(nodes.begin(), nodes.end() - 1);
        scene.skins[s].skeleton = nodes.back();
    }
    for (std::size_t o = 0; o < scene.otherScenes.size() && o < state.otherSceneRoots.size(); ++o)
        scene.otherScenes[o].roots = state.otherSceneRoots[o];
    for (std::size_t k = 0; k < scene.keptNodes.size() && k < state.keptNodeItems.size(); ++k)
        std::tie(scene.keptNodes[k].light, scene.keptNodes[k].camera) = state.keptNodeItems[k];

    if (selectedNode >= static_cast<int>(scene.nodes.size())) selectedNode = -1;
    std::erase_if(alsoSelected, [this](int n) { return n >= static_cast<int>(scene.nodes.size()) || n == selectedNode; });
    if (selectedNode < 0) alsoSelected.clear();
    if (selectedKey >= static_cast<int>(cameraPath.keys().size())) selectedKey = -1;
}

int Document::primitiveCount(int node) const {
    if (node < 0 || node >= static_cast<int>(scene.nodes.size())) return 0;
    const int mesh = scene.nodes[static_cast<std::size_t>(node)].mesh;
    if (mesh < 0 || mesh >= static_cast<int>(scene.meshes.size())) return 0;
    return static_cast<int>(scene.meshes[static_cast<std::size_t>(mesh)].primitives.size());
}

std::string Document::primitiveLabel(int node, int primitive) const {
    if (primitive < 0 || primitive >= primitiveCount(node)) return {};
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(scene.nodes[static_cast<std::size_t>(node)].mesh)];
    const int m = mesh.primitives[static_cast<std::size_t>(primitive)].material;
    const std::string name = m >= 0 && m < static_cast<int>(scene.materials.size())
                                 ? scene.materials[static_cast<std::size_t>(m)].name
                                 : std::string("default material");
    return "Primitive " + std::to_string(primitive) + ": " + name;
}

void Document::selectPrimitive(int node, int primitive) {
    if (primitive < 0 || primitive >= primitiveCount(node)) {
        select(-1);
        return;
    }
    select(node);
    selectedPrimitive = primitive;
    primitivePicked = true;
}

void Document::clickPrimitive(int node, int primitive) {
    const bool part = node == selectedNode && alsoSelected.empty() && primitiveCount(node) > 1;
    selectPrimitive(node, primitive);
    primitivePicked = primitivePicked && part;
}

void Document::select(int node, bool additive) {
    selectedPrimitive = 0;
    primitivePicked = false;
    if (node < 0 || node >= static_cast<int>(scene.nodes.size())) {
        if (!additive) {
            selectedNode = -1;
            alsoSelected.clear();
        }
        return;
    }
    if (!additive || selectedNode < 0) {
        selectedNode = node;
        alsoSelected.clear();
        return;
    }
    if (node == selectedNode) {
        // Shift+click on the active node takes it out; the next one becomes active.
        if (alsoSelected.empty()) {
            selectedNode = -1;
        } else {
            selectedNode = alsoSelected.back();
            alsoSelected.pop_back();
        }
        return;
    }
    if (const auto it = std::find(alsoSelected.begin(), alsoSelected.end(), node); it != alsoSelected.end()) {
        alsoSelected.erase(it);
        return;
    }
    alsoSelected.push_back(selectedNode);
    selectedNode = node;
}

std::vector<int> Document::selection() const {
    std::vector<int> nodes;
    const int count = static_cast<int>(scene.nodes.size());
    if (selectedNode < 0 || selectedNode >= count) return nodes;
    nodes.push_back(selectedNode);
    for (const int n : alsoSelected)
        if (n >= 0 && n < count && std::find(nodes.begin(), nodes.end(), n) == nodes.end()) nodes.push_back(n);
    return nodes;
}

bool Document::isSelected(int node) const {
    if (node < 0) return false;
    const std::vector<int> nodes = selection();
    return std::find(nodes.begin(), nodes.end(), node) != nodes.end();
}

int Document::addMesh(Mesh mesh) {
    const std::size_t index = scene.meshes.size();
    if (addedMeshes_.size() <= index) addedMeshes_.resize(index + 1);
    addedMeshes_[index] = mesh;
    scene.meshes.push_back(std::move(mesh));
    ++scene.geometryRevision;
    return static_cast<int>(index);
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
    a.output.width = b.output.width;
    a.output.height = b.output.height;
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
