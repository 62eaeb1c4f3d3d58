#include "panels/InspectorPanel.h"

#include "scene/LightUnits.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "SceneEdits.h"

namespace lit::editor {

namespace {

constexpr float kDegPerRad = 57.2957795f;

// The undo bracket around the widget just drawn. The widget edits a copy of the value, and
// `apply` writes it into the scene only after beginEdit has taken its snapshot: a slider jumps
// to the clicked value on the very frame it activates.
template <class Apply>
void track(Document& doc, const char* label, Change change, bool changed, Apply&& apply) {
    if (ImGui::IsItemActivated()) doc.beginEdit(label);
    if (changed) {
        // A colour picker popup changes the value without activating this item; the App ends such
        // an edit once no widget is active any more, so a pick in the popup is one step too.
        if (!doc.editOpen()) doc.beginEdit(label);
        apply();
        doc.touched(change);
    }
    if (ImGui::IsItemDeactivated()) doc.endEdit();
}

// Linear colours, edited as numbers in 0..1 with a swatch: glTF's base colour, emissive factor
// and light colour are all in that range (brightness is emissive strength / light intensity),
// and the --script "set" command accepts the same range.
constexpr ImGuiColorEditFlags kColourFlags = ImGuiColorEditFlags_Float;
// Smallest spot cone and the gap kept between inner and outer angles, in degrees: the falloff
// divides by their difference.
constexpr float kMinSpotDegrees = 0.5f;

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

const char* lightTypeName(LightType type) {
    switch (type) {
    case LightType::Directional: return "Directional";
    case LightType::Point: return "Point";
    case LightType::Spot: return "Spot";
    }
    return "?";
}

}  // namespace

void InspectorPanel::draw(Document& doc, const Placement& placement, bool* open) {
    placeNextWindow(placement);
    if (ImGui::Begin("Inspector", open)) {
        Scene& scene = doc.scene;
        const int selected = doc.selectedNode;
        if (selected < 0 || selected >= static_cast<int>(scene.nodes.size())) {
            ImGui::TextDisabled("Nothing selected.");
            ImGui::TextDisabled("Click a node in the Hierarchy.");
        } else {
            const Node& node = scene.nodes[static_cast<std::size_t>(selected)];
            ImGui::TextUnformatted(node.name.empty() ? "(unnamed node)" : node.name.c_str());
            ImGui::Separator();
            // Room for the longest label on the right, but at least half the width for the values.
            const float labelWidth = ImGui::CalcTextSize("Emissive strength").x + ImGui::GetStyle().ItemInnerSpacing.x;
            ImGui::PushItemWidth(-std::min(labelWidth, ImGui::GetContentRegionAvail().x * 0.5f));
            if (ImGui::CollapsingHeader("Transform", ImGuiTreeNodeFlags_DefaultOpen)) drawTransform(doc, selected);
            if (node.mesh >= 0 && node.mesh < static_cast<int>(scene.meshes.size())) {
                const Mesh& mesh = scene.meshes[static_cast<std::size_t>(node.mesh)];
                if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
                    // A multi-material mesh: choose the primitive whose material is edited.
                    const int primitives = static_cast<int>(mesh.primitives.size());
                    if (doc.selectedPrimitive >= primitives) doc.selectedPrimitive = 0;
                    if (primitives > 1) {
                        auto primitiveLabel = [&](int p) { return doc.primitiveLabel(selected, p); };
                        if (ImGui::BeginCombo("Primitive", primitiveLabel(doc.selectedPrimitive).c_str())) {
                            for (int p = 0; p < primitives; ++p)
                                if (ImGui::Selectable(primitiveLabel(p).c_str(), p == doc.selectedPrimitive))
                                {
                                    doc.selectedPrimitive = p;
                                    doc.primitivePicked = true;  // outlined alone, the selection kept
                                }
                            ImGui::EndCombo();
                        }
                        tooltip("This mesh has several parts with their own materials: the one edited below");
                    }
                    const int material = nodePrimitiveMaterial(scene, selected, doc.selectedPrimitive);
                    if (material < 0) {
                        ImGui::TextDisabled("The default material (not editable).");
                    } else {
                        // Blender's user count: an edit here changes every node listed.
                        // (drawMaterial shows the name below.)
                        const int users = materialUserCount(scene, material);
                        if (users > 1) {
                            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "(%d users)", users);
                            tooltip("Other nodes use this material too: an edit changes them all");
                            ImGui::SameLine();
                            if (ImGui::SmallButton("Make unique")) makeMaterialUnique(doc, selected, doc.selectedPrimitive);
                            tooltip("Give this node its own copy of the material (one undo step)");
                        } else {
                            ImGui::TextDisabled("(1 user)");
                        }
                        const int edited = nodePrimitiveMaterial(scene, selected, doc.selectedPrimitive);
                        if (edited >= 0) drawMaterial(doc, edited);
                    }
                }
            }
            if (node.light >= 0 && node.light < static_cast<int>(scene.lights.size()) &&
                ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen))
                drawLight(doc, node.light);
            if (node.camera >= 0 && node.camera < static_cast<int>(scene.cameras.size()) &&
                ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
                drawCamera(doc, node.camera);
            ImGui::PopItemWidth();
        }
    }
    ImGui::End();
}

