// Node animations: the sampler against hand-computed values for each glTF interpolation, clamping
// outside the keys and unit rotations; applyNodeAnimations on a small hand-made scene (pose, not
// rest transform; world transforms and revisions; camera nodes left to the camera path); and the
// Blender scene tests/data/blender/animated (tools/blender/make_animated_scene.py) posed at a
// time, saved there and reloaded the same.

#include <gtest/gtest.h>

#include "TempDir.h"

#include "Log.h"
#include "animation/AnimationSampler.h"
#include "animation/NodeAnimation.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/Scene.h"
#include "QuietLog.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace lit {
namespace {

constexpr float kTolerance = 1e-5f;
const float kSin45 = std::sqrt(0.5f);

using lit::testing::QuietLog;

void expectNear(glm::vec4 actual, glm::vec4 expected) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], kTolerance) << "component " << i;
}
void expectNear(glm::quat actual, glm::quat expected) {
    // q and −q are one rotation: compare with the sign that agrees.
    if (glm::dot(actual, expected) < 0.0f) expected = -expected;
    expectNear(glm::vec4(actual.x, actual.y, actual.z, actual.w), glm::vec4(expected.x, expected.y, expected.z, expected.w));
}

TEST(AnimationSampler, ParsesGltfInterpolationNames) {
    EXPECT_EQ(parseInterpolation("STEP"), Interpolation::Step);
    EXPECT_EQ(parseInterpolation("LINEAR"), Interpolation::Linear);
    EXPECT_EQ(parseInterpolation("CUBICSPLINE"), Interpolation::CubicSpline);
    EXPECT_FALSE(parseInterpolation("linear"));
    EXPECT_FALSE(parseInterpolation(""));
}

TEST(AnimationSampler, LinearInterpolatesAndClampsOutsideTheKeys) {
    const std::vector<float> times{1.0f, 3.0f};
    const std::vector<float> values{0.0f, 0.0f, 0.0f, 2.0f, 4.0f, -6.0f};
    const AnimationSampler sampler(times, values, 3, Interpolation::Linear);
    expectNear(sampler.sample(2.0), {1.0f, 2.0f, -3.0f, 0.0f});   // halfway
    expectNear(sampler.sample(1.5), {0.5f, 1.0f, -1.5f, 0.0f});   // a quarter
    expectNear(sampler.sample(0.0), {0.0f, 0.0f, 0.0f, 0.0f});    // before the first key: the first value
    expectNear(sampler.sample(-5.0), {0.0f, 0.0f, 0.0f, 0.0f});
    expectNear(sampler.sample(3.0), {2.0f, 4.0f, -6.0f, 0.0f});
    expectNear(sampler.sample(10.0), {2.0f, 4.0f, -6.0f, 0.0f});  // after the last key: the last value
    EXPECT_EQ(sampler.startTime(), 1.0f);
    EXPECT_EQ(sampler.endTime(), 3.0f);
}

TEST(AnimationSampler, StepHoldsEachKeyUntilTheNext) {
    const std::vector<float> times{0.0f, 1.0f, 2.0f};
    const std::vector<float> values{1, 1, 1, 2, 2, 2, 3, 3, 3};
    const AnimationSampler sampler(times, values, 3, Interpolation::Step);
    expectNear(sampler.sample(0.5), {1, 1, 1, 0});
    expectNear(sampler.sample(0.999), {1, 1, 1, 0});
    expectNear(sampler.sample(1.0), {2, 2, 2, 0});  // a key's own time shows that key
    expectNear(sampler.sample(1.9), {2, 2, 2, 0});
    expectNear(sampler.sample(2.5), {3, 3, 3, 0});
    expectNear(sampler.sample(-1.0), {1, 1, 1, 0});
}

