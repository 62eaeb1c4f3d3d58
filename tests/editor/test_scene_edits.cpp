// Structural edits (SceneEdits.h): each one applied, undone, redone, saved, reopened and compared.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "DocumentIO.h"
#include "EditorFixtures.h"
#include "Log.h"
#include "Properties.h"
#include "SceneEdits.h"
#include "ViewportOverlay.h"

namespace {

using namespace lit;
using namespace lit::editor;
using lit::editor::testing::fixtureDocument;
namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::path(::testing::TempDir()) / ("lit_edits_" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

Document reopen(Document& doc, const std::string& name) {
    const fs::path file = freshFolder(name) / "scene.gltf";
    saveDocument(doc, file);
    Log log;
    log.setSink([](const LogMessage&) {});
    return openDocument(file, log);
}

int nodeCalled(const Scene& scene, const std::string& name) { return findNode(scene, name); }

void expectNear(const glm::mat4& a, const glm::mat4& b, float tolerance = 1e-4f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "column " << c << " row " << r;
}

// Parent/children/roots agree, and every world matrix is what the locals say.
void expectConsistent(const Scene& scene) {
    std::size_t roots = 0;
    for (int i = 0; i < static_cast<int>(scene.nodes.size()); ++i) {
        const Node& n = scene.nodes[static_cast<std::size_t>(i)];
        if (n.parent < 0) {
            ++roots;
            EXPECT_NE(std::find(scene.roots.begin(), scene.roots.end(), i), scene.roots.end());
        } else {
            const auto& siblings = scene.nodes[static_cast<std::size_t>(n.parent)].children;
            EXPECT_NE(std::find(siblings.begin(), siblings.end(), i), siblings.end()) << "node " << i;
        }
        for (const int c : n.children) EXPECT_EQ(scene.nodes[static_cast<std::size_t>(c)].parent, i);
        EXPECT_LT(n.light, static_cast<int>(scene.lights.size()));
        EXPECT_LT(n.camera, static_cast<int>(scene.cameras.size()));
        EXPECT_LT(n.mesh, static_cast<int>(scene.meshes.size()));
    }
    EXPECT_EQ(roots, scene.roots.size());
}

TEST(SceneEdits, AddEveryKindUndoRedoSaveReopen) {
    for (const NodeKind kind : allNodeKinds()) {
        SCOPED_TRACE(nodeKindName(kind));
        Document doc = fixtureDocument();
        const std::size_t nodes = doc.scene.nodes.size(), lights = doc.scene.lights.size();
        const std::size_t cameras = doc.scene.cameras.size(), meshes = doc.scene.meshes.size();
        const int added = addNode(doc, kind, {1.0f, 2.0f, 3.0f}, {0.0f, 0.0f, -1.0f});
        ASSERT_EQ(added, static_cast<int>(nodes));
        EXPECT_EQ(doc.selectedNode, added);
        const Node node = doc.scene.nodes[static_cast<std::size_t>(added)];
        EXPECT_EQ(glm::vec3(node.world[3]), glm::vec3(1.0f, 2.0f, 3.0f));
        const bool isLight = kind == NodeKind::DirectionalLight || kind == NodeKind::PointLight || kind == NodeKind::SpotLight;
        const bool isMesh = kind == NodeKind::Box || kind == NodeKind::Plane || kind == NodeKind::Sphere;
        EXPECT_EQ(node.light >= 0, isLight);
        EXPECT_EQ(node.camera >= 0, kind == NodeKind::Camera);
        EXPECT_EQ(node.mesh >= 0, isMesh);
        if (isMesh) {
            const Primitive& p = doc.scene.meshes[static_cast<std::size_t>(node.mesh)].primitives.front();
            ASSERT_GE(p.material, 0);
            EXPECT_EQ(materialUserCount(doc.scene, p.material), 1);
            EXPECT_FALSE(p.indices.empty());
            EXPECT_EQ(p.indices.size() % 3, 0u);
        }
        expectConsistent(doc.scene);
        const EditableState after = doc.capture();

        ASSERT_TRUE(doc.undo());
        EXPECT_EQ(doc.scene.nodes.size(), nodes);
        EXPECT_EQ(doc.scene.lights.size(), lights);
        EXPECT_EQ(doc.scene.cameras.size(), cameras);
        EXPECT_EQ(doc.scene.meshes.size(), meshes);
        expectConsistent(doc.scene);
        ASSERT_TRUE(doc.redo());
        EXPECT_TRUE(doc.capture() == after);
        EXPECT_EQ(doc.undoLabel().rfind("Add ", 0), 0u);

        const Document back = reopen(doc, std::string("add_") + nodeKindName(kind));
        const int again = nodeCalled(back.scene, node.name);
        ASSERT_GE(again, 0);
        const Node& b = back.scene.nodes[static_cast<std::size_t>(again)];
        expectNear(b.world, node.world);
        EXPECT_EQ(b.light >= 0, isLight);
        EXPECT_EQ(b.camera >= 0, kind == NodeKind::Camera);
        EXPECT_EQ(b.mesh >= 0, isMesh);
        if (isLight) {
            EXPECT_EQ(back.scene.lights[static_cast<std::size_t>(b.light)].type,
                      doc.scene.lights[static_cast<std::size_t>(node.light)].type);
        }
        if (isMesh) {
            EXPECT_EQ(back.scene.meshes[static_cast<std::size_t>(b.mesh)].primitives.front().indices.size(),
                      doc.scene.meshes[static_cast<std::size_t>(node.mesh)].primitives.front().indices.size());
        }
    }
}

TEST(SceneEdits, NamesAreMadeUnique) {
    Document doc = fixtureDocument();
    addNode(doc, NodeKind::Box, glm::vec3(0.0f));
    addNode(doc, NodeKind::Box, glm::vec3(0.0f));  // the fixture already has a "Box"
    EXPECT_GE(findNode(doc.scene, "Box.001"), 0);
    EXPECT_GE(findNode(doc.scene, "Box.002"), 0);
}

TEST(SceneEdits, DeleteRemovesSubtreeAndItsLightUndoRedoSave) {
    Document doc = fixtureDocument();
    const int lamp = findNode(doc.scene, "Lamp");
    const int box = findNode(doc.scene, "Box");
    ASSERT_EQ(reparent(doc, box, lamp), "");  // Box under Lamp
    const std::size_t nodes = doc.scene.nodes.size(), lights = doc.scene.lights.size();
    doc.select(lamp);
    ASSERT_EQ(deleteSelection(doc), "");
    EXPECT_EQ(doc.scene.nodes.size(), nodes - 2);
    EXPECT_EQ(doc.scene.lights.size(), lights - 1);
    EXPECT_LT(findNode(doc.scene, "Lamp"), 0);
    EXPECT_LT(findNode(doc.scene, "Box"), 0);
    EXPECT_EQ(doc.selectedNode, -1);
    expectConsistent(doc.scene);
    const EditableState after = doc.capture();
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes.size(), nodes);
    EXPECT_GE(findNode(doc.scene, "Lamp"), 0);
    expectConsistent(doc.scene);
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.capture() == after);
    const Document back = reopen(doc, "delete");
    // The only light is gone; opening adds no light node (the renderer lights a scene without
    // lights with its default sun and sky, DocumentIO: addDefaultCamera).
    EXPECT_EQ(back.scene.nodes.size(), nodes - 2);
    EXPECT_LT(findNode(back.scene, "Lamp"), 0);
    EXPECT_GE(findNode(back.scene, "Cam"), 0);
    EXPECT_EQ(deleteSelection(doc), "nothing is selected");
}

