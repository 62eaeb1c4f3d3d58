#include <gtest/gtest.h>

#include <cmath>

#include "PathEditing.h"

namespace {

using namespace lit;
using namespace lit::editor;

FlyCamera cameraAt(glm::vec3 position, float yaw) {
    FlyCamera camera;
    camera.position = position;
    camera.yaw = yaw;
    camera.pitch = 0.1f;
    camera.yfov = 0.9f;
    return camera;
}

Document threeKeyDocument() {
    Document doc;
    addKey(doc, keyFromCamera(cameraAt({0, 1, 3}, 0.0f), 0.0f));
    addKey(doc, keyFromCamera(cameraAt({1, 1, 2}, 0.5f), 1.0f));
    addKey(doc, keyFromCamera(cameraAt({2, 1, 0}, 1.0f), 2.0f));
    return doc;
}

TEST(PathEditing, KeyFromCameraRoundTripsThroughAPose) {
    const FlyCamera camera = cameraAt({1, 2, 3}, 0.7f);
    const CameraKey key = keyFromCamera(camera, 0.0f);
    FlyCamera back;
    applyPoseToCamera(CameraPose{key.position, key.rotation, key.yfov}, back);
    EXPECT_NEAR(glm::length(back.position - camera.position), 0.0f, 1e-5f);
    EXPECT_NEAR(back.yaw, camera.yaw, 1e-4f);
    EXPECT_NEAR(back.pitch, camera.pitch, 1e-4f);
    EXPECT_NEAR(back.yfov, camera.yfov, 1e-6f);
    EXPECT_NEAR(glm::length(back.forward() - camera.forward()), 0.0f, 1e-4f);
}

TEST(PathEditing, EachActionIsOneUndoStep) {
    Document doc = threeKeyDocument();
    ASSERT_EQ(doc.cameraPath.keys().size(), 3u);
    EXPECT_EQ(doc.undoLabel(), "Add Key");
    ASSERT_TRUE(retimeKey(doc, 1, 1.5f));
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[1].time, 1.5f);
    ASSERT_TRUE(deleteKey(doc, 0));
    EXPECT_EQ(doc.cameraPath.keys().size(), 2u);
    ASSERT_TRUE(doc.undo());  // the delete
    EXPECT_EQ(doc.cameraPath.keys().size(), 3u);
    ASSERT_TRUE(doc.undo());  // the retime
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[1].time, 1.0f);
    ASSERT_TRUE(doc.redo());
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[1].time, 1.5f);
}

TEST(PathEditing, RetimingStaysBetweenTheNeighbours) {
    Document doc = threeKeyDocument();
    ASSERT_TRUE(retimeKey(doc, 1, 5.0f));  // past key 2 at 2 s
    EXPECT_LT(doc.cameraPath.keys()[1].time, 2.0f);
    EXPECT_GE(doc.cameraPath.keys()[1].time, 2.0f - 2.0f * kMinKeySpacing);
    ASSERT_TRUE(retimeKey(doc, 1, -3.0f));
    EXPECT_GT(doc.cameraPath.keys()[1].time, 0.0f);
    ASSERT_TRUE(retimeKey(doc, 0, -3.0f));  // the first key may move earlier freely
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[0].time, -3.0f);
    EXPECT_FALSE(retimeKey(doc, 7, 1.0f));
}

TEST(PathEditing, AddingAtAnOccupiedTimeMovesTheNewKeyOn) {
    Document doc = threeKeyDocument();
    const std::size_t index = addKey(doc, keyFromCamera(cameraAt({5, 1, 5}, 0.0f), 1.0f));
    EXPECT_EQ(index, 2u);
    EXPECT_NEAR(doc.cameraPath.keys()[index].time, 1.0f + kMinKeySpacing, 1e-6f);
    EXPECT_EQ(doc.selectedKey, 2);
}

TEST(PathEditing, PlaybackStopsAtTheEndOrWrapsWhenLooping) {
    Document doc = threeKeyDocument();
    PathPlayback playback;
    playback.play(doc.cameraPath);
    playback.advance(doc.cameraPath, 1.25);
    EXPECT_NEAR(playback.time, 1.25, 1e-9);
    playback.advance(doc.cameraPath, 5.0);
    EXPECT_DOUBLE_EQ(playback.time, doc.cameraPath.endTime());
    EXPECT_FALSE(playback.playing);
    playback.play(doc.cameraPath);  // at the end: starts over
    EXPECT_DOUBLE_EQ(playback.time, doc.cameraPath.startTime());

    setPathOptions(doc, CameraPathOptions{.loop = true});
    playback.advance(doc.cameraPath, doc.cameraPath.duration() + 0.25);
    EXPECT_TRUE(playback.playing);
    EXPECT_NEAR(playback.time, doc.cameraPath.startTime() + 0.25, 1e-6);
}