TEST(AnimationSampler, CubicSplineScalesTheTangentsByTheKeyInterval) {
    // One component, two keys 2 s apart, each (in-tangent, value, out-tangent):
    // key 0 (0, 0, 3), key 1 (−1, 1, 0). With td = 2:
    // p(s) = (2s³ − 3s² + 1)·0 + 2(s³ − 2s² + s)·3 + (−2s³ + 3s²)·1 + 2(s³ − s²)·(−1)
    //   s = 0.5:  0 + 2·0.125·3 + 0.5 + 2·(−0.125)·(−1) = 0.75 + 0.5 + 0.25 = 1.5
    //   s = 0.25: 2·0.140625·3 + 0.15625 + 2·(−0.046875)·(−1) = 0.84375 + 0.15625 + 0.09375 = 1.09375
    // (tangents not scaled by td would give 1.0 at s = 0.5).
    const std::vector<float> times{0.0f, 2.0f};
    const std::vector<float> values{0.0f, 0.0f, 3.0f, -1.0f, 1.0f, 0.0f};
    const AnimationSampler sampler(times, values, 1, Interpolation::CubicSpline);
    EXPECT_NEAR(sampler.sample(1.0).x, 1.5f, kTolerance);
    EXPECT_NEAR(sampler.sample(0.5).x, 1.09375f, kTolerance);
    EXPECT_NEAR(sampler.sample(0.0).x, 0.0f, kTolerance);  // the keys' values, not their tangents
    EXPECT_NEAR(sampler.sample(2.0).x, 1.0f, kTolerance);
    EXPECT_NEAR(sampler.sample(-1.0).x, 0.0f, kTolerance);
    EXPECT_NEAR(sampler.sample(9.0).x, 1.0f, kTolerance);
}