// What names nodes besides the hierarchy (a file's animations, skins) follows a delete's
// renumbering, and undo brings the old numbers back; the save writes them for the right nodes.
TEST(SceneEdits, DeleteRenumbersAnimationsAndSkinsUndoRestoresThem) {
    Document doc = fixtureDocument();
    const int lamp = findNode(doc.scene, "Lamp"), cam = findNode(doc.scene, "Cam"), empty = findNode(doc.scene, "Empty");
    ASSERT_LT(lamp, cam);  // so the delete renumbers the others
    Animation bob;
    bob.name = "bob";
    bob.samplers.push_back({{0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}, 3, "LINEAR"});
    bob.channels = {{0, empty, "translation"}, {0, lamp, "translation"}};
    doc.scene.animations.push_back(bob);
    Skin rig;
    rig.name = "rig";
    rig.joints = {cam, empty};
    rig.skeleton = cam;
    doc.scene.skins.push_back(rig);
    doc.select(lamp);
    ASSERT_EQ(deleteSelection(doc), "");
    const int camAfter = findNode(doc.scene, "Cam"), emptyAfter = findNode(doc.scene, "Empty");
    ASSERT_EQ(doc.scene.animations[0].channels.size(), 1u);  // the deleted lamp's channel is gone
    EXPECT_EQ(doc.scene.animations[0].channels[0].node, emptyAfter);
    EXPECT_EQ(doc.scene.skins[0].joints, (std::vector<int>{camAfter, emptyAfter}));
    EXPECT_EQ(doc.scene.skins[0].skeleton, camAfter);
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.scene.animations[0].channels == bob.channels);
    EXPECT_EQ(doc.scene.skins[0].joints, rig.joints);
    EXPECT_EQ(doc.scene.skins[0].skeleton, cam);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene.animations[0].channels.size(), 1u);
    EXPECT_EQ(doc.scene.skins[0].joints, (std::vector<int>{camAfter, emptyAfter}));
    const Document back = reopen(doc, "delete_renumbers");
    ASSERT_EQ(back.scene.skins.size(), 1u);
    ASSERT_EQ(back.scene.skins[0].joints.size(), 2u);
    EXPECT_EQ(back.scene.nodes[static_cast<std::size_t>(back.scene.skins[0].joints[0])].name, "Cam");
    EXPECT_EQ(back.scene.nodes[static_cast<std::size_t>(back.scene.skins[0].joints[1])].name, "Empty");
    bool bobKept = false;
    for (const Animation& a : back.scene.animations)
        if (a.name == "bob") {
            bobKept = true;
            ASSERT_EQ(a.channels.size(), 1u);
            EXPECT_EQ(back.scene.nodes[static_cast<std::size_t>(a.channels[0].node)].name, "Empty");
        }
    EXPECT_TRUE(bobKept);
}

