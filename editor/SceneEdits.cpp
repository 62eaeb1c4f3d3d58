#include "SceneEdits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "ViewportOverlay.h"
#include "scene/SceneBuilder.h"
#include "scene/Tangents.h"

namespace lit::editor {

namespace {

constexpr float kPi = 3.14159265358979f;

struct KindInfo {
    NodeKind kind;
    const char* name;   // script / menu name
    const char* label;  // node name and undo label
};
constexpr std::array<KindInfo, 8> kKinds{{
    {NodeKind::Empty, "empty", "Empty"},
    {NodeKind::DirectionalLight, "directional", "Sun"},
    {NodeKind::PointLight, "point", "Point light"},
    {NodeKind::SpotLight, "spot", "Spot light"},
    {NodeKind::Camera, "camera", "Camera"},
    {NodeKind::Box, "box", "Box"},
    {NodeKind::Plane, "plane", "Plane"},
    {NodeKind::Sphere, "sphere", "Sphere"},
}};

const KindInfo& infoOf(NodeKind kind) {
    for (const KindInfo& info : kKinds)
        if (info.kind == kind) return info;
    return kKinds[0];
}

bool validNode(const Scene& scene, int node) { return node >= 0 && node < static_cast<int>(scene.nodes.size()); }

// Whether `ancestor` is `node` or above it.
bool isAncestorOrSelf(const Scene& scene, int ancestor, int node) {
    for (std::size_t depth = 0; node >= 0 && depth <= scene.nodes.size(); ++depth) {
        if (node == ancestor) return true;
        node = scene.nodes[static_cast<std::size_t>(node)].parent;
    }
    return false;
}

glm::mat4 parentWorld(const Scene& scene, int node) {
    const int parent = scene.nodes[static_cast<std::size_t>(node)].parent;
    return parent >= 0 ? scene.nodes[static_cast<std::size_t>(parent)].world : glm::mat4(1.0f);
}

std::string nodeLabel(const Scene& scene, int node) {
    const std::string& name = scene.nodes[static_cast<std::size_t>(node)].name;
    return name.empty() ? "node " + std::to_string(node) : name;
}

// The label of a step on the selection: the node's name for one node, "3 nodes" for more.
std::string selectionLabel(const Document& doc, const std::vector<int>& nodes) {
    return nodes.size() == 1 ? nodeLabel(doc.scene, nodes.front()) : std::to_string(nodes.size()) + " nodes";
}

// The base of a name without a Blender-style ".NNN" suffix.
std::string nameBase(const std::string& name) {
    const std::size_t dot = name.rfind('.');
    if (dot == std::string::npos || dot + 4 != name.size()) return name;
    for (std::size_t i = dot + 1; i < name.size(); ++i)
        if (name[i] < '0' || name[i] > '9') return name;
    return name.substr(0, dot);
}

std::string uniqueMaterialName(const Scene& scene, const std::string& base) {
    auto used = [&scene](const std::string& name) {
        return std::any_of(scene.materials.begin(), scene.materials.end(),
                           [&name](const Material& m) { return m.name == name; });
    };
    const std::string stem = nameBase(base);
    for (int i = 1;; ++i) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", i);
        if (!used(stem + suffix)) return stem + suffix;
    }
}

}  // namespace

const char* nodeKindName(NodeKind kind) { return infoOf(kind).name; }

std::optional<NodeKind> parseNodeKind(std::string_view name) {
    for (const KindInfo& info : kKinds)
        if (name == info.name) return info.kind;
    return std::nullopt;
}

const std::vector<NodeKind>& allNodeKinds() {
    static const std::vector<NodeKind> kinds = [] {
        std::vector<NodeKind> all;
        for (const KindInfo& info : kKinds) all.push_back(info.kind);
        return all;
    }();
    return kinds;
}