TEST(AnimationSampler, LinearRotationsSlerpAlongTheShorterArc) {
    // Identity to 90° about +Y; a quarter of the way is 22.5° (a normalised lerp gives 21.6°).
    const std::vector<float> times{0.0f, 1.0f};
    const std::vector<float> values{0, 0, 0, 1, 0, kSin45, 0, kSin45};
    const AnimationSampler sampler(times, values, 4, Interpolation::Linear);
    const float half = glm::radians(22.5f) / 2.0f;
    expectNear(sampler.sampleRotation(0.25), glm::quat(std::cos(half), 0.0f, std::sin(half), 0.0f));
    // The second key stored negated (the same rotation): still the short way, the same pose.
    const std::vector<float> negated{0, 0, 0, 1, 0, -kSin45, 0, -kSin45};
    const AnimationSampler flipped(times, negated, 4, Interpolation::Linear);
    expectNear(flipped.sampleRotation(0.25), glm::quat(std::cos(half), 0.0f, std::sin(half), 0.0f));
    expectNear(sampler.sampleRotation(-1.0), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    expectNear(sampler.sampleRotation(2.0), glm::quat(kSin45, 0.0f, kSin45, 0.0f));
}

TEST(AnimationSampler, RotationsComeOutUnitLength) {
    // Keys of length 2 and a cubic spline between them: neither is a unit quaternion as stored.
    const std::vector<float> times{0.0f, 1.0f};
    const std::vector<float> linear{0, 0, 0, 2, 0, 2 * kSin45, 0, 2 * kSin45};
    const AnimationSampler a(times, linear, 4, Interpolation::Linear);
    for (double t : {-1.0, 0.0, 0.3, 0.7, 1.0, 2.0}) EXPECT_NEAR(glm::length(a.sampleRotation(t)), 1.0f, kTolerance);
    expectNear(a.sampleRotation(0.0), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    const std::vector<float> cubic{0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0,  // key 0: in, value (identity), out
                                   0, 1, 0, 0, 0, kSin45, 0, kSin45, 0, 0, 0, 0};
    const AnimationSampler c(times, cubic, 4, Interpolation::CubicSpline);
    for (double t : {0.1, 0.5, 0.9}) EXPECT_NEAR(glm::length(c.sampleRotation(t)), 1.0f, kTolerance);
    expectNear(c.sampleRotation(1.0), glm::quat(kSin45, 0.0f, kSin45, 0.0f));
}

TEST(AnimationSampler, OneKeyHoldsItsValue) {
    const std::vector<float> times{0.5f};
    const std::vector<float> values{7.0f, 8.0f, 9.0f};
    const AnimationSampler sampler(times, values, 3, Interpolation::Linear);
    expectNear(sampler.sample(0.0), {7, 8, 9, 0});
    expectNear(sampler.sample(3.0), {7, 8, 9, 0});
}

TEST(AnimationSampler, RejectsDataThatDoesNotMatchTheKeys) {
    const std::vector<float> times{0.0f, 1.0f};
    const std::vector<float> three{0, 0, 0, 1, 1, 1};
    EXPECT_THROW(AnimationSampler(times, three, 3, Interpolation::CubicSpline), std::invalid_argument);  // needs 18
    EXPECT_THROW(AnimationSampler(times, three, 4, Interpolation::Linear), std::invalid_argument);
    EXPECT_THROW(AnimationSampler({}, {}, 3, Interpolation::Linear), std::invalid_argument);
    EXPECT_THROW(AnimationSampler(times, three, 5, Interpolation::Linear), std::invalid_argument);
}

// A parent that slides +X by 2 m over 2 s with a child 1 m above it, and a camera node with its
// own (camera path) animation.
Scene slidingScene() {
    Scene scene;
    scene.nodes.resize(3);
    scene.nodes[0].name = "parent";
    scene.nodes[0].translation = {5.0f, 0.0f, 0.0f};  // rest pose, not on the animation's keys
    scene.nodes[0].children = {1};
    scene.nodes[1].name = "child";
    scene.nodes[1].parent = 0;
    scene.nodes[1].translation = {0.0f, 1.0f, 0.0f};
    scene.nodes[2].name = "camera";
    scene.nodes[2].camera = 0;
    scene.cameras.resize(1);
    scene.roots = {0, 2};
    Animation animation;
    animation.name = "slide";
    Animation::Sampler sampler;
    sampler.input = {0.0f, 2.0f};
    sampler.output = {0, 0, 0, 2, 0, 0};
    animation.samplers.push_back(sampler);
    animation.channels.push_back({0, 0, "translation"});
    Animation::Sampler cameraSampler = sampler;
    cameraSampler.input = {0.0f, 4.0f};
    animation.samplers.push_back(cameraSampler);
    animation.channels.push_back({1, 2, "translation"});
    scene.animations.push_back(animation);
    scene.updateWorldTransforms();
    return scene;
}

TEST(NodeAnimation, PosesNodesWithoutTouchingTheRestTransform) {
    Scene scene = slidingScene();
    const std::uint64_t geometry = scene.geometryRevision;
    EXPECT_TRUE(applyNodeAnimations(scene, 1.0));
    EXPECT_EQ(scene.nodes[0].translation, glm::vec3(5.0f, 0.0f, 0.0f));  // the rest pose stays
    ASSERT_TRUE(scene.nodes[0].pose.translation);
    EXPECT_NEAR(scene.nodes[0].pose.translation->x, 1.0f, kTolerance);
    EXPECT_FALSE(scene.nodes[0].pose.rotation);  // not animated: the rest rotation shows
    EXPECT_NEAR(scene.nodes[1].world[3].x, 1.0f, kTolerance);  // the child follows
    EXPECT_NEAR(scene.nodes[1].world[3].y, 1.0f, kTolerance);
    EXPECT_GT(scene.geometryRevision, geometry);
    // The camera node's animation is its camera path's, not a node animation.
    EXPECT_TRUE(scene.nodes[2].pose.empty());
    EXPECT_EQ(scene.nodes[2].world[3], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));

    const std::uint64_t after = scene.geometryRevision;
    EXPECT_FALSE(applyNodeAnimations(scene, 1.0));  // the same time again: nothing to redo
    EXPECT_EQ(scene.geometryRevision, after);
    EXPECT_TRUE(applyNodeAnimations(scene, 7.0));  // past the end: the last key
    EXPECT_NEAR(scene.nodes[1].world[3].x, 2.0f, kTolerance);

    const NodeAnimationSummary summary = summarizeNodeAnimations(scene);
    EXPECT_EQ(summary.channels, 1);
    EXPECT_EQ(summary.nodes, 1);
    EXPECT_DOUBLE_EQ(summary.endTime, 2.0);  // the camera's 4 s key is the camera path's
}

TEST(NodeAnimation, ClearsThePoseOfNodesNoLongerAnimated) {
    Scene scene = slidingScene();
    applyNodeAnimations(scene, 1.0);
    scene.animations.clear();
    EXPECT_TRUE(applyNodeAnimations(scene, 1.0));
    EXPECT_TRUE(scene.nodes[0].pose.empty());
    EXPECT_NEAR(scene.nodes[1].world[3].x, 5.0f, kTolerance);  // back at the rest pose
}

TEST(NodeAnimation, ListsChannelsItCannotPlay) {
    Scene scene = slidingScene();
    scene.animations[0].samplers[0].output.pop_back();  // 5 values for 2 keys of 3
    scene.animations[0].samplers[1].interpolation = "BEZIER";  // a camera node's: not a node animation
    const std::vector<std::string> problems = nodeAnimationProblems(scene);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("animation 'slide' channel 0"), std::string::npos) << problems[0];
    EXPECT_EQ(summarizeNodeAnimations(scene).channels, 0);
    EXPECT_FALSE(applyNodeAnimations(scene, 1.0));
}