TEST(SceneEdits, DuplicateCopiesSubtreeSharesMeshCopiesLight) {
    Document doc = fixtureDocument();
    const int lamp = findNode(doc.scene, "Lamp");
    const int empty = findNode(doc.scene, "Empty");
    ASSERT_EQ(reparent(doc, lamp, empty), "");
    doc.select(empty);
    doc.select(findNode(doc.scene, "Box"), /*additive=*/true);
    const std::size_t nodes = doc.scene.nodes.size(), lights = doc.scene.lights.size();
    ASSERT_EQ(duplicateSelection(doc), "");
    EXPECT_EQ(doc.scene.nodes.size(), nodes + 3);  // Empty + Lamp + Box
    EXPECT_EQ(doc.scene.lights.size(), lights + 1);
    EXPECT_EQ(doc.selection().size(), 2u);
    const int boxCopy = findNode(doc.scene, "Box.001");
    const int lampCopy = findNode(doc.scene, "Lamp.001");
    ASSERT_GE(boxCopy, 0);
    ASSERT_GE(lampCopy, 0);
    EXPECT_EQ(doc.scene.nodes[static_cast<std::size_t>(boxCopy)].mesh,
              doc.scene.nodes[static_cast<std::size_t>(findNode(doc.scene, "Box"))].mesh);
    EXPECT_NE(doc.scene.nodes[static_cast<std::size_t>(lampCopy)].light,
              doc.scene.nodes[static_cast<std::size_t>(lamp)].light);
    EXPECT_EQ(doc.scene.nodes[static_cast<std::size_t>(lampCopy)].parent, findNode(doc.scene, "Empty.001"));
    expectNear(doc.scene.nodes[static_cast<std::size_t>(lampCopy)].world, doc.scene.nodes[static_cast<std::size_t>(lamp)].world);
    expectConsistent(doc.scene);
    const EditableState after = doc.capture();
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes.size(), nodes);
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.capture() == after);
    const Document back = reopen(doc, "duplicate");
    EXPECT_EQ(back.scene.nodes.size(), nodes + 3);
    EXPECT_GE(findNode(back.scene, "Lamp.001"), 0);
}