Mesh makeSphereMesh(const std::string& name, float radius, int material, int rings, int segments) {
    rings = std::max(rings, 2);
    segments = std::max(segments, 3);
    Mesh mesh{name, {}};
    Primitive p;
    p.material = material;
    // (rings + 1) rows of (segments + 1) vertices: the seam column is doubled so UVs wrap.
    for (int r = 0; r <= rings; ++r) {
        const float theta = kPi * static_cast<float>(r) / static_cast<float>(rings);  // from +Y down
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            Vertex v;
            v.normal = n;
            v.position = radius * n;
            v.uv = {static_cast<float>(s) / static_cast<float>(segments), static_cast<float>(r) / static_cast<float>(rings)};
            v.uv1 = v.uv;
            p.vertices.push_back(v);
            p.bounds.extend(v.position);
        }
    }
    const auto row = static_cast<std::uint32_t>(segments + 1);
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = static_cast<std::uint32_t>(r) * row + static_cast<std::uint32_t>(s);
            const std::uint32_t b = a + row;
            // Counter-clockwise seen from outside; the pole rows degenerate to one triangle each.
            if (r != 0) p.indices.insert(p.indices.end(), {a, b, a + 1});
            if (r != rings - 1) p.indices.insert(p.indices.end(), {a + 1, b, b + 1});
        }
    computeTangents(p);
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

std::string uniqueNodeName(const Scene& scene, const std::string& base) {
    auto used = [&scene](const std::string& name) {
        return std::any_of(scene.nodes.begin(), scene.nodes.end(), [&name](const Node& n) { return n.name == name; });
    };
    if (!used(base)) return base;
    const std::string stem = nameBase(base);
    for (int i = 1;; ++i) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", i);
        if (!used(stem + suffix)) return stem + suffix;
    }
}

void rebuildRoots(Scene& scene) {
    scene.roots.clear();
    for (int i = 0; i < static_cast<int>(scene.nodes.size()); ++i)
        if (scene.nodes[static_cast<std::size_t>(i)].parent < 0) scene.roots.push_back(i);
    scene.updateWorldTransforms();
}

void decomposeTransform(const glm::mat4& matrix, glm::vec3& translation, glm::quat& rotation, glm::vec3& scale) {
    translation = glm::vec3(matrix[3]);
    glm::vec3 columns[3] = {glm::vec3(matrix[0]), glm::vec3(matrix[1]), glm::vec3(matrix[2])};
    scale = {glm::length(columns[0]), glm::length(columns[1]), glm::length(columns[2])};
    if (glm::dot(glm::cross(columns[0], columns[1]), columns[2]) < 0.0f) scale.x = -scale.x;
    for (int i = 0; i < 3; ++i) columns[i] = scale[i] != 0.0f ? columns[i] / scale[i] : glm::vec3(0.0f);
    // Gram-Schmidt: shear (non-uniform scale under a rotated parent) leaves the columns slightly
    // non-orthogonal; the nearest rotation keeps the first axis exact.
    columns[0] = glm::length(columns[0]) > 0.0f ? glm::normalize(columns[0]) : glm::vec3(1, 0, 0);
    columns[1] = columns[1] - glm::dot(columns[1], columns[0]) * columns[0];
    columns[1] = glm::length(columns[1]) > 1e-6f ? glm::normalize(columns[1]) : glm::vec3(0, 1, 0);
    columns[2] = glm::cross(columns[0], columns[1]);
    rotation = glm::normalize(glm::quat_cast(glm::mat3(columns[0], columns[1], columns[2])));
}

void setWorldMatrix(Scene& scene, int index, const glm::mat4& world) {
    Node& node = scene.nodes[static_cast<std::size_t>(index)];
    glm::vec3 translation, scale;
    glm::quat rotation;
    decomposeTransform(glm::inverse(parentWorld(scene, index)) * world, translation, rotation, scale);
    // A channel a node animation drives shows the animation, not the rest transform: the edit goes
    // to the rest transform's other channels, and the driven ones keep their rest values (taking
    // the posed value would bake the time shown into the saved rest pose).
    if (!node.pose.translation) node.translation = translation;
    if (!node.pose.rotation) node.rotation = rotation;
    if (!node.pose.scale) node.scale = scale;
}

std::vector<int> topLevelSelection(const Document& doc) {
    const std::vector<int> selected = doc.selection();
    std::vector<int> top;
    for (const int node : selected) {
        const int parent = doc.scene.nodes[static_cast<std::size_t>(node)].parent;
        const bool underSelected = std::any_of(selected.begin(), selected.end(), [&](int other) {
            return other != node && parent >= 0 && isAncestorOrSelf(doc.scene, other, parent);
        });
        if (!underSelected) top.push_back(node);
    }
    return top;
}

