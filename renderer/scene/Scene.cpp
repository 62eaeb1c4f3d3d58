#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lit {

glm::mat4 Node::localMatrix() const {
    return glm::translate(glm::mat4(1.0f), pose.translation.value_or(translation)) *
           glm::mat4_cast(pose.rotation.value_or(rotation)) * glm::scale(glm::mat4(1.0f), pose.scale.value_or(scale));
}

void Scene::updateWorldTransforms() {
    // Iterative depth-first walk: glTF hierarchies can be deep, and cycles were rejected on load.
    std::vector<std::pair<int, glm::mat4>> stack;
    for (int root : roots) stack.emplace_back(root, glm::mat4(1.0f));
    while (!stack.empty()) {
        auto [index, parentWorld] = stack.back();
        stack.pop_back();
        Node& node = nodes[static_cast<std::size_t>(index)];
        node.world = parentWorld * node.localMatrix();
        for (int child : node.children) stack.emplace_back(child, node.world);
    }
}

Aabb Scene::worldBounds() const {
    Aabb bounds;
    for (const Node& node : nodes) {
        if (node.mesh < 0) continue;
        for (const Primitive& p : meshes[static_cast<std::size_t>(node.mesh)].primitives)
            bounds.extend(p.bounds.transformed(node.world));
    }
    return bounds;
}

int Scene::nodeOfCamera(int cameraIndex) const {
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].camera == cameraIndex) return static_cast<int>(i);
    return -1;
}

int Scene::nodeOfLight(int lightIndex) const {
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].light == lightIndex) return static_cast<int>(i);
    return -1;
}

int Scene::findCamera(const std::string& name) const {
    for (std::size_t i = 0; i < cameras.size(); ++i)
        if (cameras[i].name == name) return static_cast<int>(i);
    for (const Node& node : nodes)
        if (node.camera >= 0 && node.name == name) return node.camera;
    return -1;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Node& node : nodes) {
        if (node.mesh < 0) continue;
        for (const Primitive& p : meshes[static_cast<std::size_t>(node.mesh)].primitives) n += p.indices.size() / 3;
    }
    return n;
}

}  // namespace lit