TEST(SceneEdits, ReparentKeepsWorldTransformAndRefusesCycles) {
    Document doc = fixtureDocument();
    const int box = findNode(doc.scene, "Box");
    const int lamp = findNode(doc.scene, "Lamp");
    // A parent that is rotated, moved and uniformly scaled.
    doc.edit("setup", Change::Transform, [&](Scene& s) {
        s.nodes[static_cast<std::size_t>(lamp)].scale = glm::vec3(2.0f);
    });
    const glm::mat4 before = doc.scene.nodes[static_cast<std::size_t>(box)].world;
    ASSERT_EQ(reparent(doc, box, lamp), "");
    EXPECT_EQ(doc.scene.nodes[static_cast<std::size_t>(box)].parent, lamp);
    expectNear(doc.scene.nodes[static_cast<std::size_t>(box)].world, before);
    EXPECT_NE(reparent(doc, lamp, box), "");  // the box is below the lamp now
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes[static_cast<std::size_t>(box)].parent, -1);
    expectNear(doc.scene.nodes[static_cast<std::size_t>(box)].world, before);
    ASSERT_TRUE(doc.redo());
    const Document back = reopen(doc, "reparent");
    const int b = findNode(back.scene, "Box");
    EXPECT_EQ(back.scene.nodes[static_cast<std::size_t>(b)].parent, findNode(back.scene, "Lamp"));
    expectNear(back.scene.nodes[static_cast<std::size_t>(b)].world, before);
    // Back to the root.
    doc.select(box);
    ASSERT_EQ(reparentSelection(doc, -1), "");
    EXPECT_EQ(doc.scene.nodes[static_cast<std::size_t>(box)].parent, -1);
    expectNear(doc.scene.nodes[static_cast<std::size_t>(box)].world, before);
    expectConsistent(doc.scene);
}

TEST(SceneEdits, DuplicateSelectsTheCopyBesideTheOriginalAndUndoRemovesIt) {
    Document doc;
    const int box = addNode(doc, NodeKind::Box, {0.0f, 0.5f, 0.0f});
    const std::size_t nodes = doc.scene.nodes.size();
    // The view's right vector is +X: the 1 m box's copy goes 1 m + 10 % to the right.
    ASSERT_EQ(duplicateSelection(doc, {1.0f, 0.0f, 0.0f}), "");
    ASSERT_EQ(doc.scene.nodes.size(), nodes + 1);
    const int copy = findNode(doc.scene, "Box.001");
    ASSERT_GE(copy, 0);
    EXPECT_EQ(doc.selectedNode, copy);
    EXPECT_EQ(doc.selection(), std::vector<int>{copy});
    const glm::vec3 moved = nodeWorldPosition(doc.scene, copy) - nodeWorldPosition(doc.scene, box);
    EXPECT_NEAR(glm::length(moved - glm::vec3(1.0f + kDuplicateGap, 0.0f, 0.0f)), 0.0f, 1e-5f);
    // The copy clears the original.
    EXPECT_GT(nodeWorldBounds(doc.scene, copy).min.x, nodeWorldBounds(doc.scene, box).max.x);
    EXPECT_EQ(doc.undoLabel(), "Duplicate Box");
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes.size(), nodes);
    EXPECT_LT(findNode(doc.scene, "Box.001"), 0);

    // A light (no size: counted as 20 cm) under a scaled, turned parent moves by the world offset.
    const int lamp = addNode(doc, NodeKind::PointLight, {0.0f, 2.0f, 0.0f});
    ASSERT_EQ(setProperty(doc, "node.scale", "2 2 2"), "");  // the lamp is selected
    doc.select(box);
    ASSERT_EQ(setProperty(doc, "node.rotation", "0 90 0"), "");
    ASSERT_EQ(setProperty(doc, "node.scale", "3 1 1"), "");
    doc.select(lamp);
    ASSERT_EQ(reparentSelection(doc, box), "");
    const glm::vec3 before = nodeWorldPosition(doc.scene, lamp);
    ASSERT_EQ(duplicateSelection(doc, {0.0f, 0.0f, -1.0f}), "");
    const int lampCopy = doc.selectedNode;
    ASSERT_NE(lampCopy, lamp);
    const glm::vec3 shift = nodeWorldPosition(doc.scene, lampCopy) - before;
    EXPECT_NEAR(glm::length(shift - glm::vec3(0.0f, 0.0f, -0.2f * (1.0f + kDuplicateGap))), 0.0f, 1e-4f);
    // No direction: the copy stays on the original.
    ASSERT_EQ(duplicateSelection(doc), "");
    EXPECT_NEAR(glm::length(nodeWorldPosition(doc.scene, doc.selectedNode) - nodeWorldPosition(doc.scene, lampCopy)),
                0.0f, 1e-5f);
}