void InspectorPanel::drawTransform(Document& doc, int nodeIndex) {
    Node& node = doc.scene.nodes[static_cast<std::size_t>(nodeIndex)];
    ImGui::PushID("transform");
    // The fields are the rest transform; say which of them an animation overrides in the viewport.
    if (!node.pose.empty()) {
        std::string driven;
        if (node.pose.translation) driven += "translation";
        if (node.pose.rotation) driven += std::string(driven.empty() ? "" : ", ") + "rotation";
        if (node.pose.scale) driven += std::string(driven.empty() ? "" : ", ") + "scale";
        ImGui::TextColored(ImVec4(0.55f, 0.8f, 0.55f, 1.0f), "Animated: %s", driven.c_str());
        tooltip("A node animation drives these channels at the timeline's playhead and overrides them in the "
                "viewport. The fields below are the rest transform, which edits change and a save writes");
    }

    glm::vec3 translation = node.translation;
    bool changed = ImGui::DragFloat3("Translation", &translation.x, 0.01f, 0.0f, 0.0f, "%.3f");
    tooltip("Metres, in the parent's space");
    track(doc, "Move", Change::Transform, changed, [&] { node.translation = translation; });

    if (euler_.node != nodeIndex || euler_.rotation != node.rotation) {
        glm::vec3 degrees = glm::eulerAngles(node.rotation) * kDegPerRad;
        // Rounding noise from the conversion would show as "-0.0".
        for (int axis = 0; axis < 3; ++axis)
            if (std::fabs(degrees[axis]) < 1e-3f) degrees[axis] = 0.0f;
        euler_ = {nodeIndex, node.rotation, degrees};
    }
    glm::vec3 degrees = euler_.degrees;
    changed = ImGui::DragFloat3("Rotation", &degrees.x, 0.5f, 0.0f, 0.0f, "%.1f");
    tooltip("Degrees: pitch (X), yaw (Y), roll (Z)");
    track(doc, "Rotate", Change::Transform, changed, [&] {
        node.rotation = glm::quat(degrees / kDegPerRad);
        euler_ = {nodeIndex, node.rotation, degrees};
    });

    glm::vec3 scale = node.scale;
    changed = ImGui::DragFloat3("Scale", &scale.x, 0.01f, 0.0f, 0.0f, "%.3f");
    track(doc, "Scale", Change::Transform, changed, [&] {
        // A zero scale collapses the node (and its normals): keep each axis a hair from zero,
        // on the side it had, so mirroring with a negative scale still works.
        for (int axis = 0; axis < 3; ++axis)
            if (std::abs(scale[axis]) < 1e-4f) scale[axis] = std::copysign(1e-4f, node.scale[axis]);
        node.scale = scale;
    });
    ImGui::PopID();
}