TEST(PathEditing, ScriptCommandsDriveKeysAndPlayback) {
    Document doc;
    PathPlayback playback;
    FlyCamera camera = cameraAt({0, 1, 3}, 0.0f);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "play", {}), "the camera path has no keys and no node is animated");
    EXPECT_EQ(runPathCommand(doc, playback, camera, "key", {"add"}), "");
    camera.position = {1, 1, 1};
    EXPECT_EQ(runPathCommand(doc, playback, camera, "time", {"2"}), "");
    // "time" points the camera at the path (one key: that key).
    EXPECT_NEAR(glm::length(camera.position - glm::vec3(0, 1, 3)), 0.0f, 1e-5f);
    camera.position = {1, 1, 1};
    EXPECT_EQ(runPathCommand(doc, playback, camera, "key", {"add"}), "");
    ASSERT_EQ(doc.cameraPath.keys().size(), 2u);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "key", {"time", "1", "3.5"}), "");
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[1].time, 3.5f);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "key", {"select", "0"}), "");
    EXPECT_EQ(doc.selectedKey, 0);
    EXPECT_NE(runPathCommand(doc, playback, camera, "key", {"select", "9"}).find("no key 9"), std::string::npos);
    EXPECT_NE(runPathCommand(doc, playback, camera, "key", {"time", "1", "abc"}), "");
    EXPECT_NE(runPathCommand(doc, playback, camera, "key", {"spin", "1"}).find("unknown key action"), std::string::npos);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "play", {}), "");
    EXPECT_TRUE(playback.playing);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "pause", {}), "");
    EXPECT_FALSE(playback.playing);
    EXPECT_EQ(runPathCommand(doc, playback, camera, "key", {"delete", "1"}), "");
    EXPECT_EQ(doc.cameraPath.keys().size(), 1u);
}

TEST(PathEditing, PlusKeyFromThreeViewsGivesKeysASecondApartAndMovesThePlayhead) {
    Document doc;
    PathPlayback playback;
    const glm::vec3 views[] = {{0, 1, 3}, {1, 1, 2}, {2, 1, 0}};
    for (const glm::vec3& view : views) addKeyFromView(doc, playback, cameraAt(view, 0.0f));
    const std::vector<CameraKey>& keys = doc.cameraPath.keys();
    ASSERT_EQ(keys.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(keys[i].time, static_cast<float>(i) * kDefaultKeyInterval);
        EXPECT_EQ(keys[i].position, views[i]);
    }
    EXPECT_DOUBLE_EQ(playback.time, 2.0 * kDefaultKeyInterval);
    EXPECT_EQ(doc.selectedKey, 2);
    ASSERT_TRUE(doc.undo());  // each "+ Key" is its own step
    EXPECT_EQ(doc.cameraPath.keys().size(), 2u);
}

TEST(PathEditing, NextKeyTimeFollowsTheMeanSpacingOrThePlayhead) {
    EXPECT_FLOAT_EQ(nextKeyTime(CameraPath(), 0.5), 0.5f);  // empty: at the playhead
    Document doc;
    addKey(doc, keyFromCamera(cameraAt({0, 1, 3}, 0.0f), 0.0f));
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, 0.0), kDefaultKeyInterval);  // on the only key
    addKey(doc, keyFromCamera(cameraAt({1, 1, 3}, 0.0f), 2.0f));
    addKey(doc, keyFromCamera(cameraAt({2, 1, 3}, 0.0f), 4.0f));
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, 4.0), 6.0f);   // on the last key: mean spacing 2 s
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, 2.0), 6.0f);   // on a middle key: after the last
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, -1.0), 6.0f);  // before the first key: after the last
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, 5.0), 5.0f);   // past the end: at the playhead
    EXPECT_FLOAT_EQ(nextKeyTime(doc.cameraPath, 1.0), 1.0f);   // between keys: inserted there

    // Keys piled up a frame apart do not make the next one pile up too.
    Document piled;
    addKey(piled, keyFromCamera(cameraAt({0, 1, 3}, 0.0f), 0.0f));
    addKey(piled, keyFromCamera(cameraAt({0, 1, 3}, 0.0f), 0.0f));
    ASSERT_EQ(piled.cameraPath.keys().size(), 2u);
    EXPECT_FLOAT_EQ(nextKeyTime(piled.cameraPath, piled.cameraPath.endTime()),
                    piled.cameraPath.endTime() + kMinAddedKeyInterval);
}

