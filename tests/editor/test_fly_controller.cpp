#include <gtest/gtest.h>

#include <glm/gtc/epsilon.hpp>

#include "FlyController.h"

namespace {

using lit::FlyCamera;
using lit::editor::applyFlyInput;
using lit::editor::FlyControlSettings;
using lit::editor::FlyInput;

constexpr float kEps = 1e-4f;

TEST(EditorFlyController, ForwardMovesAlongTheViewDirectionAtTheCameraSpeed) {
    FlyCamera camera;
    camera.position = {0.0f, 1.0f, 3.0f};
    camera.speed = 2.0f;  // m/s
    FlyInput input;
    input.move.z = 1.0f;
    applyFlyInput(camera, input, 0.5f);
    // yaw 0, pitch 0 looks down −Z: half a second at 2 m/s is one metre.
    EXPECT_TRUE(glm::all(glm::epsilonEqual(camera.position, glm::vec3(0.0f, 1.0f, 2.0f), kEps)));
}

TEST(EditorFlyController, StrafeAndVerticalFollowRightAndWorldUp) {
    FlyCamera camera;
    camera.position = glm::vec3(0.0f);
    camera.speed = 1.0f;
    camera.pitch = 0.5f;  // looking up: "up" still means world +Y
    FlyInput input;
    input.move = {1.0f, 0.0f, 0.0f};
    applyFlyInput(camera, input, 1.0f);
    EXPECT_TRUE(glm::all(glm::epsilonEqual(camera.position, camera.right(), kEps)));
    camera.position = glm::vec3(0.0f);
    input.move = {0.0f, 1.0f, 0.0f};
    applyFlyInput(camera, input, 1.0f);
    EXPECT_TRUE(glm::all(glm::epsilonEqual(camera.position, glm::vec3(0.0f, 1.0f, 0.0f), kEps)));
}

TEST(EditorFlyController, DiagonalIsNotFasterAndShiftIsFaster) {
    FlyCamera camera;
    camera.position = glm::vec3(0.0f);
    camera.speed = 1.0f;
    FlyInput input;
    input.move = {1.0f, 0.0f, 1.0f};
    applyFlyInput(camera, input, 1.0f);
    EXPECT_NEAR(glm::length(camera.position), 1.0f, kEps);

    camera.position = glm::vec3(0.0f);
    input.fast = true;
    const FlyControlSettings settings;
    applyFlyInput(camera, input, 1.0f, settings);
    EXPECT_NEAR(glm::length(camera.position), settings.fastMultiplier, kEps);
}

TEST(EditorFlyController, MouseRightTurnsRightAndMouseDownLooksDown) {
    FlyCamera camera;
    const glm::vec3 rightBefore = camera.right();
    FlyInput input;
    input.lookPixels = {50.0f, 0.0f};
    applyFlyInput(camera, input, 0.0f);
    // The new forward leans toward where "right" was.
    EXPECT_GT(glm::dot(camera.forward(), rightBefore), 0.1f);

    FlyCamera down;
    input.lookPixels = {0.0f, 50.0f};
    applyFlyInput(down, input, 0.0f);
    EXPECT_LT(down.forward().y, -0.1f);
}

TEST(EditorFlyController, PitchStopsShortOfStraightUp) {
    FlyCamera camera;
    FlyInput input;
    input.lookPixels = {0.0f, -1e6f};
    const FlyControlSettings settings;
    applyFlyInput(camera, input, 0.0f, settings);
    EXPECT_FLOAT_EQ(camera.pitch, settings.maxPitch);
    EXPECT_GT(glm::length(glm::vec2(camera.forward().x, camera.forward().z)), 0.01f);
}

TEST(EditorFlyController, WheelScalesSpeedWithinLimits) {
    FlyCamera camera;
    camera.speed = 2.0f;
    FlyInput input;
    input.wheelSteps = 1.0f;
    const FlyControlSettings settings;
    applyFlyInput(camera, input, 0.0f, settings);
    EXPECT_NEAR(camera.speed, 2.0f * settings.speedStepFactor, kEps);
    input.wheelSteps = -1000.0f;
    applyFlyInput(camera, input, 0.0f, settings);
    EXPECT_FLOAT_EQ(camera.speed, settings.minSpeed);
}

TEST(EditorFlyController, YawStaysBounded) {
    FlyCamera camera;
    FlyInput input;
    input.lookPixels = {1e5f, 0.0f};
    for (int i = 0; i < 100; ++i) applyFlyInput(camera, input, 0.0f);
    EXPECT_LE(std::abs(camera.yaw), 3.1416f);
}

TEST(EditorFlyController, SpeedForBoundsScalesWithTheScene) {
    lit::Aabb small;
    small.extend(glm::vec3(-1.0f));
    small.extend(glm::vec3(1.0f));
    lit::Aabb large;
    large.extend(glm::vec3(-30.0f));
    large.extend(glm::vec3(30.0f));
    EXPECT_LT(lit::editor::flySpeedForBounds(small), lit::editor::flySpeedForBounds(large));
    EXPECT_GT(lit::editor::flySpeedForBounds(lit::Aabb{}), 0.0f);
}

}  // namespace

namespace {

using namespace lit;
using namespace lit::editor;

TEST(FlyOrbit, OrbitKeepsTheDistanceAndLooksAtThePivot) {
    FlyCamera camera;
    camera.position = {0.0f, 0.0f, 5.0f};
    const glm::vec3 pivot{0.0f, 0.0f, 1.0f};
    orbitAround(camera, pivot, {200.0f, -50.0f});
    EXPECT_NEAR(glm::length(camera.position - pivot), 4.0f, 1e-4f);
    EXPECT_NEAR(glm::length(glm::normalize(pivot - camera.position) - camera.forward()), 0.0f, 1e-4f);
    // Dragging right takes the camera round to the left (−X seen from +Z).
    EXPECT_LT(camera.position.x, 0.0f);
    // Dragging up (negative y) lowers it below the pivot.
    EXPECT_LT(camera.position.y, 0.0f);
}

TEST(FlyOrbit, FrameBoundsCentresTheBoxAndFitsItInTheView) {
    FlyCamera camera;
    camera.position = {10.0f, 3.0f, 10.0f};
    lookAt(camera, glm::vec3(0.0f));
    Aabb box;
    box.extend(glm::vec3(4.0f, 1.0f, 4.0f));
    box.extend(glm::vec3(6.0f, 3.0f, 6.0f));
    const glm::vec3 forward = camera.forward();
    const float distance = frameBounds(camera, box);
    EXPECT_EQ(camera.forward(), forward);  // orientation kept
    EXPECT_NEAR(glm::length(camera.position + forward * distance - box.center()), 0.0f, 1e-4f);
    // The bounding sphere takes 80 % of the vertical FOV.
    EXPECT_NEAR(std::asin(box.radius() / distance), 0.4f * camera.yfov, 1e-4f);
    EXPECT_EQ(frameBounds(camera, Aabb{}), 0.0f);
}

}  // namespace