namespace {

// One line per texture of the material's extensions: which factor it multiplies, by which channel.
void drawExtensionTextures(const Material& material) {
    static constexpr std::array<std::array<const char*, 2>, kExtensionTextureSlots.size()> kWhat = {{
        {"Transmission texture", "red channel"},
        {"Clear coat texture", "red channel"},
        {"Coat roughness texture", "green channel"},
        {"Specular texture", "alpha channel"},
        {"Specular tint texture", "rgb"},
        {"Sheen colour texture", "rgb"},
        {"Sheen roughness texture", "alpha channel"},
        {"Coat normal texture", "normal map"},
        {"Thickness texture", "green channel"},
    }};
    static_assert(kWhat.back()[0] != nullptr, "a line for every kExtensionTextureSlots entry");
    for (std::size_t k = 0; k < kExtensionTextureSlots.size(); ++k) {
        const ExtensionTexture& t = material.*kExtensionTextureSlots[k].member;
        if (t.texture < 0) continue;
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s %d, %s%s%s", kWhat[k][0], t.texture, kWhat[k][1],
                            drawnTexCoord(t) == 1 ? ", TEXCOORD_1" : "", t.transform.present ? ", transformed" : "");
        ImGui::PopTextWrapPos();
        const bool normalMap = kExtensionTextureSlots[k].member == &Material::clearcoatNormalTexture;
        const std::string tip = std::string(normalMap ? "Bends the coat's normal, scale " + std::to_string(t.scale)
                                                      : "Multiplies its factor") +
                                " (" + kExtensionTextureSlots[k].extension + "; from the file, saved back as it is)";
        tooltip(tip.c_str());
    }
}

// Read-only: each texture reference's UV set where it reads TEXCOORD_1, and its
// KHR_texture_transform where it has one.
void drawTextureTransforms(const Material& material) {
    static constexpr std::array<const char*, 5> kSlots = {"Albedo", "Metal-rough", "Normal", "Emissive", "Occlusion"};
    const std::array<int, 5> textures = {material.baseColorTexture, material.metallicRoughnessTexture,
                                         material.normalTexture, material.emissiveTexture, material.occlusionTexture};
    for (std::size_t slot = 0; slot < kSlots.size(); ++slot) {
        const TextureTransform& t = material.textureTransforms[slot];
        const bool secondSet = drawnTexCoord(material, slot) == 1;
        if (textures[slot] < 0 || (!t.present && !secondSet)) continue;
        ImGui::PushTextWrapPos(0.0f);  // the inspector is narrow: wrap rather than cut the numbers off
        if (t.present)
            ImGui::TextDisabled("%s UV%s: scale %.3g x %.3g, offset %.3g, %.3g, rotation %.1f deg", kSlots[slot],
                                secondSet ? " (TEXCOORD_1)" : "", t.scale.x, t.scale.y, t.offset.x, t.offset.y,
                                t.rotation * kDegPerRad);
        else
            ImGui::TextDisabled("%s UV: TEXCOORD_1", kSlots[slot]);
        ImGui::PopTextWrapPos();
        tooltip(t.present ? "KHR_texture_transform and UV set from the file (saved back as they are)"
                          : "The UV set the file names for this texture (saved back as it is)");
    }
}

}  // namespace

