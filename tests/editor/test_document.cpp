#include <gtest/gtest.h>

#include "Document.h"
#include "EditorFixtures.h"

namespace {

using namespace lit;
using namespace lit::editor;
using lit::editor::testing::fixtureDocument;

constexpr int kBox = 0;
constexpr int kLampLight = 0;
constexpr int kCamera = 0;

TEST(Document, StartsCleanWithNothingToUndo) {
    Document doc = fixtureDocument();
    EXPECT_FALSE(doc.dirty());
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
    EXPECT_FALSE(doc.undo());
    EXPECT_FALSE(doc.redo());
    EXPECT_EQ(doc.undoLabel(), "");
    EXPECT_EQ(doc.redoLabel(), "");
}

TEST(Document, TransformEditUndoRedoRecomputesWorld) {
    Document doc = fixtureDocument();
    const std::uint64_t geometry = doc.scene.geometryRevision;
    doc.edit("Move", Change::Transform, [](Scene& s) { s.nodes[kBox].translation = {1.0f, 2.0f, 3.0f}; });
    EXPECT_GT(doc.scene.geometryRevision, geometry);
    EXPECT_EQ(glm::vec3(doc.scene.nodes[kBox].world[3]), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(doc.undoLabel(), "Move");

    const std::uint64_t afterEdit = doc.scene.geometryRevision;
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes[kBox].translation, glm::vec3(0.0f, 0.5f, 0.0f));
    EXPECT_EQ(glm::vec3(doc.scene.nodes[kBox].world[3]), glm::vec3(0.0f, 0.5f, 0.0f));
    EXPECT_GT(doc.scene.geometryRevision, afterEdit);
    EXPECT_EQ(doc.redoLabel(), "Move");
    EXPECT_FALSE(doc.canUndo());

    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene.nodes[kBox].translation, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(glm::vec3(doc.scene.nodes[kBox].world[3]), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FALSE(doc.canRedo());
}

TEST(Document, MaterialEditBumpsOnlyTheMaterialRevision) {
    Document doc = fixtureDocument();
    const Scene before = doc.scene;
    doc.edit("Roughness", Change::Material, [](Scene& s) { s.materials[0].roughness = 0.1f; });
    EXPECT_EQ(doc.scene.materialRevision, before.materialRevision + 1);
    EXPECT_EQ(doc.scene.geometryRevision, before.geometryRevision);
    EXPECT_EQ(doc.scene.lightRevision, before.lightRevision);

    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.materials[0].roughness, 0.5f);
    // restore() bumps what differs and nothing else.
    EXPECT_EQ(doc.scene.materialRevision, before.materialRevision + 2);
    EXPECT_EQ(doc.scene.geometryRevision, before.geometryRevision);
    EXPECT_EQ(doc.scene.lightRevision, before.lightRevision);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene.materials[0].roughness, 0.1f);
    EXPECT_EQ(doc.scene.materialRevision, before.materialRevision + 3);
}

TEST(Document, LightEditUndoRedo) {
    Document doc = fixtureDocument();
    const Scene before = doc.scene;
    doc.edit("Intensity", Change::Light, [](Scene& s) { s.lights[kLampLight].intensity = 99.0f; });
    EXPECT_EQ(doc.scene.lightRevision, before.lightRevision + 1);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.lights[kLampLight].intensity, 10.0f);
    EXPECT_EQ(doc.scene.lightRevision, before.lightRevision + 2);
    EXPECT_EQ(doc.scene.materialRevision, before.materialRevision);
    EXPECT_EQ(doc.scene.geometryRevision, before.geometryRevision);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene.lights[kLampLight].intensity, 99.0f);
}