// The node animations share the path's clock: playback and the ruler cover the later end, and a
// scene with animated nodes and no keys plays too.
TEST(PathEditing, PlaybackCoversTheNodeAnimations) {
    const CameraPath empty;
    PathPlayback playback;
    playback.play(empty, 0.0);
    EXPECT_FALSE(playback.playing);  // nothing to play
    playback.time = 5.0;
    playback.play(empty, 2.0);
    ASSERT_TRUE(playback.playing);
    EXPECT_DOUBLE_EQ(playback.time, 0.0);  // at the end: from the start again
    playback.advance(empty, 1.5, 2.0);
    EXPECT_DOUBLE_EQ(playback.time, 1.5);
    EXPECT_TRUE(playback.playing);
    playback.advance(empty, 1.0, 2.0);
    EXPECT_DOUBLE_EQ(playback.time, 2.0);  // the animations' end
    EXPECT_FALSE(playback.playing);

    const Document doc = threeKeyDocument();  // keys at 0, 1, 2 s
    EXPECT_DOUBLE_EQ(playSpan(doc.cameraPath, 5.0).end, 5.0);  // the animations run longer
    EXPECT_DOUBLE_EQ(playSpan(doc.cameraPath, 1.0).end, 2.0);  // the path does
    EXPECT_DOUBLE_EQ(playSpan(doc.cameraPath).end, 2.0);
    EXPECT_DOUBLE_EQ(scrubSpan(doc.cameraPath, 5.0).end, 5.0 + 1.25);  // a quarter past the end
    EXPECT_DOUBLE_EQ(scrubSpan(empty, 2.0).end, 3.0);                  // at least a second past it
    playback.time = 0.0;
    playback.play(doc.cameraPath, 5.0);
    playback.advance(doc.cameraPath, 3.0, 5.0);
    EXPECT_DOUBLE_EQ(playback.time, 3.0);  // past the path's last key, the animations play on
    EXPECT_TRUE(playback.playing);
}

TEST(PathEditing, TheScrubSpanReachesPastTheLastKey) {
    EXPECT_DOUBLE_EQ(scrubSpan(CameraPath()).end, kDefaultKeyInterval);
    Document doc = threeKeyDocument();  // keys at 0, 1, 2 s
    const TimeSpan span = scrubSpan(doc.cameraPath);
    EXPECT_DOUBLE_EQ(span.start, 0.0);
    EXPECT_DOUBLE_EQ(span.end, 3.0);  // a second (more than a quarter of 2 s) past the end
    ASSERT_TRUE(retimeKey(doc, 2, 10.0f));
    EXPECT_DOUBLE_EQ(scrubSpan(doc.cameraPath).end, 12.5);
    // The playhead past the end shows the last key's view.
    FlyCamera camera;
    lookThroughPath(doc.cameraPath, 12.0, camera);
    EXPECT_NEAR(glm::length(camera.position - glm::vec3(2, 1, 0)), 0.0f, 1e-5f);
}

TEST(PathEditing, TheDurationSpreadsTheKeysInProportionAsOneUndoStep) {
    Document doc = threeKeyDocument();
    ASSERT_TRUE(setPathDuration(doc, 6.0f));
    EXPECT_EQ(doc.undoLabel(), "Path Duration");
    const std::vector<CameraKey>& keys = doc.cameraPath.keys();
    EXPECT_FLOAT_EQ(keys[0].time, 0.0f);
    EXPECT_FLOAT_EQ(keys[1].time, 3.0f);
    EXPECT_FLOAT_EQ(keys[2].time, 6.0f);
    EXPECT_FLOAT_EQ(doc.cameraPath.duration(), 6.0f);
    // Too short a duration keeps the keys a key spacing apart.
    ASSERT_TRUE(setPathDuration(doc, 1e-6f));
    EXPECT_GE(doc.cameraPath.keys()[1].time - doc.cameraPath.keys()[0].time, kMinKeySpacing);
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_FLOAT_EQ(doc.cameraPath.keys()[2].time, 2.0f);
    EXPECT_FALSE(setPathDuration(doc, 0.0f));
    Document one;
    addKey(one, keyFromCamera(cameraAt({0, 1, 3}, 0.0f), 0.0f));
    EXPECT_FALSE(setPathDuration(one, 3.0f));
}

TEST(PathEditing, TheRulerPicksTheNearestKey) {
    Document doc = threeKeyDocument();
    EXPECT_EQ(keyNear(doc.cameraPath, 0.9, 0.2), 1);
    EXPECT_EQ(keyNear(doc.cameraPath, 1.6, 0.2), -1);
    ASSERT_TRUE(retimeKey(doc, 1, 0.05f));  // drawn almost on top of key 0
    EXPECT_EQ(keyNear(doc.cameraPath, 0.01, 0.1), 0);
    EXPECT_EQ(keyNear(doc.cameraPath, 0.04, 0.1), 1);
}

TEST(PathEditing, PlayStartsFromTheStartWhenThePlayheadIsOutsideThePath) {
    Document doc = threeKeyDocument();
    PathPlayback playback;
    playback.time = 2.8;  // scrubbed past the end
    playback.play(doc.cameraPath);
    EXPECT_DOUBLE_EQ(playback.time, 0.0);
    playback.time = -0.5;
    playback.play(doc.cameraPath);
    EXPECT_DOUBLE_EQ(playback.time, 0.0);
    FlyCamera camera;
    EXPECT_EQ(runPathCommand(doc, playback, camera, "play", {"0.5"}), "");
    EXPECT_FLOAT_EQ(playback.speed, 0.5f);
    EXPECT_NE(runPathCommand(doc, playback, camera, "play", {"9"}), "");
    EXPECT_EQ(runPathCommand(doc, playback, camera, "duration", {"4"}), "");
    EXPECT_FLOAT_EQ(doc.cameraPath.duration(), 4.0f);
    EXPECT_NE(runPathCommand(doc, playback, camera, "duration", {"-1"}), "");
}

}  // namespace