void InspectorPanel::drawMaterial(Document& doc, int materialIndex) {
    Material& material = doc.scene.materials[static_cast<std::size_t>(materialIndex)];
    ImGui::PushID("material");
    ImGui::TextDisabled("%s", material.name.empty() ? "(unnamed material)" : material.name.c_str());

    glm::vec3 albedo = glm::vec3(material.baseColorFactor);
    bool changed = ImGui::ColorEdit3("Albedo", &albedo.x, kColourFlags);
    tooltip("Base colour factor, linear RGB (multiplies the texture)");
    track(doc, "Albedo", Change::Material, changed, [&] {
        material.baseColorFactor = glm::vec4(albedo, material.baseColorFactor.a);
    });

    // On/off for the base colour texture; off keeps the index in the Document so on restores it.
    const int remembered = doc.rememberedAlbedoTexture(materialIndex);
    bool textured = material.baseColorTexture >= 0;
    ImGui::BeginDisabled(remembered < 0 && !textured);
    if (ImGui::Checkbox("Albedo texture", &textured)) {
        doc.edit(textured ? "Albedo Texture On" : "Albedo Texture Off", Change::Material,
                 [&](Scene& scene) {
                     scene.materials[static_cast<std::size_t>(materialIndex)].baseColorTexture =
                         textured ? remembered : -1;
                 });
    }
    ImGui::EndDisabled();
    if (remembered < 0 && !textured) tooltip("This material has no base colour texture");
    drawTextureTransforms(material);

    float roughness = material.roughness;
    changed = ImGui::SliderFloat("Roughness", &roughness, 0.0f, 1.0f, "%.3f");
    tooltip("Perceptual roughness (GGX alpha = roughness^2)");
    track(doc, "Roughness", Change::Material, changed, [&] { material.roughness = roughness; });

    float metalness = material.metallic;
    changed = ImGui::SliderFloat("Metalness", &metalness, 0.0f, 1.0f, "%.3f");
    track(doc, "Metalness", Change::Material, changed, [&] { material.metallic = metalness; });

    glm::vec3 emissive = material.emissiveFactor;
    changed = ImGui::ColorEdit3("Emissive", &emissive.x, kColourFlags);
    tooltip("Emissive colour, linear RGB");
    track(doc, "Emissive", Change::Material, changed, [&] { material.emissiveFactor = emissive; });

    float strength = material.emissiveStrength;
    changed = ImGui::DragFloat("Emissive strength", &strength, 0.05f, 0.0f, 1000.0f, "%.2f");
    tooltip("Multiplier on the emissive colour (KHR_materials_emissive_strength)");
    track(doc, "Emissive Strength", Change::Material, changed, [&] { material.emissiveStrength = strength; });
    drawSpecularLayers(doc, material);
    ImGui::PopID();
}

