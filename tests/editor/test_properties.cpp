#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "EditorFixtures.h"
#include "Properties.h"

namespace {

using namespace lit;
using namespace lit::editor;
using lit::editor::testing::fixtureDocument;

constexpr float kRad = 0.017453292519943295f;

Document selected(const std::string& node) {
    Document doc = fixtureDocument();
    doc.selectedNode = findNode(doc.scene, node);
    EXPECT_GE(doc.selectedNode, 0) << node;
    return doc;
}

struct Case {
    const char* node;
    const char* name;
    const char* value;
    std::function<bool(const Scene&)> check;
};

TEST(Properties, FindNodeByExactName) {
    const Document doc = fixtureDocument();
    EXPECT_EQ(findNode(doc.scene, "Box"), 0);
    EXPECT_EQ(findNode(doc.scene, "Lamp"), 2);
    EXPECT_EQ(findNode(doc.scene, "box"), -1);
    EXPECT_EQ(findNode(doc.scene, ""), -1);
}

TEST(Properties, EveryNameSetsItsField) {
    const std::vector<Case> cases{
        {"Box", "node.translation", "1 2.5 -3",
         [](const Scene& s) { return s.nodes[0].translation == glm::vec3(1, 2.5f, -3); }},
        {"Box", "node.scale", "2 3 4", [](const Scene& s) { return s.nodes[0].scale == glm::vec3(2, 3, 4); }},
        {"Box", "node.name", "  Big Box ", [](const Scene& s) { return s.nodes[0].name == "Big Box"; }},
        {"Box", "material.albedo", "0.1 0.2 0.3",
         [](const Scene& s) { return s.materials[0].baseColorFactor == glm::vec4(0.1f, 0.2f, 0.3f, 1.0f); }},
        {"Box", "material.albedo", "0.1 0.2 0.3 0.5",
         [](const Scene& s) { return s.materials[0].baseColorFactor == glm::vec4(0.1f, 0.2f, 0.3f, 0.5f); }},
        {"Box", "material.roughness", "0.25", [](const Scene& s) { return s.materials[0].roughness == 0.25f; }},
        {"Box", "material.metalness", "1", [](const Scene& s) { return s.materials[0].metallic == 1.0f; }},
        {"Box", "material.emissive", "1 0.5 0",
         [](const Scene& s) { return s.materials[0].emissiveFactor == glm::vec3(1, 0.5f, 0); }},
        {"Box", "material.emissiveStrength", "20",
         [](const Scene& s) { return s.materials[0].emissiveStrength == 20.0f; }},
        {"Box", "material.ior", "1.33", [](const Scene& s) { return s.materials[0].ior == 1.33f; }},
        {"Box", "material.specular", "0.5", [](const Scene& s) { return s.materials[0].specularFactor == 0.5f; }},
        {"Box", "material.specularTint", "2 1 0.5",
         [](const Scene& s) { return s.materials[0].specularColorFactor == glm::vec3(2, 1, 0.5f); }},
        {"Box", "material.sheen", "0.5 0.25 1",
         [](const Scene& s) { return s.materials[0].sheenColorFactor == glm::vec3(0.5f, 0.25f, 1); }},
        {"Box", "material.sheenRoughness", "0.4", [](const Scene& s) { return s.materials[0].sheenRoughness == 0.4f; }},
        {"Box", "material.clearcoat", "0.75", [](const Scene& s) { return s.materials[0].clearcoatFactor == 0.75f; }},
        {"Box", "material.clearcoatRoughness", "0.2",
         [](const Scene& s) { return s.materials[0].clearcoatRoughness == 0.2f; }},
        {"Box", "material.transmission", "0.9", [](const Scene& s) { return s.materials[0].transmission == 0.9f; }},
        {"Box", "material.thickness", "0.05", [](const Scene& s) { return s.materials[0].thickness == 0.05f; }},
        {"Box", "material.attenuationDistance", "0.2",
         [](const Scene& s) { return s.materials[0].attenuationDistance == 0.2f; }},
        {"Box", "material.attenuationColor", "0.8 0.5 0.25",
         [](const Scene& s) { return s.materials[0].attenuationColor == glm::vec3(0.8f, 0.5f, 0.25f); }},
        {"Lamp", "light.type", "point", [](const Scene& s) { return s.lights[0].type == LightType::Point; }},
        {"Lamp", "light.type", "directional",
         [](const Scene& s) { return s.lights[0].type == LightType::Directional; }},
        {"Lamp", "light.color", "1 0.8 0.6",
         [](const Scene& s) { return s.lights[0].color == glm::vec3(1, 0.8f, 0.6f); }},
        {"Lamp", "light.intensity", "250", [](const Scene& s) { return s.lights[0].intensity == 250.0f; }},
        {"Lamp", "light.range", "12.5", [](const Scene& s) { return s.lights[0].range == 12.5f; }},
        {"Lamp", "light.inner", "10",
         [](const Scene& s) { return std::abs(s.lights[0].innerConeAngle - 10 * kRad) < 1e-6f; }},
        {"Lamp", "light.outer", "60",
         [](const Scene& s) { return std::abs(s.lights[0].outerConeAngle - 60 * kRad) < 1e-6f; }},
        {"Lamp", "light.shadow", "off", [](const Scene& s) { return !s.lights[0].castsShadow; }},
        {"Cam", "camera.fov", "45", [](const Scene& s) { return std::abs(s.cameras[0].yfov - 45 * kRad) < 1e-6f; }},
        {"Cam", "camera.near", "0.5", [](const Scene& s) { return s.cameras[0].znear == 0.5f; }},
        {"Cam", "camera.far", "0", [](const Scene& s) { return s.cameras[0].zfar == 0.0f; }},
        {"Cam", "camera.far", "200", [](const Scene& s) { return s.cameras[0].zfar == 200.0f; }},
    };
    std::set<std::string> covered;
    for (const Case& c : cases) {
        Document doc = selected(c.node);
        EXPECT_FALSE(c.check(doc.scene)) << c.name << " already holds " << c.value;
        EXPECT_EQ(setProperty(doc, c.name, c.value), "") << c.name;
        EXPECT_TRUE(c.check(doc.scene)) << c.name << " " << c.value;
        EXPECT_EQ(doc.undoLabel(), c.name);
        EXPECT_TRUE(doc.dirty());
        ASSERT_TRUE(doc.undo());
        EXPECT_FALSE(c.check(doc.scene)) << c.name << " not undone";
        EXPECT_FALSE(doc.canUndo()) << c.name << ": more than one step";
        covered.insert(c.name);
    }
    covered.insert("node.rotation");           // below
    covered.insert("material.albedoTexture");  // below
    for (const std::string& name : propertyNames()) EXPECT_TRUE(covered.count(name)) << name << " untested";
}

TEST(Properties, EditsBumpTheRightRevision) {
    Document doc = selected("Box");
    const Scene before = doc.scene;
    ASSERT_EQ(setProperty(doc, "node.translation", "0 1 0"), "");
    EXPECT_GT(doc.scene.geometryRevision, before.geometryRevision);
    EXPECT_EQ(glm::vec3(doc.scene.nodes[0].world[3]), glm::vec3(0, 1, 0));
    ASSERT_EQ(setProperty(doc, "material.roughness", "0.3"), "");
    EXPECT_GT(doc.scene.materialRevision, before.materialRevision);
    doc.selectedNode = findNode(doc.scene, "Lamp");
    ASSERT_EQ(setProperty(doc, "light.intensity", "3"), "");
    EXPECT_GT(doc.scene.lightRevision, before.lightRevision);
}

TEST(Properties, RotationIsXyzEulerDegrees) {
    Document doc = selected("Box");
    ASSERT_EQ(setProperty(doc, "node.rotation", "90 0 0"), "");
    const glm::vec3 up = doc.scene.nodes[0].rotation * glm::vec3(0, 1, 0);
    EXPECT_NEAR(glm::length(up - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);  // +90° about X takes +Y to +Z

    // X first, then Y, then Z: R = Rz · Ry · Rx.
    ASSERT_EQ(setProperty(doc, "node.rotation", "30 40 50"), "");
    const glm::quat expected = glm::angleAxis(50 * kRad, glm::vec3(0, 0, 1)) *
                               glm::angleAxis(40 * kRad, glm::vec3(0, 1, 0)) *
                               glm::angleAxis(30 * kRad, glm::vec3(1, 0, 0));
    EXPECT_NEAR(std::abs(glm::dot(doc.scene.nodes[0].rotation, expected)), 1.0f, 1e-6f);
    // And the inspector's display (glm::eulerAngles) reads the same angles back.
    const glm::vec3 degrees = glm::eulerAngles(doc.scene.nodes[0].rotation) / kRad;
    EXPECT_NEAR(degrees.x, 30.0f, 1e-3f);
    EXPECT_NEAR(degrees.y, 40.0f, 1e-3f);
    EXPECT_NEAR(degrees.z, 50.0f, 1e-3f);
}

TEST(Properties, AlbedoTextureOffAndOnAgain) {
    Document doc = fixtureDocument();
    doc.scene.images.push_back(Image{"white", "", 1, 1, {255, 255, 255, 255}, true});
    doc.scene.textures.push_back(Texture{.image = 0});
    doc.scene.materials[0].baseColorTexture = 0;
    doc.markSaved();
    doc.selectedNode = findNode(doc.scene, "Box");
    ASSERT_EQ(setProperty(doc, "material.albedoTexture", "off"), "");
    EXPECT_EQ(doc.scene.materials[0].baseColorTexture, -1);
    ASSERT_EQ(setProperty(doc, "material.albedoTexture", "on"), "");
    EXPECT_EQ(doc.scene.materials[0].baseColorTexture, 0);
    EXPECT_FALSE(doc.dirty());

    // A material that never had one cannot turn it on.
    Document plain = selected("Box");
    EXPECT_EQ(setProperty(plain, "material.albedoTexture", "on"),
              "material.albedoTexture: material 'Red' has no albedo texture");
    EXPECT_FALSE(plain.canUndo());
}

struct ErrorCase {
    const char* node;  // nullptr: nothing selected
    const char* name;
    const char* value;
    const char* message;
};

TEST(Properties, BadInputSaysWhyAndChangesNothing) {
    const std::vector<ErrorCase> cases{
        {nullptr, "light.intensity", "3", "no node is selected"},
        {"Box", "light.colour", "1 1 1", "unknown property 'light.colour'"},
        {"Box", "light.intensity", "3", "node 'Box' holds no light"},
        {"Box", "camera.fov", "30", "node 'Box' holds no camera"},
        {"Empty", "material.roughness", "0.5", "node 'Empty' holds no mesh"},
        {"Plain", "material.roughness", "0.5",
         "node 'Plain' has no material of its own (its mesh uses the default material)"},
        {"Lamp", "light.intensity", "abc", "light.intensity: expected 1 number, got 'abc'"},
        {"Lamp", "light.intensity", "1.5x", "light.intensity: expected 1 number, got '1.5x'"},
        {"Lamp", "light.intensity", "", "light.intensity: expected 1 number, got ''"},
        {"Lamp", "light.intensity", "1 2", "light.intensity: expected 1 number, got '1 2'"},
        {"Lamp", "light.intensity", "nan", "light.intensity: expected 1 number, got 'nan'"},
        {"Lamp", "light.intensity", "inf", "light.intensity: expected 1 number, got 'inf'"},
        {"Lamp", "light.intensity", "-1", "light.intensity: must not be negative, got '-1'"},
        {"Lamp", "light.color", "1 1", "light.color: expected 3 numbers, got '1 1'"},
        {"Lamp", "light.type", "area", "light.type: expected directional, point or spot, got 'area'"},
        {"Lamp", "light.shadow", "yes", "light.shadow: expected on or off, got 'yes'"},
        {"Lamp", "light.outer", "95", "light.outer: must be more than light.inner (11.4592°) and at most 90, got '95'"},
        {"Lamp", "light.inner", "40", "light.inner: must be at least 0 and less than light.outer (34.3775°), got '40'"},
        {"Box", "material.albedo", "1 1", "material.albedo: expected 3 or 4 numbers, got '1 1'"},
        {"Box", "material.albedo", "1 1 2", "material.albedo: values must be in [0, 1], got '1 1 2'"},
        {"Box", "material.roughness", "1.5", "material.roughness: must be in [0, 1], got '1.5'"},
        {"Box", "material.ior", "0.5", "material.ior: must be at least 1 (or 0, a mirror), got '0.5'"},
        {"Box", "material.specularTint", "1 -1 1", "material.specularTint: values must not be negative, got '1 -1 1'"},
        {"Box", "material.clearcoat", "2", "material.clearcoat: must be in [0, 1], got '2'"},
        {"Box", "node.scale", "1 0 1", "node.scale: scale must not be 0, got '1 0 1'"},
        {"Box", "node.name", "   ", "node.name: expected a name, got ''"},
        {"Box", "node.translation", "1,2,3", "node.translation: expected 3 numbers, got '1,2,3'"},
        {"Cam", "camera.fov", "180", "camera.fov: must be between 0 and 180 (exclusive), got '180'"},
        {"Cam", "camera.near", "60", "camera.near: must be more than 0 and less than camera.far, got '60'"},
        {"Cam", "camera.far", "0.01", "camera.far: must be 0 (fitted) or more than camera.near, got '0.01'"},
    };
    for (const ErrorCase& c : cases) {
        Document doc = fixtureDocument();
        doc.selectedNode = c.node ? findNode(doc.scene, c.node) : -1;
        const Scene before = doc.scene;
        EXPECT_EQ(setProperty(doc, c.name, c.value), c.message);
        EXPECT_FALSE(doc.canUndo()) << c.name << " " << c.value;
        EXPECT_FALSE(doc.dirty()) << c.name << " " << c.value;
        EXPECT_FALSE(doc.editOpen());
        EXPECT_EQ(doc.scene.geometryRevision, before.geometryRevision);
        EXPECT_EQ(doc.scene.materialRevision, before.materialRevision);
        EXPECT_EQ(doc.scene.lightRevision, before.lightRevision);
    }
    Document doc = fixtureDocument();
    doc.selectedNode = 99;
    EXPECT_EQ(setProperty(doc, "node.scale", "1 1 1"), "the selected node 99 does not exist");
}

TEST(Properties, CheckWithoutAScene) {
    EXPECT_EQ(checkPropertyValue("light.intensity", "3"), "");
    EXPECT_EQ(checkPropertyValue("light.inner", "80"), "");  // depends on the light's outer angle
    EXPECT_EQ(checkPropertyValue("camera.near", "1000"), "");
    EXPECT_EQ(checkPropertyValue("material.albedoTexture", "on"), "");
    EXPECT_EQ(checkPropertyValue("node.name", "A B"), "");
    EXPECT_EQ(checkPropertyValue("light.intensity", "x"), "light.intensity: expected 1 number, got 'x'");
    EXPECT_EQ(checkPropertyValue("material.roughness", "2"), "material.roughness: must be in [0, 1], got '2'");
    EXPECT_EQ(checkPropertyValue("light.outer", "91"),
              "light.outer: must be more than light.inner (0°) and at most 90, got '91'");
    EXPECT_EQ(checkPropertyValue("node.colour", "1"), "unknown property 'node.colour'");
}

}  // namespace