float midGreyLightIntensity(LightType type, float distance, float exposureEv) {
    constexpr float kPi = 3.14159265f;
    const float d = type == LightType::Directional ? 1.0f : std::max(distance, 0.01f);
    return kMiddleGrey * kPi * d * d / std::exp2(exposureEv);
}

int addNode(Document& doc, NodeKind kind, glm::vec3 position, glm::vec3 direction, float lightDistance) {
    const KindInfo& info = infoOf(kind);
    int index = -1;
    doc.edit(std::string("Add ") + info.label, Change::Transform, [&](Scene& scene) {
        Node node;
        node.name = uniqueNodeName(scene, info.label);
        node.translation = position;
        const bool aims = kind == NodeKind::DirectionalLight || kind == NodeKind::SpotLight || kind == NodeKind::Camera;
        if (aims && glm::length(direction) > 0.0f) node.rotation = rotationLookingAlong(glm::normalize(direction));
        switch (kind) {
        case NodeKind::Empty: break;
        case NodeKind::DirectionalLight:
        case NodeKind::PointLight:
        case NodeKind::SpotLight: {
            Light light;
            light.name = node.name;
            light.type = kind == NodeKind::DirectionalLight ? LightType::Directional
                         : kind == NodeKind::PointLight      ? LightType::Point
                                                             : LightType::Spot;
            light.intensity = midGreyLightIntensity(light.type, lightDistance, doc.settings.output.exposureEv);
            if (kind == NodeKind::SpotLight) light.innerConeAngle = 0.5f * light.outerConeAngle;
            scene.lights.push_back(light);
            node.light = static_cast<int>(scene.lights.size() - 1);
            ++scene.lightRevision;
            break;
        }
        case NodeKind::Camera: {
            Camera camera;
            camera.name = node.name;
            scene.cameras.push_back(camera);
            node.camera = static_cast<int>(scene.cameras.size() - 1);
            break;
        }
        case NodeKind::Box:
        case NodeKind::Plane:
        case NodeKind::Sphere: {
            // Its own material, so editing the new object's colour changes nothing else.
            Material material;
            material.name = uniqueMaterialName(scene, node.name + " material");
            material.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
            material.metallic = 0.0f;
            material.roughness = 0.5f;
            scene.materials.push_back(material);
            ++scene.materialRevision;
            const int m = static_cast<int>(scene.materials.size() - 1);
            Mesh mesh = kind == NodeKind::Box     ? makeBoxMesh(node.name, glm::vec3(kPrimitiveBoxSide), m)
                        : kind == NodeKind::Plane ? makePlaneMesh(node.name, kPrimitivePlaneSide, m)
                                                  : makeSphereMesh(node.name, kPrimitiveSphereRadius, m);
            node.mesh = doc.addMesh(std::move(mesh));
            break;
        }
        }
        scene.nodes.push_back(std::move(node));
        index = static_cast<int>(scene.nodes.size() - 1);
        rebuildRoots(scene);
    });
    doc.select(index);
    return index;
}

int addNodeInFront(Document& doc, NodeKind kind, glm::vec3 eye, glm::vec3 forward) {
    const Aabb bounds = doc.scene.worldBounds();
    const float distance = bounds.empty() ? 2.0f : std::clamp(0.1f * glm::length(bounds.size()), 1.0f, 10.0f);
    const glm::vec3 direction =
        kind == NodeKind::DirectionalLight ? glm::normalize(forward + glm::vec3(0.0f, -1.0f, 0.0f)) : forward;
    return addNode(doc, kind, eye + forward * distance, direction, distance);
}