TEST(SceneEdits, ANewLightShowsAWhiteSurfaceAtItsDistanceAsMiddleGrey) {
    constexpr float kPi = 3.14159265f;
    // Radiance of a white Lambertian surface facing the light (docs/UNITS.md), after exposure.
    auto exposedRadiance = [&](const Light& light, float distance, float ev) {
        const float irradiance =
            light.type == LightType::Directional ? light.intensity : light.intensity / (distance * distance);
        return 1.0f / kPi * irradiance * std::exp2(ev);
    };
    // 1 m away at EV 0: 0.18 π W/sr = 386 cd, not the 6830 cd a fixed 10 W/sr gave.
    EXPECT_NEAR(midGreyLightIntensity(LightType::Point, 1.0f, 0.0f), 0.5655f, 1e-3f);
    EXPECT_NEAR(midGreyLightIntensity(LightType::Point, 1.0f, 0.0f) * 683.0f, 386.2f, 0.5f);
    EXPECT_NEAR(midGreyLightIntensity(LightType::Spot, 2.0f, 2.0f), 0.5655f, 1e-3f);  // ×4 for 2 m, ÷4 for +2 EV

    Document doc;
    doc.settings.output.exposureEv = 1.5f;
    const glm::vec3 eye(0.0f, 1.0f, 5.0f), forward(0.0f, 0.0f, -1.0f);
    for (const NodeKind kind : {NodeKind::PointLight, NodeKind::SpotLight, NodeKind::DirectionalLight}) {
        const int node = addNodeInFront(doc, kind, eye, forward);
        const Node& n = doc.scene.nodes[static_cast<std::size_t>(node)];
        const Light& light = doc.scene.lights[static_cast<std::size_t>(n.light)];
        // A surface as far beyond the light as the light is from the camera.
        const float distance = glm::length(nodeWorldPosition(doc.scene, node) - eye);
        EXPECT_NEAR(exposedRadiance(light, distance, doc.settings.output.exposureEv), kMiddleGrey, 1e-4f)
            << nodeKindName(kind);
    }
    // The script's "add point X Y Z": the distance from the camera to X Y Z.
    const int lamp = addNode(doc, NodeKind::PointLight, {0.0f, 1.0f, 1.0f}, forward, 4.0f);
    const Light& light = doc.scene.lights[static_cast<std::size_t>(doc.scene.nodes[static_cast<std::size_t>(lamp)].light)];
    EXPECT_NEAR(exposedRadiance(light, 4.0f, 1.5f), kMiddleGrey, 1e-4f);
}

