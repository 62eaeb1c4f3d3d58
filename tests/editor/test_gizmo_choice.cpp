#include <gtest/gtest.h>

#include "GizmoChoice.h"
#include "SceneEdits.h"

namespace {

using namespace lit;
using namespace lit::editor;

TEST(GizmoChoice, ScaleFallsBackToMoveOnLightsAndCameras) {
    Document doc;
    const int lamp = addNode(doc, NodeKind::PointLight, {0, 1, 0});
    const int spot = addNode(doc, NodeKind::SpotLight, {1, 1, 0});
    const int sun = addNode(doc, NodeKind::DirectionalLight, {0, 3, 0});
    const int camera = addNode(doc, NodeKind::Camera, {0, 1, 4});
    const int box = addNode(doc, NodeKind::Box, {0, 0, 0});
    const int empty = addNode(doc, NodeKind::Empty, {0, 0, 0});
    GizmoTool tool;
    tool.mode = GizmoMode::Scale;
    for (const int node : {lamp, spot, sun, camera}) {
        EXPECT_FALSE(scaleAppliesTo(doc.scene, node)) << node;
        EXPECT_EQ(gizmoModeFor(tool, doc.scene, node), GizmoMode::Translate) << node;
    }
    // Things with a size keep the scale gizmo, and so does an empty (its children scale with it).
    for (const int node : {box, empty, -1}) {
        EXPECT_TRUE(scaleAppliesTo(doc.scene, node)) << node;
        EXPECT_EQ(gizmoModeFor(tool, doc.scene, node), GizmoMode::Scale) << node;
    }
    // Rotate means something for a spot light or a camera: it stays.
    tool.mode = GizmoMode::Rotate;
    EXPECT_EQ(gizmoModeFor(tool, doc.scene, spot), GizmoMode::Rotate);
    // A light with children: scaling it scales them.
    doc.select(box);
    ASSERT_EQ(reparentSelection(doc, lamp), "");
    EXPECT_TRUE(scaleAppliesTo(doc.scene, lamp));
}

}  // namespace