// KHR_materials_ior, _specular, _sheen and _clearcoat (docs/MATERIALS.md): their factors.
void InspectorPanel::drawSpecularLayers(Document& doc, Material& material) {
    if (!ImGui::TreeNodeEx("Specular, sheen and clear coat", ImGuiTreeNodeFlags_DefaultOpen)) return;
    float ior = material.ior;
    bool changed = ImGui::DragFloat("IOR", &ior, 0.005f, 1.0f, 3.0f, "%.3f");
    tooltip("Index of refraction of the dielectric (KHR_materials_ior): F0 = ((IOR - 1)/(IOR + 1))^2, 0.04 at 1.5");
    track(doc, "IOR", Change::Material, changed, [&] { material.ior = std::max(ior, 1.0f); });

    float specular = material.specularFactor;
    changed = ImGui::SliderFloat("Specular", &specular, 0.0f, 1.0f, "%.3f");
    tooltip("Strength of the dielectric's specular reflection, F0 and F90 alike (KHR_materials_specular)");
    track(doc, "Specular", Change::Material, changed, [&] { material.specularFactor = specular; });

    glm::vec3 tint = material.specularColorFactor;
    changed = ImGui::ColorEdit3("Specular tint", &tint.x, kColourFlags | ImGuiColorEditFlags_HDR);
    tooltip("Colour of the dielectric's F0, linear RGB, may exceed 1 (KHR_materials_specular); F0 is capped at 1");
    track(doc, "Specular Tint", Change::Material, changed,
          [&] { material.specularColorFactor = glm::max(tint, glm::vec3(0.0f)); });

    glm::vec3 sheen = material.sheenColorFactor;
    changed = ImGui::ColorEdit3("Sheen", &sheen.x, kColourFlags);
    tooltip("Sheen colour, linear RGB; black = no sheen (KHR_materials_sheen: cloth, velvet)");
    track(doc, "Sheen", Change::Material, changed, [&] { material.sheenColorFactor = sheen; });

    float sheenRoughness = material.sheenRoughness;
    changed = ImGui::SliderFloat("Sheen roughness", &sheenRoughness, 0.0f, 1.0f, "%.3f");
    tooltip("Perceptual roughness of the sheen: low keeps it at grazing angles, high spreads it");
    track(doc, "Sheen Roughness", Change::Material, changed, [&] { material.sheenRoughness = sheenRoughness; });

    float coat = material.clearcoatFactor;
    changed = ImGui::SliderFloat("Clear coat", &coat, 0.0f, 1.0f, "%.3f");
    tooltip("Weight of a clear dielectric coat (IOR 1.5) over the material (KHR_materials_clearcoat)");
    track(doc, "Clear Coat", Change::Material, changed, [&] { material.clearcoatFactor = coat; });

    float coatRoughness = material.clearcoatRoughness;
    changed = ImGui::SliderFloat("Coat roughness", &coatRoughness, 0.0f, 1.0f, "%.3f");
    tooltip("Perceptual roughness of the clear coat");
    track(doc, "Clear Coat Roughness", Change::Material, changed,
          [&] { material.clearcoatRoughness = coatRoughness; });

    float transmission = material.transmission;
    changed = ImGui::SliderFloat("Transmission", &transmission, 0.0f, 1.0f, "%.3f");
    tooltip("Share of the dielectric's light that passes straight through, tinted by the base colour "
            "(KHR_materials_transmission; drawn as a thin sheet: glass panes, film)");
    track(doc, "Transmission", Change::Material, changed, [&] { material.transmission = transmission; });

    float thickness = material.thickness;
    changed = ImGui::DragFloat("Thickness", &thickness, 0.001f, 0.0f, 10.0f, "%.3f m");
    tooltip(
        "Thickness of the volume a transmissive mesh encloses, metres in the mesh's space; 0: a thin wall "
        "without a volume (KHR_materials_volume: a solid that bends the view by its IOR and absorbs what crosses it)");
    track(doc, "Thickness", Change::Material, changed, [&] { material.thickness = std::max(thickness, 0.0f); });

    float attenuationDistance = material.attenuationDistance;
    changed = ImGui::DragFloat("Attenuation distance", &attenuationDistance, 0.01f, 0.0f, 1000.0f,
                               attenuationDistance > 0.0f ? "%.3f m" : "infinite");
    tooltip(
        "Distance in the volume after which the attenuation colour is what is left of the light, metres; "
        "0: infinite, no absorption (KHR_materials_volume)");
    track(doc, "Attenuation Distance", Change::Material, changed,
          [&] { material.attenuationDistance = std::max(attenuationDistance, 0.0f); });

    glm::vec3 attenuationColor = material.attenuationColor;
    changed = ImGui::ColorEdit3("Attenuation colour", &attenuationColor.x, kColourFlags);
    tooltip("Colour the volume's medium leaves of white light after the attenuation distance, linear RGB");
    track(doc, "Attenuation Colour", Change::Material, changed,
          [&] { material.attenuationColor = glm::clamp(attenuationColor, glm::vec3(0.0f), glm::vec3(1.0f)); });
    drawExtensionTextures(material);
    ImGui::TreePop();
}

