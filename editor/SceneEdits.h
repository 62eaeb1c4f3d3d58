#pragma once
// Structural edits of the document's scene: add a node (empty, light, camera, primitive),
// delete, duplicate, re-parent keeping the world transform, make a shared material unique, and
// the transform edits the gizmo applies to a multi-selection. Each public edit is one undo step
// (Document::edit) and leaves the scene consistent (parents, children, roots, world matrices).
// Window-free (lit_editor_core): the panels, the viewport and the --script runner all call these.
//
// Node indices: a delete removes nodes from Scene::nodes and renumbers the rest (glTF order is
// kept); lights and cameras held only by deleted nodes are removed too. Meshes are never
// removed (another node or an undo step may still use them); a mesh no node uses is still saved.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "Document.h"

namespace lit::editor {

enum class NodeKind { Empty, DirectionalLight, PointLight, SpotLight, Camera, Box, Plane, Sphere };

// The script / menu name of a kind ("empty", "directional", "point", "spot", "camera", "box",
// "plane", "sphere") and back.
const char* nodeKindName(NodeKind kind);
std::optional<NodeKind> parseNodeKind(std::string_view name);
const std::vector<NodeKind>& allNodeKinds();

// Generated primitive sizes, metres: a 1 m box, a 2 m plane, a sphere of radius 0.5 m.
inline constexpr float kPrimitiveBoxSide = 1.0f;
inline constexpr float kPrimitivePlaneSide = 2.0f;
inline constexpr float kPrimitiveSphereRadius = 0.5f;
// An added light shows a white diffuse surface `distance` metres away, facing it, as middle grey
// (0.18) after the exposure: Lambertian radiance ρ/π · E with ρ = 1, times 2^exposureEv, is 0.18.
// So I = 0.18 · π · d² / 2^EV in W/sr for a point or spot light (E = I / d²), and 0.18 · π / 2^EV
// in W/m² for a directional one (E = I; `distance` unused). Scene units (docs/UNITS.md: × 683 for
// cd and lux). At EV 0 and 1 m: 0.57 W/sr = 386 cd; a fixed 10 W/sr (6830 cd) there shows the
// wall 17.7 times as bright, 4.1 stops over middle grey, burnt out after tone mapping.
inline constexpr float kMiddleGrey = 0.18f;
float midGreyLightIntensity(LightType type, float distance, float exposureEv);
// Where addNode assumes the lit surface is when not told: the Add menu's own placement distance
// at room scale.
inline constexpr float kDefaultLightDistance = 2.0f;  // metres

// A UV sphere (rings × segments quads, poles as triangle fans) of `radius` centred on the origin.
Mesh makeSphereMesh(const std::string& name, float radius, int material, int rings = 16, int segments = 32);

// Adds a root node of `kind` at world `position` (lights and cameras looking down −Z rotated to
// point along `direction`, normalised; ignored for other kinds), named after the kind and made
// unique ("Box", "Box.001"). Primitives get a new mesh and their own new material. A light gets
// midGreyLightIntensity at `lightDistance` (metres) and the document's exposure. Selects the
// new node alone. One undo step "Add <Kind>". Returns the node index.
int addNode(Document& doc, NodeKind kind, glm::vec3 position, glm::vec3 direction = {0.0f, -1.0f, 0.0f},
            float lightDistance = kDefaultLightDistance);

// addNode in front of a camera at `eye` looking along `forward` (unit): two metres (or a tenth
// of the scene, 1 to 10 m) ahead; lights and cameras look the way the camera does (a sun also
// downwards), so a new spot light lights what is in view. A light's intensity is set for a
// surface as far from it as it is from the camera. The Add menu's and the script's "add".
int addNodeInFront(Document& doc, NodeKind kind, glm::vec3 eye, glm::vec3 forward);

// Deletes the selected nodes with their subtrees. One undo step. Returns "" or why nothing was
// deleted ("nothing is selected").
std::string deleteSelection(Document& doc);

// Copies each selected node (top-level ones: a selected child of a selected node comes with its
// parent) with its subtree, next to the original under the same parent. Meshes are shared
// (instances, like Godot); lights and cameras are copied so the copies can be edited alone.
// The copies become the selection. One undo step. Returns "" or the reason.
// `offsetDirection` (world, unit; zero: none) moves the copies aside so they do not hide in the
// original: by the selection's width along it plus kDuplicateGap of that (at least 20 cm, the
// size F gives a light). The editor passes the view's right vector: the copy appears beside the
// original on screen, as Ctrl+D in Blender followed by a move.
std::string duplicateSelection(Document& doc, glm::vec3 offsetDirection = glm::vec3(0.0f));
// The world offset duplicateSelection gives the copies of the top-level selected nodes.
glm::vec3 duplicateOffset(const Document& doc, glm::vec3 offsetDirection);
inline constexpr float kDuplicateGap = 0.1f;  // fraction of the selection's width between copy and original

// Makes `newParent` (-1: the scene root) the parent of `node`, keeping its world transform.
// Refused (returns the reason) when newParent is node itself or below it.
std::string reparent(Document& doc, int node, int newParent);
// reparent() for every top-level selected node, as one step.
std::string reparentSelection(Document& doc, int newParent);

// How many nodes draw material `material` (a node counts once however many of its primitives
// use it).
int materialUserCount(const Scene& scene, int material);
// The material of primitive `primitive` of node `node`'s mesh, or -1 (none, default material).
int nodePrimitiveMaterial(const Scene& scene, int node, int primitive);
// Gives primitive `primitive` of `node` its own copy of its material ("<name>.001") so that
// editing it changes no other node. When the node's mesh is shared with other nodes, the node
// first gets its own copy of the mesh. One undo step. Returns "" or the reason.
std::string makeMaterialUnique(Document& doc, int node, int primitive);

// World matrix → translation, rotation, scale (a negative determinant flips the X scale).
// Shear, which a rotated parent with non-uniform scale can cause, is dropped.
void decomposeTransform(const glm::mat4& matrix, glm::vec3& translation, glm::quat& rotation, glm::vec3& scale);

// The selected nodes without those whose ancestor is selected too (moving a parent moves its
// children already).
std::vector<int> topLevelSelection(const Document& doc);

// Sets node `index`'s local transform so its world matrix becomes `world` (parent kept). On a
// node an animation poses (Node::pose) only the channels the animation does not drive change: the
// animation overrides the channels it drives, whose rest values stay (a door that swings can be
// moved; its swing cannot be turned by hand while it plays).
void setWorldMatrix(Scene& scene, int index, const glm::mat4& world);

// Name not used by any node: `base`, else "base.001", "base.002", ... (Blender's scheme).
std::string uniqueNodeName(const Scene& scene, const std::string& base);

// Scene::roots rebuilt from the parents (in index order) and the world matrices updated.
void rebuildRoots(Scene& scene);

}  // namespace lit::editor