std::string deleteSelection(Document& doc) {
    const std::vector<int> top = topLevelSelection(doc);
    if (top.empty()) return "nothing is selected";
    const std::string label = "Delete " + selectionLabel(doc, top);
    doc.edit(label, Change::Transform, [&](Scene& scene) {
        const std::size_t count = scene.nodes.size();
        std::vector<bool> removed(count, false);
        for (std::size_t i = 0; i < count; ++i)
            for (const int t : top)
                if (isAncestorOrSelf(scene, t, static_cast<int>(i))) removed[i] = true;
        // New indices of the nodes that stay.
        std::vector<int> remap(count, -1);
        int next = 0;
        for (std::size_t i = 0; i < count; ++i)
            if (!removed[i]) remap[i] = next++;
        // Lights and cameras that only deleted nodes held go too.
        std::vector<bool> lightUsed(scene.lights.size(), false), cameraUsed(scene.cameras.size(), false);
        std::vector<bool> lightDeleted(scene.lights.size(), false), cameraDeleted(scene.cameras.size(), false);
        const auto markUse = [&](const Node& n, bool deleted) {
            if (n.light >= 0 && n.light < static_cast<int>(scene.lights.size()))
                (deleted ? lightDeleted : lightUsed)[static_cast<std::size_t>(n.light)] = true;
            if (n.camera >= 0 && n.camera < static_cast<int>(scene.cameras.size()))
                (deleted ? cameraDeleted : cameraUsed)[static_cast<std::size_t>(n.camera)] = true;
        };
        for (std::size_t i = 0; i < count; ++i) markUse(scene.nodes[i], removed[i]);
        for (const Node& n : scene.keptNodes) markUse(n, false);  // the file's nodes outside the shown scene
        auto compact = [](auto& items, const std::vector<bool>& deleted, const std::vector<bool>& used) {
            std::vector<int> map(items.size(), -1);
            std::size_t keep = 0;
            for (std::size_t i = 0; i < items.size(); ++i) {
                if (deleted[i] && !used[i]) continue;
                map[i] = static_cast<int>(keep);
                if (keep != i) items[keep] = std::move(items[i]);
                ++keep;
            }
            items.resize(keep);
            return map;
        };
        const std::vector<int> lightMap = compact(scene.lights, lightDeleted, lightUsed);
        const std::vector<int> cameraMap = compact(scene.cameras, cameraDeleted, cameraUsed);

        const auto renumberItems = [&](Node& n) {
            if (n.light >= 0 && n.light < static_cast<int>(lightMap.size())) n.light = lightMap[static_cast<std::size_t>(n.light)];
            if (n.camera >= 0 && n.camera < static_cast<int>(cameraMap.size()))
                n.camera = cameraMap[static_cast<std::size_t>(n.camera)];
        };
        for (Node& n : scene.keptNodes) renumberItems(n);
        std::vector<Node> nodes;
        nodes.reserve(static_cast<std::size_t>(next));
        for (std::size_t i = 0; i < count; ++i) {
            if (removed[i]) continue;
            Node n = std::move(scene.nodes[i]);
            n.parent = n.parent >= 0 ? remap[static_cast<std::size_t>(n.parent)] : -1;
            std::vector<int> children;
            for (const int c : n.children)
                if (remap[static_cast<std::size_t>(c)] >= 0) children.push_back(remap[static_cast<std::size_t>(c)]);
            n.children = std::move(children);
            renumberItems(n);
            nodes.push_back(std::move(n));
        }
        scene.nodes = std::move(nodes);
        // What else names nodes follows the renumbering: animation channels of deleted nodes go,
        // a skin with a deleted joint keeps -1 there (the writer then leaves it out), and other
        // scenes lose deleted roots. References to kept nodes (scene/Scene.h: keptNodeRef) stay.
        const auto renumber = [&](int node) {
            if (node <= -2) return node;
            return node >= 0 && static_cast<std::size_t>(node) < count ? remap[static_cast<std::size_t>(node)] : -1;
        };
        for (Animation& animation : scene.animations) {
            for (Animation::Channel& channel : animation.channels) channel.node = renumber(channel.node);
            std::erase_if(animation.channels, [](const Animation::Channel& c) { return c.node == -1; });
        }
        for (Scene::OtherScene& other : scene.otherScenes) {
            for (int& root : other.roots) root = renumber(root);
            std::erase(other.roots, -1);
        }
        for (Skin& skin : scene.skins) {
            for (int& joint : skin.joints) joint = renumber(joint);
            skin.skeleton = renumber(skin.skeleton);
        }
        ++scene.lightRevision;
        rebuildRoots(scene);
    });
    doc.select(-1);
    return "";
}