TEST(Document, CameraEditUndoRedoBumpsNothing) {
    Document doc = fixtureDocument();
    const Scene before = doc.scene;
    doc.edit("Field of View", Change::Camera, [](Scene& s) { s.cameras[kCamera].yfov = 1.2f; });
    EXPECT_TRUE(doc.canUndo());
    EXPECT_EQ(doc.scene.geometryRevision, before.geometryRevision);
    EXPECT_EQ(doc.scene.materialRevision, before.materialRevision);
    EXPECT_EQ(doc.scene.lightRevision, before.lightRevision);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.cameras[kCamera].yfov, before.cameras[kCamera].yfov);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene.cameras[kCamera].yfov, 1.2f);
}

TEST(Document, CameraPathEditUndoRedo) {
    Document doc = fixtureDocument();
    const std::vector<CameraKey> keys = doc.cameraPath.keys();
    doc.edit("Path Options", Change::CameraPath, [&](Scene&) {
        CameraPathOptions options;
        options.loop = true;
        doc.cameraPath.setOptions(options);
    });
    doc.edit("Delete Key", Change::CameraPath, [&](Scene&) { doc.cameraPath.removeKey(1); });
    EXPECT_EQ(doc.cameraPath.keys().size(), 1u);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.cameraPath.keys(), keys);
    EXPECT_TRUE(doc.cameraPath.options().loop);
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.cameraPath.options().loop);
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.cameraPath.keys().size(), 1u);
    EXPECT_TRUE(doc.cameraPath.options().loop);
    // The restored path is evaluated, not just stored.
    ASSERT_TRUE(doc.cameraPath.evaluate(0.0).has_value());
}

TEST(Document, ADragOfManyChangesIsOneStep) {
    Document doc = fixtureDocument();
    doc.beginEdit("Drag");
    for (int i = 1; i <= 30; ++i) {
        doc.beginEdit("ignored while open");
        doc.scene.nodes[kBox].translation.x = 0.1f * static_cast<float>(i);
        doc.touched(Change::Transform);
        doc.scene.materials[0].roughness = 0.01f * static_cast<float>(i);
        doc.touched(Change::Material);
    }
    EXPECT_TRUE(doc.editOpen());
    EXPECT_TRUE(doc.canUndo());  // the open edit would be undone
    EXPECT_EQ(doc.undoLabel(), "Drag");
    doc.endEdit();
    EXPECT_FALSE(doc.editOpen());
    EXPECT_EQ(doc.undoLabel(), "Drag");
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.nodes[kBox].translation.x, 0.0f);
    EXPECT_EQ(doc.scene.materials[0].roughness, 0.5f);
    EXPECT_FALSE(doc.canUndo());
}

TEST(Document, UndoEndsAnOpenEdit) {
    Document doc = fixtureDocument();
    doc.beginEdit("Drag");
    doc.scene.lights[kLampLight].intensity = 3.0f;
    doc.touched(Change::Light);
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.editOpen());
    EXPECT_EQ(doc.scene.lights[kLampLight].intensity, 10.0f);
    EXPECT_EQ(doc.redoLabel(), "Drag");
}

TEST(Document, AnEditThatChangesNothingPushesNoStep) {
    Document doc = fixtureDocument();
    doc.edit("Nothing", Change::Transform, [](Scene&) {});
    EXPECT_FALSE(doc.canUndo());
    // Changed and changed back within the edit: no step either.
    doc.beginEdit("There and back");
    doc.scene.nodes[kBox].scale = glm::vec3(2.0f);
    doc.touched(Change::Transform);
    doc.scene.nodes[kBox].scale = glm::vec3(1.0f);
    doc.touched(Change::Transform);
    doc.endEdit();
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
}

TEST(Document, ANewEditClearsRedo) {
    Document doc = fixtureDocument();
    doc.edit("A", Change::Light, [](Scene& s) { s.lights[0].intensity = 1.0f; });
    doc.edit("B", Change::Light, [](Scene& s) { s.lights[0].intensity = 2.0f; });
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.canRedo());
    // An edit that changes nothing keeps the redo list.
    doc.edit("Nothing", Change::Light, [](Scene&) {});
    EXPECT_TRUE(doc.canRedo());
    doc.edit("C", Change::Light, [](Scene& s) { s.lights[0].intensity = 3.0f; });
    EXPECT_FALSE(doc.canRedo());
    EXPECT_FALSE(doc.redo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene.lights[0].intensity, 1.0f);
}