TEST(SceneEdits, MakeUniqueSplitsASharedMaterial) {
    Document doc = fixtureDocument();
    const int box = findNode(doc.scene, "Box");
    const int red = nodePrimitiveMaterial(doc.scene, box, 0);
    ASSERT_GE(red, 0);
    EXPECT_EQ(materialUserCount(doc.scene, red), 1);
    EXPECT_NE(makeMaterialUnique(doc, box, 0), "");  // used only here: refused
    EXPECT_EQ(duplicateSelection(doc), "nothing is selected");
    doc.select(box);
    ASSERT_EQ(duplicateSelection(doc), "");
    const int copy = findNode(doc.scene, "Box.001");
    EXPECT_EQ(materialUserCount(doc.scene, red), 2);
    ASSERT_EQ(makeMaterialUnique(doc, copy, 0), "");
    const int own = nodePrimitiveMaterial(doc.scene, copy, 0);
    EXPECT_NE(own, red);
    EXPECT_EQ(materialUserCount(doc.scene, red), 1);
    EXPECT_EQ(materialUserCount(doc.scene, own), 1);
    EXPECT_EQ(nodePrimitiveMaterial(doc.scene, box, 0), red);  // the original keeps its material
    // Editing the copy's material leaves the original's alone.
    doc.select(copy);
    ASSERT_EQ(setProperty(doc, "material.roughness", "0.1"), "");
    EXPECT_FLOAT_EQ(doc.scene.materials[static_cast<std::size_t>(red)].roughness, 0.5f);
    const EditableState after = doc.capture();
    ASSERT_TRUE(doc.undo());  // roughness
    ASSERT_TRUE(doc.undo());  // make unique
    EXPECT_EQ(nodePrimitiveMaterial(doc.scene, copy, 0), red);
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.capture() == after);
    const Document back = reopen(doc, "unique");
    const int b = nodePrimitiveMaterial(back.scene, findNode(back.scene, "Box"), 0);
    const int c = nodePrimitiveMaterial(back.scene, findNode(back.scene, "Box.001"), 0);
    EXPECT_NE(b, c);
    EXPECT_FLOAT_EQ(back.scene.materials[static_cast<std::size_t>(c)].roughness, 0.1f);
    EXPECT_FLOAT_EQ(back.scene.materials[static_cast<std::size_t>(b)].roughness, 0.5f);
}

TEST(SceneEdits, PerPrimitiveMaterialSelection) {
    Document doc = fixtureDocument();
    const int box = findNode(doc.scene, "Box");
    // A second primitive with a material of its own.
    const int blue = addMaterial(doc.scene, {0.1f, 0.1f, 0.8f}, 0.3f, 0.0f, "Blue");
    Mesh& mesh = doc.scene.meshes[static_cast<std::size_t>(doc.scene.nodes[static_cast<std::size_t>(box)].mesh)];
    mesh.primitives.push_back(mesh.primitives.front());
    mesh.primitives.back().material = blue;
    doc.markSaved();
    doc.select(box);
    doc.selectedPrimitive = 1;
    ASSERT_EQ(setProperty(doc, "material.roughness", "0.9"), "");
    EXPECT_FLOAT_EQ(doc.scene.materials[static_cast<std::size_t>(blue)].roughness, 0.9f);
    EXPECT_FLOAT_EQ(doc.scene.materials[0].roughness, 0.5f);
    // Make the second primitive's material unique although the node is its only user: the
    // first primitive does not share it, so this is refused; sharing it makes it allowed.
    EXPECT_NE(makeMaterialUnique(doc, box, 1), "");
    // Undo, redo, save and reopen (every edit undoable and saved): the edit stays on
    // the second primitive's material, the first primitive's is untouched.
    const EditableState after = doc.capture();
    ASSERT_TRUE(doc.undo());
    EXPECT_FLOAT_EQ(doc.scene.materials[static_cast<std::size_t>(blue)].roughness, 0.3f);
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.capture() == after);
    const Document back = reopen(doc, "primitive");
    const int backBox = findNode(back.scene, "Box");
    const int first = nodePrimitiveMaterial(back.scene, backBox, 0);
    const int second = nodePrimitiveMaterial(back.scene, backBox, 1);
    ASSERT_GE(first, 0);
    ASSERT_GE(second, 0);
    EXPECT_NE(first, second);
    EXPECT_FLOAT_EQ(back.scene.materials[static_cast<std::size_t>(second)].roughness, 0.9f);
    EXPECT_FLOAT_EQ(back.scene.materials[static_cast<std::size_t>(first)].roughness, 0.5f);
    EXPECT_EQ(back.scene.materials[static_cast<std::size_t>(second)].name, "Blue");
}

TEST(SceneEdits, MultiSelectionToggles) {
    Document doc = fixtureDocument();
    doc.select(0);
    doc.select(1, true);
    doc.select(2, true);
    EXPECT_EQ(doc.selectedNode, 2);
    EXPECT_EQ(doc.selection(), (std::vector<int>{2, 0, 1}));
    doc.select(0, true);  // toggles 0 off
    EXPECT_EQ(doc.selection(), (std::vector<int>{2, 1}));
    doc.select(2, true);  // the active one off: the last other becomes active
    EXPECT_EQ(doc.selection(), (std::vector<int>{1}));
    doc.select(3);
    EXPECT_EQ(doc.selection(), (std::vector<int>{3}));
    doc.select(-1);
    EXPECT_TRUE(doc.selection().empty());
}

