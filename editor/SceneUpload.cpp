#include "SceneUpload.h"

#include <exception>
#include <string>

namespace lit::editor {

namespace {

// What the renderer's GpuScene depends on besides transforms and material values: the nodes'
// meshes, the meshes' primitives' materials and the material count.
std::vector<int> structureOf(const Scene& scene) {
    std::vector<int> structure;
    structure.reserve(scene.nodes.size() + scene.meshes.size() * 2 + 4);
    structure.push_back(static_cast<int>(scene.nodes.size()));
    for (const Node& node : scene.nodes) structure.push_back(node.mesh);
    structure.push_back(static_cast<int>(scene.meshes.size()));
    for (const Mesh& mesh : scene.meshes) {
        structure.push_back(static_cast<int>(mesh.primitives.size()));
        for (const Primitive& p : mesh.primitives) structure.push_back(p.material);
    }
    structure.push_back(static_cast<int>(scene.materials.size()));
    return structure;
}

}  // namespace

void SceneUpload::upload(const Scene& scene) {
    ++uploads_;
    renderer_.setScene(scene);
    uploaded_ = structureOf(scene);
}

void SceneUpload::syncStructure(const Scene& scene, Log& log) {
    std::vector<int> structure = structureOf(scene);
    if (structure == uploaded_) return;
    ++uploads_;
    try {
        renderer_.setScene(scene);
    } catch (const std::exception& error) {
        log.error(std::string("cannot upload the edited scene: ") + error.what());
    }
    uploaded_ = std::move(structure);
}

}  // namespace lit::editor