TEST(Document, DirtyFollowsTheSavedState) {
    Document doc = fixtureDocument();
    doc.edit("A", Change::Material, [](Scene& s) { s.materials[0].metallic = 1.0f; });
    EXPECT_TRUE(doc.dirty());
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.dirty());
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.dirty());
    doc.markSaved();
    EXPECT_FALSE(doc.dirty());
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.dirty());  // the saved state is now the one after A
    ASSERT_TRUE(doc.redo());
    EXPECT_FALSE(doc.dirty());
    // Edited by hand back to the saved value: clean.
    doc.edit("B", Change::Material, [](Scene& s) { s.materials[0].metallic = 0.0f; });
    EXPECT_TRUE(doc.dirty());
    doc.edit("C", Change::Material, [](Scene& s) { s.materials[0].metallic = 1.0f; });
    EXPECT_FALSE(doc.dirty());
    // A camera path edit makes it dirty too.
    CameraPathOptions loop;
    loop.loop = true;
    doc.edit("Loop", Change::CameraPath, [&](Scene&) { doc.cameraPath.setOptions(loop); });
    EXPECT_TRUE(doc.dirty());
    doc.markUnsaved();
    doc.markSaved();
    EXPECT_FALSE(doc.dirty());
    doc.markUnsaved();
    EXPECT_TRUE(doc.dirty());
}

TEST(Document, DirtyIgnoresRecomputedWorldMatrices) {
    Document doc = fixtureDocument();
    doc.scene.nodes[kBox].world = glm::mat4(0.0f);  // stale
    EXPECT_FALSE(doc.dirty());
    doc.scene.updateWorldTransforms();
    EXPECT_FALSE(doc.dirty());
}

TEST(Document, UndoHistoryKeepsTheNewestSteps) {
    Document doc = fixtureDocument();
    const int total = static_cast<int>(Document::kMaxUndoSteps) + 10;
    for (int i = 1; i <= total; ++i)
        doc.edit("Step " + std::to_string(i), Change::Light,
                 [i](Scene& s) { s.lights[0].intensity = static_cast<float>(i); });
    std::size_t undone = 0;
    while (doc.undo()) ++undone;
    EXPECT_EQ(undone, Document::kMaxUndoSteps);
    // The oldest ten were dropped: undoing everything ends after step 10.
    EXPECT_EQ(doc.scene.lights[0].intensity, 10.0f);
    EXPECT_EQ(doc.redoLabel(), "Step 11");
}

TEST(Document, RestoreOfABadPathChangesNothing) {
    Document doc = fixtureDocument();
    EditableState state = doc.capture();
    state.nodes[kBox].translation = {5.0f, 5.0f, 5.0f};
    state.materials[0].roughness = 0.0f;
    state.pathKeys[1].time = -1.0f;  // not after key 0
    const EditableState before = doc.capture();
    const Scene scene = doc.scene;
    EXPECT_THROW(doc.restore(state), CameraPathError);
    EXPECT_TRUE(doc.capture() == before);
    EXPECT_EQ(doc.scene.geometryRevision, scene.geometryRevision);
    EXPECT_EQ(doc.scene.materialRevision, scene.materialRevision);
}

TEST(Document, AnEditWhoseApplyThrowsIsCancelled) {
    Document doc = fixtureDocument();
    EXPECT_THROW(doc.edit("Bad Key", Change::CameraPath,
                          [&](Scene& s) {
                              s.nodes[kBox].translation.x = 7.0f;
                              doc.cameraPath.insertKey(doc.cameraPath.keys()[0]);  // time taken: throws
                          }),
                 CameraPathError);
    EXPECT_FALSE(doc.editOpen());
    EXPECT_FALSE(doc.canUndo());
    EXPECT_EQ(doc.scene.nodes[kBox].translation.x, 0.0f);
    EXPECT_FALSE(doc.dirty());
}