glm::vec3 duplicateOffset(const Document& doc, glm::vec3 offsetDirection) {
    if (glm::length(offsetDirection) < 1e-6f) return glm::vec3(0.0f);
    const glm::vec3 direction = glm::normalize(offsetDirection);
    Aabb bounds;
    for (const int node : topLevelSelection(doc)) {
        const Aabb b = nodeWorldBounds(doc.scene, node);
        bounds.extend(b.min);
        bounds.extend(b.max);
    }
    if (bounds.empty()) return glm::vec3(0.0f);
    // The box's extent along the direction: each side's share.
    const glm::vec3 size = bounds.size();
    const float width = std::max(glm::dot(glm::abs(size), glm::abs(direction)), 0.2f);
    return direction * width * (1.0f + kDuplicateGap);
}

std::string duplicateSelection(Document& doc, glm::vec3 offsetDirection) {
    const std::vector<int> top = topLevelSelection(doc);
    if (top.empty()) return "nothing is selected";
    const glm::vec3 offset = duplicateOffset(doc, offsetDirection);
    std::vector<int> copies;
    doc.edit("Duplicate " + selectionLabel(doc, top), Change::Transform, [&](Scene& scene) {
        // Copies node `source` and its subtree under `parent`; returns the copy's index.
        std::function<int(int, int)> copyTree = [&](int source, int parent) -> int {
            Node node = scene.nodes[static_cast<std::size_t>(source)];
            node.name = uniqueNodeName(scene, node.name.empty() ? "node" : node.name);
            node.parent = parent;
            node.children.clear();
            node.fileIndex = -1;  // a new node: saved after the file's (scene/Scene.h)
            if (node.light >= 0 && node.light < static_cast<int>(scene.lights.size())) {
                Light light = scene.lights[static_cast<std::size_t>(node.light)];
                scene.lights.push_back(light);
                node.light = static_cast<int>(scene.lights.size() - 1);
                ++scene.lightRevision;
            }
            if (node.camera >= 0 && node.camera < static_cast<int>(scene.cameras.size())) {
                Camera camera = scene.cameras[static_cast<std::size_t>(node.camera)];
                scene.cameras.push_back(camera);
                node.camera = static_cast<int>(scene.cameras.size() - 1);
            }
            const std::vector<int> children = scene.nodes[static_cast<std::size_t>(source)].children;
            scene.nodes.push_back(std::move(node));
            const int index = static_cast<int>(scene.nodes.size() - 1);
            if (parent >= 0) scene.nodes[static_cast<std::size_t>(parent)].children.push_back(index);
            for (const int child : children) copyTree(child, index);
            return index;
        };
        for (const int source : top) copies.push_back(copyTree(source, scene.nodes[static_cast<std::size_t>(source)].parent));
        // The offset is in world space; each copy's translation is in its parent's.
        for (const int copy : copies) {
            Node& node = scene.nodes[static_cast<std::size_t>(copy)];
            const glm::mat4 parent = node.parent >= 0 ? scene.nodes[static_cast<std::size_t>(node.parent)].world : glm::mat4(1.0f);
            node.translation += glm::vec3(glm::inverse(parent) * glm::vec4(offset, 0.0f));
        }
        rebuildRoots(scene);
    });
    doc.select(-1);
    for (auto it = copies.rbegin(); it != copies.rend(); ++it) doc.select(*it, /*additive=*/true);
    return "";
}

namespace {
// Moves `node` under `newParent` keeping its world matrix (checks done by the caller).
void reparentInScene(Scene& s, int node, int newParent) {
    const glm::mat4 world = s.nodes[static_cast<std::size_t>(node)].world;
    Node& n = s.nodes[static_cast<std::size_t>(node)];
    if (n.parent >= 0) std::erase(s.nodes[static_cast<std::size_t>(n.parent)].children, node);
    n.parent = newParent;
    if (newParent >= 0) s.nodes[static_cast<std::size_t>(newParent)].children.push_back(node);
    rebuildRoots(s);  // the new parent's world matrix is current (its own parents are unchanged)
    setWorldMatrix(s, node, world);
    s.updateWorldTransforms();
}
}  // namespace

