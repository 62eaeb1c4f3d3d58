// The editor's opening view of a scene without a camera (scene/OpeningView.h): inside the largest
// enclosed space at eye height, looking along its longest line of sight; none for an object alone.
#include "Log.h"
#include "scene/GltfLoader.h"
#include "scene/OpeningView.h"
#include "scene/SceneBuilder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace lit {
namespace {

// A room of inside size w × h × d (x, y, z) with 0.2 m walls, its floor's top at y = 0, centred
// on (cx, cz); without a roof when `roof` is false (a courtyard).
void addRoom(Scene& scene, float cx, float cz, float w, float h, float d, bool roof = true) {
    const float t = 0.2f;
    addMeshNode(scene, makeBoxMesh("floor", {w + 2 * t, t, d + 2 * t}, -1), {cx, -t / 2, cz});
    if (roof) addMeshNode(scene, makeBoxMesh("roof", {w + 2 * t, t, d + 2 * t}, -1), {cx, h + t / 2, cz});
    addMeshNode(scene, makeBoxMesh("west", {t, h, d}, -1), {cx - w / 2 - t / 2, h / 2, cz});
    addMeshNode(scene, makeBoxMesh("east", {t, h, d}, -1), {cx + w / 2 + t / 2, h / 2, cz});
    addMeshNode(scene, makeBoxMesh("north", {w + 2 * t, h, t}, -1), {cx, h / 2, cz - d / 2 - t / 2});
    addMeshNode(scene, makeBoxMesh("south", {w + 2 * t, h, t}, -1), {cx, h / 2, cz + d / 2 + t / 2});
}

TEST(OpeningView, StandsInsideARoomAtEyeHeightLookingAlongIt) {
    Scene scene;
    addRoom(scene, 0.0f, 0.0f, 12.0f, 3.0f, 6.0f);
    scene.updateWorldTransforms();
    const auto view = findOpeningView(scene);
    ASSERT_TRUE(view.has_value());
    EXPECT_GT(view->position.x, -6.0f);
    EXPECT_LT(view->position.x, 6.0f);
    EXPECT_GT(view->position.z, -3.0f);
    EXPECT_LT(view->position.z, 3.0f);
    EXPECT_NEAR(view->position.y, 1.5f, 0.2f) << "half the 3 m room's height: lower than 1.6 m";
    EXPECT_GT(std::abs(view->forward.x), 0.9f) << "the room's long axis is x";
    EXPECT_FLOAT_EQ(view->forward.y, 0.0f);
}

TEST(OpeningView, TheEditorsDefaultCameraStandsThere) {
    Scene scene;
    addRoom(scene, 0.0f, 0.0f, 12.0f, 3.0f, 6.0f);
    scene.updateWorldTransforms();
    Log log;
    ASSERT_TRUE(addDefaultCamera(scene, log, DefaultCameraPlacement::InsideLargestSpace));
    const Node& node = scene.nodes.back();
    ASSERT_GE(node.camera, 0);
    const glm::vec3 position(node.world[3]);
    EXPECT_LT(std::abs(position.x), 6.0f);
    EXPECT_NEAR(position.y, 1.5f, 0.2f);
    const glm::vec3 forward = glm::normalize(glm::vec3(node.world * glm::vec4(0, 0, -1, 0)));
    EXPECT_GT(std::abs(forward.x), 0.9f);
    // lit-render's placement frames the bounds from outside.
    Scene framed;
    addRoom(framed, 0.0f, 0.0f, 12.0f, 3.0f, 6.0f);
    framed.updateWorldTransforms();
    ASSERT_TRUE(addDefaultCamera(framed, log));
    EXPECT_GT(glm::vec3(framed.nodes.back().world[3]).z, 3.2f) << "outside the room";
}

TEST(OpeningView, PicksTheLargestOfTwoRooms) {
    Scene scene;
    addRoom(scene, -10.0f, 0.0f, 4.0f, 3.0f, 4.0f);
    addRoom(scene, 8.0f, 0.0f, 14.0f, 6.0f, 10.0f);
    scene.updateWorldTransforms();
    const auto view = findOpeningView(scene);
    ASSERT_TRUE(view.has_value());
    EXPECT_GT(view->position.x, 1.0f) << "in the large room (x from 1 to 15)";
    EXPECT_NEAR(view->position.y, 1.6f, 0.35f) << "eye height in a 6 m room";
}

TEST(OpeningView, ACourtyardOpenToTheSkyCounts) {
    Scene scene;
    addRoom(scene, 0.0f, 0.0f, 10.0f, 4.0f, 10.0f, false);
    scene.updateWorldTransforms();
    const auto view = findOpeningView(scene);
    ASSERT_TRUE(view.has_value());
    EXPECT_NEAR(view->position.y, 1.6f, 0.35f);
    EXPECT_LT(glm::length(glm::vec2(view->position.x, view->position.z)), 5.0f);
}

TEST(OpeningView, AnObjectAloneHasNone) {
    Scene scene;
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), -1), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    EXPECT_FALSE(findOpeningView(scene).has_value());
    // A hollow box too low to stand in is an object too.
    Scene low;
    addRoom(low, 0.0f, 0.0f, 3.0f, 1.2f, 3.0f);
    low.updateWorldTransforms();
    EXPECT_FALSE(findOpeningView(low).has_value());
}

// Sponza (../shared/scenes, skipped without): it has no camera, and the framing view from outside
// looks at its roof. The opening view stands on the ground floor inside, clear of the columns.
TEST(OpeningView, SponzaOpensInsideOnTheGroundFloor) {
    const std::filesystem::path path = LIT_SOURCE_DIR "/../shared/scenes/sponza/Sponza.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "Sponza not available at " << path;
    Log log;
    GltfLoadOptions options;
    Scene scene = loadGltf(path, log, options);
    scene.updateWorldTransforms();
    const Aabb bounds = scene.worldBounds();
    const auto view = findOpeningView(scene);
    ASSERT_TRUE(view.has_value());
    for (int a = 0; a < 3; ++a) {
        EXPECT_GT(view->position[a], bounds.min[a]);
        EXPECT_LT(view->position[a], bounds.max[a]);
    }
    EXPECT_LT(view->position.y - bounds.min.y, 0.3f * (bounds.max.y - bounds.min.y)) << "on the ground floor";
    EXPECT_GT(view->clearance, 0.75f);
    std::printf("[          ] Sponza opens at (%.2f, %.2f, %.2f) looking (%.2f, %.2f, %.2f), clearance %.2f m\n",
                view->position.x, view->position.y, view->position.z, view->forward.x, view->forward.y,
                view->forward.z, view->clearance);
}

}  // namespace
}  // namespace lit