TEST(SceneEdits, DecomposeRoundTrips) {
    const glm::quat rotation = glm::normalize(glm::quat(0.9f, 0.1f, -0.3f, 0.2f));
    const glm::mat4 m = glm::translate(glm::mat4(1.0f), {1.0f, -2.0f, 3.0f}) * glm::mat4_cast(rotation) *
                        glm::scale(glm::mat4(1.0f), {2.0f, 0.5f, 3.0f});
    glm::vec3 t, s;
    glm::quat r;
    decomposeTransform(m, t, r, s);
    const glm::mat4 back = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    expectNear(back, m);
}

// The file's nodes outside the shown scene (Scene::keptNodes) are neither listed nor edited, but
// a delete that removes a light or camera before theirs renumbers their lights and cameras,
// another scene loses only the deleted root, references to them stay, undo brings all back, and
// a save writes them for the right objects. Fails when a delete or a save mixes them up.
TEST(SceneEdits, DeleteAndAddKeepTheNodesOutsideTheShownScene) {
    Scene scene = lit::editor::testing::fixtureScene();
    Light hiddenLight;
    hiddenLight.name = "hidden light";
    scene.lights.push_back(hiddenLight);
    Camera hiddenCamera;
    hiddenCamera.name = "hidden camera";
    scene.cameras.push_back(hiddenCamera);
    ASSERT_EQ(scene.lights.size(), 2u);  // the fixture's Lamp comes first
    ASSERT_EQ(scene.cameras.size(), 2u);  // and its Cam
    Node hiddenLamp;
    hiddenLamp.name = "hidden lamp";
    hiddenLamp.light = 1;
    hiddenLamp.children = {1};
    Node hiddenCam;
    hiddenCam.name = "hidden cam";
    hiddenCam.camera = 1;
    hiddenCam.parent = 0;
    scene.keptNodes = {hiddenLamp, hiddenCam};
    const int cam = findNode(scene, "Cam");
    scene.otherScenes.push_back({"backstage", {keptNodeRef(0), cam}, {}});
    scene.sceneIndex = 0;
    Animation blink;
    blink.name = "blink";
    blink.samplers.push_back({{0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}, 3, "LINEAR"});
    blink.channels = {{0, keptNodeRef(0), "translation"}};
    scene.animations.push_back(blink);
    Skin rig;
    rig.name = "rig";
    rig.joints = {keptNodeRef(1)};
    scene.skins.push_back(rig);
    Document doc(std::move(scene), lit::editor::testing::fixturePath(), "fixture.gltf");
    const auto expectKept = [](const Scene& s, const std::string& light, const std::string& camera) {
        ASSERT_EQ(s.keptNodes.size(), 2u);
        EXPECT_EQ(s.lights.at(static_cast<std::size_t>(s.keptNodes[0].light)).name, light);
        EXPECT_EQ(s.cameras.at(static_cast<std::size_t>(s.keptNodes[1].camera)).name, camera);
        ASSERT_EQ(s.animations.at(0).channels.size(), 1u);
        EXPECT_EQ(s.animations[0].channels[0].node, keptNodeRef(0));
        EXPECT_EQ(s.skins.at(0).joints, std::vector<int>{keptNodeRef(1)});
    };
    doc.select(findNode(doc.scene, "Lamp"));
    ASSERT_EQ(deleteSelection(doc), "");
    doc.select(findNode(doc.scene, "Cam"));
    ASSERT_EQ(deleteSelection(doc), "");
    ASSERT_EQ(doc.scene.lights.size(), 1u);
    ASSERT_EQ(doc.scene.cameras.size(), 1u);
    expectKept(doc.scene, "hidden light", "hidden camera");
    EXPECT_EQ(doc.scene.otherScenes.at(0).roots, std::vector<int>{keptNodeRef(0)});
    const int added = addNode(doc, NodeKind::PointLight, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_GE(added, 0);
    expectKept(doc.scene, "hidden light", "hidden camera");
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.lights.size(), 2u);
    expectKept(doc.scene, "hidden light", "hidden camera");
    EXPECT_EQ(doc.scene.otherScenes.at(0).roots, (std::vector<int>{keptNodeRef(0), cam}));
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    expectKept(doc.scene, "hidden light", "hidden camera");

    const Document back = reopen(doc, "kept_nodes");
    EXPECT_EQ(findNode(back.scene, "hidden lamp"), -1);  // not shown after the reopen either
    ASSERT_EQ(back.scene.keptNodes.size(), 2u);
    const Node& lamp = back.scene.keptNodes[0].name == "hidden lamp" ? back.scene.keptNodes[0] : back.scene.keptNodes[1];
    const Node& camNode = back.scene.keptNodes[0].name == "hidden cam" ? back.scene.keptNodes[0] : back.scene.keptNodes[1];
    ASSERT_EQ(lamp.name, "hidden lamp");
    ASSERT_EQ(camNode.name, "hidden cam");
    EXPECT_EQ(back.scene.lights.at(static_cast<std::size_t>(lamp.light)).name, "hidden light");
    EXPECT_EQ(back.scene.cameras.at(static_cast<std::size_t>(camNode.camera)).name, "hidden camera");
    ASSERT_EQ(lamp.children.size(), 1u);
    EXPECT_EQ(back.scene.keptNodes.at(static_cast<std::size_t>(lamp.children[0])).name, "hidden cam");
    ASSERT_EQ(back.scene.otherScenes.size(), 1u);
    ASSERT_EQ(back.scene.otherScenes[0].roots.size(), 1u);
    EXPECT_EQ(back.scene.keptNodes.at(static_cast<std::size_t>(keptNodeIndex(back.scene.otherScenes[0].roots[0]))).name,
              "hidden lamp");
    bool blinkKept = false;
    for (const Animation& a : back.scene.animations)
        if (a.name == "blink") {
            blinkKept = true;
            ASSERT_EQ(a.channels.size(), 1u);
            ASSERT_LE(a.channels[0].node, -2);
            EXPECT_EQ(back.scene.keptNodes.at(static_cast<std::size_t>(keptNodeIndex(a.channels[0].node))).name, "hidden lamp");
        }
    EXPECT_TRUE(blinkKept);
    ASSERT_EQ(back.scene.skins.size(), 1u);
    ASSERT_EQ(back.scene.skins[0].joints.size(), 1u);
    ASSERT_LE(back.scene.skins[0].joints[0], -2);
    EXPECT_EQ(back.scene.keptNodes.at(static_cast<std::size_t>(keptNodeIndex(back.scene.skins[0].joints[0]))).name, "hidden cam");
    // The camera path animates a camera of the shown scene (a new one: the shown Cam is deleted),
    // not the kept one.
    EXPECT_GE(findNode(back.scene, "camera path"), 0);
}