const char* const kAnimatedScene = LIT_SOURCE_DIR "/tests/data/blender/animated/animated.gltf";

int nodeNamed(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].name == name) return static_cast<int>(i);
    ADD_FAILURE() << "no node " << name;
    return 0;
}

TEST(NodeAnimation, PlaysTheBlenderScene) {
    QuietLog log;
    Scene scene = loadGltf(kAnimatedScene, log);
    const NodeAnimationSummary summary = summarizeNodeAnimations(scene);
    EXPECT_EQ(summary.channels, 2);  // the box's translation, the door's rotation
    EXPECT_NEAR(summary.endTime, 2.0, 1e-4);
    EXPECT_TRUE(nodeAnimationProblems(scene).empty());
    applyNodeAnimations(scene, 1.0);
    const Node& box = scene.nodes[static_cast<std::size_t>(nodeNamed(scene, "box"))];
    const Node& door = scene.nodes[static_cast<std::size_t>(nodeNamed(scene, "door"))];
    // Keyed linearly: the box halfway from x −1.5 to +1.5, the door halfway to 90° about +Y.
    EXPECT_NEAR(box.world[3].x, 0.0f, 1e-4f);
    EXPECT_NEAR(box.world[3].y, 0.3f, 1e-4f);
    EXPECT_NEAR(box.world[3].z, 0.0f, 1e-4f);
    const float half = glm::radians(45.0f) / 2.0f;
    expectNear(*door.pose.rotation, glm::quat(std::cos(half), 0.0f, std::sin(half), 0.0f));
    // The door's free edge (1 m along its local +X) has swung from +X towards −Z.
    const glm::vec3 edge = glm::vec3(door.world * glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(edge.x, -2.5f + kSin45, 1e-4f);
    EXPECT_NEAR(edge.z, -1.5f - kSin45, 1e-4f);
}

TEST(NodeAnimation, SavingAtATimeWritesTheRestPose) {
    QuietLog log;
    const Scene original = loadGltf(kAnimatedScene, log);
    Scene posed = original;
    applyNodeAnimations(posed, 1.3);
    lit::testing::TempDir dir("lit_node_animation");
    const auto file = dir.path() / "saved.gltf";
    saveGltf(posed, file);
    Scene reloaded = loadGltf(file, log);
    ASSERT_EQ(reloaded.nodes.size(), original.nodes.size());
    for (std::size_t i = 0; i < original.nodes.size(); ++i) {
        SCOPED_TRACE(original.nodes[i].name);
        EXPECT_EQ(reloaded.nodes[i].translation, original.nodes[i].translation);
        EXPECT_EQ(reloaded.nodes[i].rotation, original.nodes[i].rotation);
        EXPECT_EQ(reloaded.nodes[i].scale, original.nodes[i].scale);
        EXPECT_TRUE(reloaded.nodes[i].pose.empty());
    }
    ASSERT_EQ(reloaded.animations.size(), original.animations.size());
    for (std::size_t a = 0; a < original.animations.size(); ++a) {
        ASSERT_EQ(reloaded.animations[a].samplers.size(), original.animations[a].samplers.size());
        for (std::size_t s = 0; s < original.animations[a].samplers.size(); ++s) {
            EXPECT_EQ(reloaded.animations[a].samplers[s].input, original.animations[a].samplers[s].input);
            EXPECT_EQ(reloaded.animations[a].samplers[s].output, original.animations[a].samplers[s].output);
            EXPECT_EQ(reloaded.animations[a].samplers[s].interpolation, original.animations[a].samplers[s].interpolation);
        }
        EXPECT_EQ(reloaded.animations[a].channels, original.animations[a].channels);
    }
    // And it plays the same: posed at 1.3 s again, every node is where the saved scene had it.
    applyNodeAnimations(reloaded, 1.3);
    for (std::size_t i = 0; i < original.nodes.size(); ++i) EXPECT_EQ(reloaded.nodes[i].world, posed.nodes[i].world);
}

}  // namespace
}  // namespace lit
