#pragma once
// Named properties of the selection, set from text: the --script "set" command and tests use
// these, and the inspector edits the same fields. Window-free (lit_editor_core).
//
// Names (values are whitespace-separated numbers unless noted; angles in degrees):
//   node.translation X Y Z | node.rotation PITCH YAW ROLL (XYZ Euler, degrees) | node.scale X Y Z
//   node.name TEXT
//   material.albedo R G B [A] | material.albedoTexture on|off | material.roughness V
//   material.metalness V | material.emissive R G B | material.emissiveStrength V
//   material.ior V | material.specular V | material.specularTint R G B | material.sheen R G B
//   material.sheenRoughness V | material.clearcoat V | material.clearcoatRoughness V   (docs/MATERIALS.md)
//   light.type directional|point|spot | light.color R G B | light.intensity V | light.range V
//   light.inner DEG | light.outer DEG | light.shadow on|off
//   camera.fov DEG | camera.near V | camera.far V
// "material.*" applies to the material of the selected node's mesh primitive
// Document::selectedPrimitive (the first one by default); "light.*" / "camera.*" to the light / camera the selected node holds.
// "material.albedoTexture on" gives back the texture the material had before it was turned off
// in this session (Document::rememberedAlbedoTexture). Numbers must be finite and whole words
// ("1.5x" is an error); ranges follow glTF (roughness in [0, 1], 0 <= inner < outer <= 90°).

#include <string>
#include <string_view>
#include <vector>

#include "Document.h"

namespace lit::editor {

// Sets property `name` of doc.selectedNode to `value` as one undo step labelled with the name.
// Returns "" on success, else a message saying what is wrong ("no node is selected",
// "node 'Floor' holds no light", "light.intensity: expected 1 number, got 'abc'", "unknown
// property 'light.colour'") and changes nothing.
std::string setProperty(Document& doc, std::string_view name, std::string_view value);

// The checks that need no scene: a known name, the count and format of the numbers, on|off,
// the light type, and the ranges that do not depend on other values (roughness in [0, 1]).
// Returns "" or the message setProperty would give. Used by the script parser.
std::string checkPropertyValue(std::string_view name, std::string_view value);

// Every property name above, for help text and error messages.
const std::vector<std::string>& propertyNames();

// Index of the node called `name` (exact match), or -1.
int findNode(const Scene& scene, std::string_view name);

}  // namespace lit::editor