// The animation overrides the channels it drives: a gizmo edit of a node whose rotation is
// animated moves it (translation is not driven) and leaves its rest rotation as it was, rather
// than baking the pose at the playhead into the saved rest transform.
TEST(SceneEdits, AGizmoEditOfAnAnimatedNodeChangesOnlyTheChannelsTheAnimationLeaves) {
    lit::Scene scene;
    scene.nodes.resize(1);
    scene.roots = {0};
    const glm::quat posed = glm::angleAxis(1.0f, glm::vec3(0.0f, 1.0f, 0.0f));
    scene.nodes[0].pose.rotation = posed;
    scene.updateWorldTransforms();
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f)) * glm::mat4_cast(posed);
    setWorldMatrix(scene, 0, world);
    EXPECT_NEAR(glm::distance(scene.nodes[0].translation, glm::vec3(1.0f, 2.0f, 3.0f)), 0.0f, 1e-5f);
    EXPECT_EQ(scene.nodes[0].rotation, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));  // the rest rotation stays
    scene.nodes[0].pose = {};
    setWorldMatrix(scene, 0, world);  // not animated: every channel takes the edit
    EXPECT_NEAR(std::abs(glm::dot(scene.nodes[0].rotation, posed)), 1.0f, 1e-5f);
}

}  // namespace
