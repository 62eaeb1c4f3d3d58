#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "TranslateGizmo.h"

namespace {

using namespace lit;
using namespace lit::editor;

// A camera at (0, 0, 5) looking down −Z at the origin, 800×600 window.
CameraView testView() {
    FlyCamera camera;
    camera.position = {0.0f, 0.0f, 5.0f};
    camera.yaw = 0.0f;
    camera.pitch = 0.0f;
    camera.yfov = 0.8f;
    return camera.view(800.0f / 600.0f, 0.1f, 100.0f);
}
constexpr glm::vec2 kViewport{800.0f, 600.0f};

TEST(TranslateGizmo, ScreenRayThroughAProjectedPointHitsIt) {
    const CameraView view = testView();
    const glm::vec3 point{0.7f, -0.4f, -1.5f};
    const auto screen = projectToScreen(view, kViewport, point);
    ASSERT_TRUE(screen.has_value());
    const ScreenRay ray = screenRay(view, kViewport, *screen);
    const glm::vec3 toPoint = point - ray.origin;
    const glm::vec3 offAxis = toPoint - glm::dot(toPoint, ray.direction) * ray.direction;
    EXPECT_LT(glm::length(offAxis), 1e-4f);
}

TEST(TranslateGizmo, CentreOfTheWindowProjectsFromTheOrigin) {
    const auto screen = projectToScreen(testView(), kViewport, glm::vec3(0.0f));
    ASSERT_TRUE(screen.has_value());
    EXPECT_NEAR(screen->x, 400.0f, 1e-3f);
    EXPECT_NEAR(screen->y, 300.0f, 1e-3f);
    EXPECT_FALSE(projectToScreen(testView(), kViewport, glm::vec3(0.0f, 0.0f, 10.0f)).has_value());  // behind
}

TEST(TranslateGizmo, AxesSpanTheirPixelLengthOnScreen) {
    const CameraView view = testView();
    const float length = TranslateGizmo::axisLength(view, kViewport, glm::vec3(0.0f));
    const glm::vec2 a = *projectToScreen(view, kViewport, glm::vec3(0.0f));
    const glm::vec2 b = *projectToScreen(view, kViewport, glm::vec3(length, 0.0f, 0.0f));
    EXPECT_NEAR(glm::length(b - a), TranslateGizmo::kAxisPixels, 1.0f);
}

TEST(TranslateGizmo, HitTestFindsTheAxisUnderTheMouse) {
    const CameraView view = testView();
    // From straight ahead X goes right, Y goes up on screen, Z points at the camera (a dot).
    EXPECT_EQ(TranslateGizmo::hitTest(view, kViewport, glm::vec3(0.0f), {450.0f, 301.0f}), 0);
    EXPECT_EQ(TranslateGizmo::hitTest(view, kViewport, glm::vec3(0.0f), {401.0f, 250.0f}), 1);
    EXPECT_EQ(TranslateGizmo::hitTest(view, kViewport, glm::vec3(0.0f), {450.0f, 360.0f}), -1);  // empty space
    EXPECT_EQ(TranslateGizmo::hitTest(view, kViewport, glm::vec3(0.0f), {300.0f, 300.0f}), -1);  // left of X's start
}

TEST(TranslateGizmo, DraggingFollowsTheMouseAlongTheAxisOnly) {
    const CameraView view = testView();
    TranslateGizmo gizmo;
    const glm::vec3 origin{0.2f, 0.1f, 0.0f};
    const glm::vec2 grab = *projectToScreen(view, kViewport, origin + glm::vec3(0.3f, 0.0f, 0.0f));
    ASSERT_TRUE(gizmo.begin(0, view, kViewport, origin, grab));
    // Move the mouse to where (origin + 1.3 X) projects, plus some vertical wobble.
    const glm::vec2 target = *projectToScreen(view, kViewport, origin + glm::vec3(1.3f, 0.0f, 0.0f));
    const glm::vec3 moved = gizmo.drag(view, kViewport, target + glm::vec2(0.0f, 25.0f));
    EXPECT_NEAR(moved.x, origin.x + 1.0f, 1e-3f);
    EXPECT_FLOAT_EQ(moved.y, origin.y);  // only X changes
    EXPECT_FLOAT_EQ(moved.z, origin.z);
    // No mouse motion: no movement.
    const glm::vec3 still = gizmo.drag(view, kViewport, grab);
    EXPECT_NEAR(glm::length(still - origin), 0.0f, 1e-4f);
}

TEST(TranslateGizmo, AnAxisPointingAtTheCameraCannotBeDragged) {
    const CameraView view = testView();
    TranslateGizmo gizmo;
    EXPECT_FALSE(gizmo.begin(2, view, kViewport, glm::vec3(0.0f), {400.0f, 300.0f}));
    EXPECT_FALSE(gizmo.active());
}

}  // namespace