void InspectorPanel::drawLight(Document& doc, int lightIndex) {
    Light& light = doc.scene.lights[static_cast<std::size_t>(lightIndex)];
    ImGui::PushID("light");

    // A combo's choice is made in its popup, not on the combo item: one-shot edit.
    if (ImGui::BeginCombo("Type", lightTypeName(light.type))) {
        for (const LightType type : {LightType::Directional, LightType::Point, LightType::Spot}) {
            if (ImGui::Selectable(lightTypeName(type), type == light.type) && type != light.type)
                doc.edit("Light Type", Change::Light,
                         [&](Scene& scene) { scene.lights[static_cast<std::size_t>(lightIndex)].type = type; });
        }
        ImGui::EndCombo();
    }

    glm::vec3 colour = light.color;
    bool changed = ImGui::ColorEdit3("Colour", &colour.x, kColourFlags);
    tooltip("Linear RGB, multiplied by the intensity");
    track(doc, "Light Colour", Change::Light, changed, [&] { light.color = colour; });

    // The Scene's radiometric units (W/sr, W/m²); the file holds them × 683 lm/W as cd or lux.
    const bool directional = light.type == LightType::Directional;
    float intensity = light.intensity;
    changed = ImGui::DragFloat(directional ? "Intensity (W/m^2)" : "Intensity (W/sr)", &intensity, 0.01f, 0.0f, 1.0e5f,
                               "%.3f", ImGuiSliderFlags_Logarithmic);
    tooltip(directional ? "Irradiance in W/m^2; saved as illuminance in lux (x 683 lm/W, docs/UNITS.md)"
                        : "Radiant intensity in W/sr; saved as luminous intensity in candela (x 683 lm/W, docs/UNITS.md)");
    ImGui::TextDisabled(directional ? "= %.1f lux in the file" : "= %.1f cd in the file",
                        photometricFromRadiometric(intensity));
    track(doc, "Light Intensity", Change::Light, changed, [&] { light.intensity = intensity; });

    if (!directional) {
        float range = light.range;
        changed = ImGui::DragFloat("Range (m)", &range, 0.05f, 0.0f, 1.0e4f, range > 0.0f ? "%.2f" : "infinite");
        tooltip("Distance where the light fades out, metres; 0 = infinite");
        track(doc, "Light Range", Change::Light, changed, [&] { light.range = range; });
    }
    if (light.type == LightType::Spot) {
        float inner = light.innerConeAngle * kDegPerRad;
        changed = ImGui::SliderFloat("Inner angle", &inner, 0.0f,
                                     std::max(light.outerConeAngle * kDegPerRad - kMinSpotDegrees, 0.0f), "%.1f deg");
        tooltip("Full intensity inside this angle from the axis");
        track(doc, "Spot Inner Angle", Change::Light, changed, [&] { light.innerConeAngle = inner / kDegPerRad; });

        float outer = light.outerConeAngle * kDegPerRad;
        changed = ImGui::SliderFloat("Outer angle", &outer, kMinSpotDegrees, 90.0f, "%.1f deg",
                                     ImGuiSliderFlags_AlwaysClamp);
        tooltip("No light outside this angle from the axis");
        track(doc, "Spot Outer Angle", Change::Light, changed, [&] {
            light.outerConeAngle = outer / kDegPerRad;
            light.innerConeAngle =
                std::min(light.innerConeAngle, (outer - kMinSpotDegrees) / kDegPerRad);
            light.innerConeAngle = std::max(light.innerConeAngle, 0.0f);
        });
    }

    bool shadow = light.castsShadow;
    if (ImGui::Checkbox("Casts shadow", &shadow))
        doc.edit(shadow ? "Shadow On" : "Shadow Off", Change::Light,
                 [&](Scene& scene) { scene.lights[static_cast<std::size_t>(lightIndex)].castsShadow = shadow; });
    ImGui::PopID();
}

void InspectorPanel::drawCamera(Document& doc, int cameraIndex) {
    Camera& camera = doc.scene.cameras[static_cast<std::size_t>(cameraIndex)];
    ImGui::PushID("camera");

    float fov = camera.yfov * kDegPerRad;
    bool changed = ImGui::SliderFloat("Field of view", &fov, 5.0f, 150.0f, "%.1f deg");
    tooltip("Vertical field of view");
    track(doc, "Camera FOV", Change::Camera, changed, [&] { camera.yfov = fov / kDegPerRad; });

    float znear = camera.znear;
    changed = ImGui::DragFloat("Near (m)", &znear, 0.001f, 0.001f, 100.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    track(doc, "Camera Near", Change::Camera, changed, [&] { camera.znear = znear; });

    float zfar = camera.zfar;
    changed = ImGui::DragFloat("Far (m)", &zfar, 0.1f, 0.0f, 1.0e5f, zfar > 0.0f ? "%.2f" : "fitted");
    tooltip("Far plane, metres; 0 = fitted to the scene");
    track(doc, "Camera Far", Change::Camera, changed, [&] { camera.zfar = zfar; });
    ImGui::PopID();
}

}  // namespace lit::editor
