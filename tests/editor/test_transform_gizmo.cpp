#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "TransformGizmo.h"

namespace {

using namespace lit;
using namespace lit::editor;

// A camera at (0, 0, 5) looking down −Z at the origin, 800×600 window (as test_translate_gizmo).
CameraView testView() {
    FlyCamera camera;
    camera.position = {0.0f, 0.0f, 5.0f};
    camera.yaw = 0.0f;
    camera.pitch = 0.0f;
    camera.yfov = 0.8f;
    return camera.view(800.0f / 600.0f, 0.1f, 100.0f);
}
constexpr glm::vec2 kViewport{800.0f, 600.0f};
const glm::mat3 kWorldAxes(1.0f);

glm::vec2 screenOf(glm::vec3 point) { return *projectToScreen(testView(), kViewport, point); }

TEST(TransformGizmo, LocalAxesFollowTheNodeAndScaleIsAlwaysLocal) {
    const glm::mat4 world = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)) *
                            glm::scale(glm::mat4(1.0f), glm::vec3(3.0f));
    const glm::mat3 local = gizmoAxes(GizmoMode::Translate, GizmoSpace::Local, world);
    EXPECT_NEAR(glm::length(local[0] - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);  // X turned to −Z, unit length
    EXPECT_EQ(gizmoAxes(GizmoMode::Rotate, GizmoSpace::World, world), glm::mat3(1.0f));
    const glm::mat3 scale = gizmoAxes(GizmoMode::Scale, GizmoSpace::World, world);
    EXPECT_NEAR(glm::length(scale[0] - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
}

TEST(TransformGizmo, RotateRingsArePickedOnTheRing) {
    const CameraView view = testView();
    // Seen from +Z, the Z ring is a circle of kRingPixels around the centre; X and Y rings are
    // edge-on lines through it (vertical and horizontal).
    const glm::vec2 centre = screenOf(glm::vec3(0.0f));
    const float r = TransformGizmo::kRingPixels;
    EXPECT_EQ(TransformGizmo::hitTest(GizmoMode::Rotate, view, kViewport, glm::vec3(0.0f), kWorldAxes,
                                      centre + glm::vec2(r * 0.7071f, r * 0.7071f)), 2);
    EXPECT_EQ(TransformGizmo::hitTest(GizmoMode::Rotate, view, kViewport, glm::vec3(0.0f), kWorldAxes,
                                      centre + glm::vec2(2.0f, 40.0f)), 0);  // the X ring: the vertical line
    EXPECT_EQ(TransformGizmo::hitTest(GizmoMode::Rotate, view, kViewport, glm::vec3(0.0f), kWorldAxes,
                                      centre + glm::vec2(40.0f, 45.0f)), -1);  // inside, off every ring
}

TEST(TransformGizmo, RotateFollowsTheMouseAroundTheCentreAndUnwraps) {
    const CameraView view = testView();
    const glm::vec2 centre = screenOf(glm::vec3(0.0f));
    const float r = TransformGizmo::kRingPixels;
    TransformGizmo gizmo;
    ASSERT_TRUE(gizmo.begin(GizmoMode::Rotate, 2, view, kViewport, glm::vec3(0.0f), kWorldAxes, centre + glm::vec2(r, 0)));
    // A quarter turn counter-clockwise on screen (right → up) about +Z, which points at the
    // camera: +90° about Z, so +X goes to +Y.
    GizmoDelta delta = gizmo.drag(view, kViewport, centre + glm::vec2(0, -r), {});
    EXPECT_NEAR(glm::degrees(delta.angle), 90.0f, 1e-3f);
    const glm::mat4 turned = applyGizmoDelta(GizmoMode::Rotate, delta, glm::vec3(0.0f), glm::mat4(1.0f));
    EXPECT_NEAR(glm::length(glm::vec3(turned * glm::vec4(1, 0, 0, 0)) - glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
    // Keep going round through left and down to right again: a full turn, not zero.
    gizmo.drag(view, kViewport, centre + glm::vec2(-r, 0), {});
    gizmo.drag(view, kViewport, centre + glm::vec2(0, r), {});
    delta = gizmo.drag(view, kViewport, centre + glm::vec2(r, 0), {});
    EXPECT_NEAR(glm::degrees(delta.angle), 360.0f, 1e-3f);
}

TEST(TransformGizmo, RotateAboutAnAxisPointingAwayTurnsTheOtherWay) {
    const CameraView view = testView();
    const glm::vec2 centre = screenOf(glm::vec3(0.0f));
    glm::mat3 axes(1.0f);
    axes[2] = -axes[2];  // a local Z pointing away from the camera
    TransformGizmo gizmo;
    ASSERT_TRUE(gizmo.begin(GizmoMode::Rotate, 2, view, kViewport, glm::vec3(0.0f), axes, centre + glm::vec2(80, 0)));
    const GizmoDelta delta = gizmo.drag(view, kViewport, centre + glm::vec2(0, -80), {});
    EXPECT_NEAR(glm::degrees(delta.angle), -90.0f, 1e-3f);
    EXPECT_EQ(delta.rotationAxis, axes[2]);
}

TEST(TransformGizmo, RotateAboutAPivotMovesOtherNodesAround) {
    GizmoDelta delta;
    delta.rotationAxis = {0, 1, 0};
    delta.angle = glm::radians(180.0f);
    const glm::mat4 start = glm::translate(glm::mat4(1.0f), {2.0f, 0.0f, 0.0f});
    const glm::mat4 moved = applyGizmoDelta(GizmoMode::Rotate, delta, glm::vec3(1.0f, 0.0f, 0.0f), start);
    EXPECT_NEAR(glm::length(glm::vec3(moved[3]) - glm::vec3(0.0f, 0.0f, 0.0f)), 0.0f, 1e-5f);
}

TEST(TransformGizmo, SnappingRoundsAnglesDistancesAndFactors) {
    const CameraView view = testView();
    const glm::vec2 centre = screenOf(glm::vec3(0.0f));
    GizmoSnap snap;
    snap.enabled = true;
    snap.rotateStepDegrees = 15.0f;
    TransformGizmo gizmo;
    ASSERT_TRUE(gizmo.begin(GizmoMode::Rotate, 2, view, kViewport, glm::vec3(0.0f), kWorldAxes, centre + glm::vec2(80, 0)));
    // 40° on screen snaps to 45°.
    const float a = glm::radians(40.0f);
    const GizmoDelta rotated = gizmo.drag(view, kViewport, centre + 80.0f * glm::vec2(std::cos(a), -std::sin(a)), snap);
    EXPECT_NEAR(glm::degrees(rotated.angle), 45.0f, 1e-3f);

    snap.translateStep = 0.25f;
    ASSERT_TRUE(gizmo.begin(GizmoMode::Translate, 0, view, kViewport, glm::vec3(0.0f), kWorldAxes, screenOf({0.3f, 0, 0})));
    const GizmoDelta moved = gizmo.drag(view, kViewport, screenOf({0.3f + 0.61f, 0, 0}), snap);
    EXPECT_NEAR(moved.translation.x, 0.5f, 1e-5f);  // 0.61 m → 0.5 m
    EXPECT_EQ(moved.translation.y, 0.0f);

    snap.scaleStep = 0.1f;
    const float length = TranslateGizmo::axisLength(view, kViewport, glm::vec3(0.0f));
    ASSERT_TRUE(gizmo.begin(GizmoMode::Scale, 1, view, kViewport, glm::vec3(0.0f), kWorldAxes, screenOf({0, length, 0})));
    const GizmoDelta scaled = gizmo.drag(view, kViewport, screenOf({0, length * 1.537f, 0}), snap);
    EXPECT_NEAR(scaled.scale.y, 1.5f, 1e-4f);  // 1.537 → 1.5
    EXPECT_EQ(scaled.scale.x, 1.0f);
    EXPECT_EQ(snapTo(0.74f, 0.25f), 0.75f);
    EXPECT_EQ(snapTo(0.74f, 0.0f), 0.74f);
}

TEST(TransformGizmo, ScaleHandleLengthDoublesAndCentreScalesUniformly) {
    const CameraView view = testView();
    const float length = TranslateGizmo::axisLength(view, kViewport, glm::vec3(0.0f));
    TransformGizmo gizmo;
    ASSERT_EQ(TransformGizmo::hitTest(GizmoMode::Scale, view, kViewport, glm::vec3(0.0f), kWorldAxes, screenOf({0, 0, 0})),
              TransformGizmo::kUniformHandle);
    ASSERT_EQ(TransformGizmo::hitTest(GizmoMode::Scale, view, kViewport, glm::vec3(0.0f), kWorldAxes,
                                      screenOf({length * 0.8f, 0, 0})), 0);
    ASSERT_TRUE(gizmo.begin(GizmoMode::Scale, 0, view, kViewport, glm::vec3(0.0f), kWorldAxes, screenOf({length, 0, 0})));
    GizmoDelta delta = gizmo.drag(view, kViewport, screenOf({2.0f * length, 0, 0}), {});
    EXPECT_NEAR(delta.scale.x, 2.0f, 1e-3f);
    // Scale acts along the node's own axes about its own origin.
    const glm::mat4 start = glm::translate(glm::mat4(1.0f), {1.0f, 2.0f, 3.0f});
    const glm::mat4 scaled = applyGizmoDelta(GizmoMode::Scale, delta, glm::vec3(0.0f), start);
    EXPECT_EQ(glm::vec3(scaled[3]), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_NEAR(glm::length(glm::vec3(scaled[0])), 2.0f, 1e-3f);

    const glm::vec2 centre = screenOf(glm::vec3(0.0f));
    ASSERT_TRUE(gizmo.begin(GizmoMode::Scale, TransformGizmo::kUniformHandle, view, kViewport, glm::vec3(0.0f), kWorldAxes,
                            centre));
    delta = gizmo.drag(view, kViewport, centre + glm::vec2(TransformGizmo::kAxisPixels * 0.5f, 0.0f), {});
    EXPECT_NEAR(delta.scale.x, 1.5f, 1e-5f);
    EXPECT_EQ(delta.scale.x, delta.scale.z);
    // Dragging far inwards never reaches zero (glTF forbids a zero scale).
    delta = gizmo.drag(view, kViewport, centre - glm::vec2(1000.0f, 0.0f), {});
    EXPECT_GT(delta.scale.x, 0.0f);
}

TEST(TransformGizmo, TranslateAlongALocalAxis) {
    const CameraView view = testView();
    const glm::mat4 world = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
    const glm::mat3 axes = gizmoAxes(GizmoMode::Translate, GizmoSpace::Local, world);
    TransformGizmo gizmo;
    ASSERT_TRUE(gizmo.begin(GizmoMode::Translate, 0, view, kViewport, glm::vec3(0.0f), axes, screenOf(axes[0] * 0.3f)));
    const GizmoDelta delta = gizmo.drag(view, kViewport, screenOf(axes[0] * 1.3f), {});
    EXPECT_NEAR(glm::length(delta.translation - axes[0]), 0.0f, 1e-3f);  // 1 m along the turned X
}

TEST(TransformGizmo, LinesPerModeAndHighlight) {
    const CameraView view = testView();
    const auto rings = gizmoLines(GizmoMode::Rotate, view, kViewport, glm::vec3(0.0f), kWorldAxes, 1);
    EXPECT_EQ(rings.size(), 3u * TransformGizmo::kRingSegments);
    int yellow = 0;
    for (const OverlayLine& line : rings) yellow += line.color == glm::vec4(1.0f, 0.95f, 0.2f, 1.0f) ? 1 : 0;
    EXPECT_EQ(yellow, TransformGizmo::kRingSegments);  // the hovered ring only
    EXPECT_EQ(gizmoLines(GizmoMode::Translate, view, kViewport, glm::vec3(0.0f), kWorldAxes, -1).size(), 15u);
    EXPECT_EQ(gizmoLines(GizmoMode::Scale, view, kViewport, glm::vec3(0.0f), kWorldAxes, -1).size(), 3u * 13u + 12u);
}

TEST(TransformGizmo, ModeNamesRoundTrip) {
    for (GizmoMode mode : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale})
        EXPECT_EQ(parseGizmoMode(gizmoModeName(mode)), mode);
    EXPECT_FALSE(parseGizmoMode("spin").has_value());
}

}  // namespace