std::string reparentSelection(Document& doc, int newParent) {
    Scene& scene = doc.scene;
    const std::vector<int> top = topLevelSelection(doc);
    if (top.empty()) return "nothing is selected";
    if (newParent >= 0 && !validNode(scene, newParent)) return "no such parent node";
    for (const int node : top)
        if (newParent >= 0 && isAncestorOrSelf(scene, node, newParent))
            return "cannot make " + nodeLabel(scene, node) + " a child of itself or of its own child";
    const std::string label = "Parent " + selectionLabel(doc, top) +
                              (newParent >= 0 ? " to " + nodeLabel(scene, newParent) : " to the scene root");
    doc.edit(label, Change::Transform, [&](Scene& s) {
        for (const int node : top)
            if (s.nodes[static_cast<std::size_t>(node)].parent != newParent) reparentInScene(s, node, newParent);
    });
    return "";
}

std::string reparent(Document& doc, int node, int newParent) {
    if (!validNode(doc.scene, node)) return "no such node";
    doc.select(node);
    return reparentSelection(doc, newParent);
}

int materialUserCount(const Scene& scene, int material) {
    if (material < 0) return 0;
    int users = 0;
    for (const Node& node : scene.nodes) {
        if (node.mesh < 0 || node.mesh >= static_cast<int>(scene.meshes.size())) continue;
        const std::vector<Primitive>& primitives = scene.meshes[static_cast<std::size_t>(node.mesh)].primitives;
        if (std::any_of(primitives.begin(), primitives.end(), [material](const Primitive& p) { return p.material == material; }))
            ++users;
    }
    return users;
}

int nodePrimitiveMaterial(const Scene& scene, int node, int primitive) {
    if (!validNode(scene, node)) return -1;
    const int mesh = scene.nodes[static_cast<std::size_t>(node)].mesh;
    if (mesh < 0 || mesh >= static_cast<int>(scene.meshes.size())) return -1;
    const std::vector<Primitive>& primitives = scene.meshes[static_cast<std::size_t>(mesh)].primitives;
    if (primitive < 0 || primitive >= static_cast<int>(primitives.size())) return -1;
    const int material = primitives[static_cast<std::size_t>(primitive)].material;
    return material < static_cast<int>(scene.materials.size()) ? material : -1;
}

std::string makeMaterialUnique(Document& doc, int node, int primitive) {
    const int material = nodePrimitiveMaterial(doc.scene, node, primitive);
    if (material < 0) return "the primitive uses the default material, which cannot be edited";
    const int mesh = doc.scene.nodes[static_cast<std::size_t>(node)].mesh;
    // Users of this material other than through this primitive: other nodes, or other
    // primitives of this mesh.
    int meshUsers = 0;
    for (const Node& n : doc.scene.nodes) meshUsers += n.mesh == mesh ? 1 : 0;
    const std::vector<Primitive>& primitives = doc.scene.meshes[static_cast<std::size_t>(mesh)].primitives;
    const int inMesh = static_cast<int>(std::count_if(primitives.begin(), primitives.end(),
                                                      [material](const Primitive& p) { return p.material == material; }));
    if (materialUserCount(doc.scene, material) <= 1 && meshUsers <= 1 && inMesh <= 1)
        return "material '" + doc.scene.materials[static_cast<std::size_t>(material)].name + "' is used only here";
    doc.edit("Make Material Unique", Change::Material, [&](Scene& scene) {
        int ownMesh = mesh;
        if (meshUsers > 1) {
            // The mesh is instanced by other nodes too: this node gets its own copy.
            Mesh copy = scene.meshes[static_cast<std::size_t>(mesh)];
            copy.name = copy.name.empty() ? std::string() : copy.name + " (copy)";
            ownMesh = doc.addMesh(std::move(copy));
            scene.nodes[static_cast<std::size_t>(node)].mesh = ownMesh;
        }
        Material copy = scene.materials[static_cast<std::size_t>(material)];
        copy.name = uniqueMaterialName(scene, copy.name.empty() ? "material" : copy.name);
        scene.materials.push_back(std::move(copy));
        scene.meshes[static_cast<std::size_t>(ownMesh)].primitives[static_cast<std::size_t>(primitive)].material =
            static_cast<int>(scene.materials.size() - 1);
        ++scene.geometryRevision;
    });
    return "";
}

}  // namespace lit::editor