TEST(Document, RestoreDropsASelectionThatNoLongerExists) {
    Document doc = fixtureDocument();
    doc.edit("Add Key", Change::CameraPath, [&](Scene&) {
        CameraKey key;
        key.time = 5.0f;
        doc.cameraPath.insertKey(key);
    });
    doc.selectedKey = 2;
    doc.selectedNode = 1;
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.selectedKey, -1);
    EXPECT_EQ(doc.selectedNode, 1);
}

}  // namespace

namespace {

using namespace lit;
using namespace lit::editor;

TEST(Document, RenderSettingsChangesAreUnsavedButNotTheOutputSize) {
    Document doc = lit::editor::testing::fixtureDocument();
    ASSERT_FALSE(doc.dirty());
    doc.settings.output.width = 333;  // follows the window: not a change of the document
    doc.settings.output.height = 222;
    EXPECT_FALSE(doc.dirty());
    doc.settings.gi.enabled = !doc.settings.gi.enabled;
    EXPECT_TRUE(doc.dirty());
    EXPECT_FALSE(doc.canUndo());  // settings are not undo steps
    doc.markSaved();
    EXPECT_FALSE(doc.dirty());
    doc.settings.output.exposureEv += 1.0f;
    EXPECT_TRUE(doc.dirty());
}

// A one-node scene's parts: the first click on a node selects it whole, a click on the active
// node picks the part under the cursor; a node of one primitive is never picked in parts.
TEST(Document, ASecondClickOnTheActiveNodePicksThePartUnderTheCursor) {
    Document doc = fixtureDocument();
    Mesh& box = doc.scene.meshes[static_cast<std::size_t>(doc.scene.nodes[kBox].mesh)];
    box.primitives.push_back(box.primitives.front());  // two parts, same material
    ASSERT_EQ(doc.primitiveCount(kBox), 2);
    EXPECT_EQ(doc.primitiveCount(1), 1);
    EXPECT_EQ(doc.primitiveCount(4), 0) << "the empty node";
    EXPECT_EQ(doc.primitiveLabel(kBox, 1), "Primitive 1: Red");

    doc.clickPrimitive(kBox, 1);
    EXPECT_EQ(doc.selectedNode, kBox);
    EXPECT_EQ(doc.selectedPrimitive, 1) << "the inspector edits the part clicked";
    EXPECT_FALSE(doc.primitivePicked) << "the first click selects the node whole";
    doc.clickPrimitive(kBox, 0);
    EXPECT_TRUE(doc.primitivePicked);
    EXPECT_EQ(doc.selectedPrimitive, 0);
    doc.clickPrimitive(kBox, 1);
    EXPECT_TRUE(doc.primitivePicked) << "the next part of the same node";
    EXPECT_EQ(doc.selectedPrimitive, 1);

    doc.clickPrimitive(1, 0);  // another node: whole again
    EXPECT_EQ(doc.selectedNode, 1);
    EXPECT_FALSE(doc.primitivePicked);
    doc.clickPrimitive(1, 0);
    EXPECT_FALSE(doc.primitivePicked) << "one primitive is the node";

    doc.selectPrimitive(kBox, 1);  // the hierarchy's row of the part
    EXPECT_TRUE(doc.primitivePicked);
    doc.select(kBox);
    EXPECT_FALSE(doc.primitivePicked);
    EXPECT_EQ(doc.selectedPrimitive, 0);
    doc.selectPrimitive(kBox, 2);  // out of range: nothing
    EXPECT_EQ(doc.selectedNode, -1);
    EXPECT_FALSE(doc.primitivePicked);
}

}  // namespace
