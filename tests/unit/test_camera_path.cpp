// Camera path model (renderer/animation/CameraPath.cpp): interpolation through the keys, C1
// continuity, constant speed, shorter-arc rotation, loops, still cameras and bad keys.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "animation/CameraPath.h"

namespace lit {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::quat yawPitch(float yawDegrees, float pitchDegrees = 0.0f) {
    return glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
           glm::angleAxis(glm::radians(pitchDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
}

CameraKey key(float time, glm::vec3 position, glm::quat rotation = {1.0f, 0.0f, 0.0f, 0.0f}, float yfov = 0.8f) {
    return CameraKey{time, position, rotation, yfov};
}

// Uneven in time and in space, turning and zooming: the general case.
std::vector<CameraKey> wigglyKeys() {
    return {key(0.0f, {0.0f, 1.0f, 5.0f}, yawPitch(0.0f), 0.8f),
            key(0.7f, {1.0f, 1.2f, 4.0f}, yawPitch(20.0f, -5.0f), 0.7f),
            key(2.5f, {4.0f, 2.0f, 0.5f}, yawPitch(75.0f, -15.0f), 0.9f),
            key(3.0f, {3.5f, 1.5f, -1.0f}, yawPitch(110.0f, 0.0f), 0.6f),
            key(5.0f, {0.0f, 1.0f, -3.0f}, yawPitch(170.0f, 10.0f), 0.75f)};
}

CameraPose at(const CameraPath& path, double t) {
    const std::optional<CameraPose> pose = path.evaluate(t);
    EXPECT_TRUE(pose.has_value());
    return pose.value_or(CameraPose{});
}

// Angle between two rotations in radians, ignoring the quaternion sign.
float angleBetween(const glm::quat& a, const glm::quat& b) {
    const float d = std::min(1.0f, std::abs(glm::dot(glm::normalize(a), glm::normalize(b))));
    return 2.0f * std::acos(d);
}

// Second-order one-sided finite differences (error O(h²)): velocity arriving at t and leaving t.
glm::dvec3 velocityBefore(const CameraPath& path, double t, double h) {
    return (3.0 * glm::dvec3(at(path, t).position) - 4.0 * glm::dvec3(at(path, t - h).position) +
            glm::dvec3(at(path, t - 2 * h).position)) /
           (2 * h);
}
glm::dvec3 velocityAfter(const CameraPath& path, double t, double h) {
    return (-3.0 * glm::dvec3(at(path, t).position) + 4.0 * glm::dvec3(at(path, t + h).position) -
            glm::dvec3(at(path, t + 2 * h).position)) /
           (2 * h);
}

// Body-frame angular velocity (rad/s) over [t0, t1].
glm::dvec3 angularVelocity(const CameraPath& path, double t0, double t1) {
    glm::dquat r = glm::conjugate(glm::dquat(at(path, t0).rotation)) * glm::dquat(at(path, t1).rotation);
    if (r.w < 0.0) r = -r;
    const glm::dvec3 v(r.x, r.y, r.z);
    const double s = glm::length(v);
    return s > 0.0 ? v * (2.0 * std::atan2(s, r.w) / s / (t1 - t0)) : glm::dvec3(0.0);
}

// Lengths of the steps between `samples` poses at uniform times over the whole path.
std::vector<double> stepLengths(const CameraPath& path, int samples) {
    std::vector<double> lengths;
    const double start = path.startTime(), length = path.duration();
    glm::dvec3 previous = at(path, start).position;
    for (int i = 1; i <= samples; ++i) {
        const glm::dvec3 p = at(path, start + length * i / samples).position;
        lengths.push_back(glm::length(p - previous));
        previous = p;
    }
    return lengths;
}

double spread(const std::vector<double>& values) {
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return *hi / *lo;
}

std::string errorOf(const std::vector<CameraKey>& keys) {
    try {
        CameraPath path(keys);
    } catch (const CameraPathError& e) {
        return e.what();
    }
    return "";
}

TEST(CameraPath, EmptyPathIsNoPath) {
    const CameraPath path;
    EXPECT_TRUE(path.empty());
    EXPECT_FALSE(path.evaluate(0.0).has_value());
    EXPECT_FALSE(path.view(0.0, 1.0f, Aabb{}).has_value());
    EXPECT_TRUE(path.frameTimes(30.0).empty());
    EXPECT_EQ(path.duration(), 0.0f);
    // Options on an empty path change nothing.
    CameraPath looped({}, {true, true, true});
    EXPECT_FALSE(looped.evaluate(1.0).has_value());
}

TEST(CameraPath, OneKeyIsAStillCamera) {
    const CameraKey only = key(2.0f, {1.0f, 2.0f, 3.0f}, yawPitch(30.0f, -10.0f), 0.6f);
    for (const CameraPathOptions options : {CameraPathOptions{}, CameraPathOptions{true, true, true}}) {
        const CameraPath path({only}, options);
        for (const double t : {-10.0, 0.0, 2.0, 2.5, 1e6}) {
            const CameraPose pose = at(path, t);
            EXPECT_EQ(pose.position, only.position);
            EXPECT_LT(angleBetween(pose.rotation, only.rotation), 1e-6f);
            EXPECT_EQ(pose.yfov, only.yfov);
        }
        EXPECT_EQ(path.frameTimes(30.0), std::vector<double>{2.0});
        EXPECT_EQ(path.duration(), 0.0f);
    }
}

TEST(CameraPath, PassesThroughEveryKey) {
    for (const bool loop : {false, true}) {
        const CameraPath path(wigglyKeys(), {loop, false, false});
        for (const CameraKey& k : path.keys()) {
            const CameraPose pose = at(path, k.time);
            EXPECT_NEAR(glm::length(pose.position - k.position), 0.0f, 1e-5f) << "key at " << k.time;
            EXPECT_LT(angleBetween(pose.rotation, k.rotation), 1e-3f) << "key at " << k.time;  // 0.06°
            EXPECT_NEAR(pose.yfov, k.yfov, 1e-6f) << "key at " << k.time;
        }
    }
}

TEST(CameraPath, ClampsOutsideTheKeysOfAnOpenPath) {
    const CameraPath path(wigglyKeys());
    const CameraKey& first = path.keys().front();
    const CameraKey& last = path.keys().back();
    EXPECT_NEAR(glm::length(at(path, -3.0).position - first.position), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(at(path, 99.0).position - last.position), 0.0f, 1e-5f);
    EXPECT_LT(angleBetween(at(path, 99.0).rotation, last.rotation), 1e-3f);
    EXPECT_EQ(path.startTime(), 0.0f);
    EXPECT_EQ(path.endTime(), 5.0f);
}

// Velocities from both sides of each interior key agree; the tolerance (0.5 % of the speed,
// from finite-difference and float rounding error) is far below the change of velocity across a
// segment, so a C0-only spline (a kink at the key) would fail.
TEST(CameraPath, PositionIsC1AtKeys) {
    const CameraPath path(wigglyKeys());
    const double h = 1e-3;
    for (std::size_t i = 1; i + 1 < path.keys().size(); ++i) {
        const double t = path.keys()[i].time;
        const glm::dvec3 before = velocityBefore(path, t, h);
        const glm::dvec3 after = velocityAfter(path, t, h);
        const double speed = glm::length(after);
        EXPECT_GT(speed, 0.1) << "key " << i;
        EXPECT_LT(glm::length(before - after), 5e-3 * speed + 1e-3) << "key " << i << " speed " << speed;
        // The velocity does change over the neighbouring segment: the test could see a kink.
        EXPECT_GT(glm::length(velocityAfter(path, t + 0.2, h) - after), 0.05 * speed) << "key " << i;
    }
}

TEST(CameraPath, RotationAndFovAreC1AtKeys) {
    const CameraPath path(wigglyKeys());
    const double h = 1e-4;
    for (std::size_t i = 1; i + 1 < path.keys().size(); ++i) {
        const double t = path.keys()[i].time;
        const glm::dvec3 before = angularVelocity(path, t - h, t);
        const glm::dvec3 after = angularVelocity(path, t, t + h);
        EXPECT_LT(glm::length(before - after), 0.01 * glm::length(after) + 5e-3) << "key " << i;
        const double fovBefore = (at(path, t).yfov - at(path, t - h).yfov) / h;
        const double fovAfter = (at(path, t + h).yfov - at(path, t).yfov) / h;
        EXPECT_NEAR(fovBefore, fovAfter, 0.01 * std::abs(fovAfter) + 5e-3) << "key " << i;
    }
}

TEST(CameraPath, ShorterArcFrom350To10DegreesOfYaw) {
    const CameraPath path(
        {key(0.0f, {0.0f, 0.0f, 0.0f}, yawPitch(350.0f)), key(2.0f, {1.0f, 0.0f, 0.0f}, yawPitch(10.0f))});
    // Halfway the camera looks straight down −Z (yaw 0°), not backwards (yaw 180°).
    const glm::vec3 forward = at(path, 1.0).rotation * glm::vec3(0.0f, 0.0f, -1.0f);
    EXPECT_NEAR(forward.z, -1.0f, 1e-4f);
    EXPECT_LT(angleBetween(at(path, 1.0).rotation, glm::quat(1.0f, 0.0f, 0.0f, 0.0f)), glm::radians(0.1f));
    // And it never swings further than the keys on the way.
    for (int i = 0; i <= 40; ++i)
        EXPECT_LE(angleBetween(at(path, i * 0.05).rotation, glm::quat(1.0f, 0.0f, 0.0f, 0.0f)), glm::radians(10.01f));
}

TEST(CameraPath, ShorterArcHoldsWhenKeysComeWithOppositeSigns) {
    // q and −q are the same rotation; a file may hold either.
    const glm::quat a = yawPitch(40.0f), b = -yawPitch(60.0f), c = yawPitch(80.0f);
    const CameraPath path({key(0.0f, {0, 0, 0}, a), key(1.0f, {1, 0, 0}, b), key(2.0f, {2, 0, 0}, c)});
    for (int i = 0; i <= 40; ++i) {
        const float angle = angleBetween(at(path, i * 0.05).rotation, yawPitch(40.0f + 20.0f * float(i) * 0.05f));
        EXPECT_LT(angle, glm::radians(1.0f)) << "t = " << i * 0.05;
    }
}

TEST(CameraPath, ConstantSpeedIsEvenWhateverTheKeySpacing) {
    // Key distances 0.1 m, 5.1 m, 0.54 m, 4.7 m, one second apart.
    const std::vector<CameraKey> keys = {key(0.0f, {0.0f, 0.0f, 0.0f}), key(1.0f, {0.1f, 0.0f, 0.0f}),
                                         key(2.0f, {5.0f, 0.0f, 1.0f}), key(3.0f, {5.5f, 0.0f, 1.2f}),
                                         key(4.0f, {10.0f, 0.5f, 0.0f})};
    const CameraPath keyed(keys);
    const CameraPath even(keys, {false, true, false});
    const double keyedSpread = spread(stepLengths(keyed, 200));
    const double evenSpread = spread(stepLengths(even, 200));
    EXPECT_GT(keyedSpread, 5.0);  // the test has teeth: by key times the speed varies a lot
    EXPECT_LT(evenSpread, 1.05);
    // Same ends, same duration.
    EXPECT_NEAR(glm::length(at(even, 0.0).position - keys.front().position), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(at(even, 4.0).position - keys.back().position), 0.0f, 1e-5f);
}

TEST(CameraPath, ConstantSpeedOrientationFollowsThePosition) {
    // Where the constant-speed camera passes key 2's position it has key 2's orientation.
    std::vector<CameraKey> keys = wigglyKeys();
    const CameraPath even(keys, {false, true, false});
    double bestT = 0.0, bestDistance = 1e9;
    for (int i = 0; i <= 20000; ++i) {
        const double t = 5.0 * i / 20000.0;
        const double d = glm::length(at(even, t).position - keys[2].position);
        if (d < bestDistance) bestDistance = d, bestT = t;
    }
    EXPECT_LT(bestDistance, 2e-3);
    EXPECT_LT(angleBetween(at(even, bestT).rotation, keys[2].rotation), glm::radians(0.5f));
    EXPECT_NEAR(at(even, bestT).yfov, keys[2].yfov, 2e-3f);
}

TEST(CameraPath, ConstantSpeedKeepsAStillKeyTurningSmoothly) {
    // Keys 1 and 2 share a position: the camera pauses there and turns 90° in the keyed second.
    const std::vector<CameraKey> keys = {key(0.0f, {0, 0, 0}, yawPitch(0.0f)), key(1.0f, {2, 0, 0}, yawPitch(0.0f)),
                                         key(2.0f, {2, 0, 0}, yawPitch(90.0f)), key(3.0f, {2, 0, -3}, yawPitch(90.0f))};
    const CameraPath even(keys, {false, true, false});
    float largestTurn = 0.0f;
    for (int i = 1; i <= 300; ++i)
        largestTurn =
            std::max(largestTurn, angleBetween(at(even, (i - 1) / 100.0).rotation, at(even, i / 100.0).rotation));
    // 90° over ~1 s in 10 ms steps is ~0.9° a step on average; a jump would be tens of degrees.
    EXPECT_LT(largestTurn, glm::radians(3.0f));
}

TEST(CameraPath, EaseInOutStartsAndStopsAtRest) {
    const std::vector<CameraKey> keys = {key(0.0f, {0, 0, 0}), key(2.0f, {4, 0, 0}), key(4.0f, {8, 0, 0})};
    for (const bool constantSpeed : {false, true}) {
        const CameraPath eased(keys, {false, constantSpeed, true});
        const double h = 1e-3;
        EXPECT_LT(glm::length(velocityAfter(eased, 0.0, h)), 0.05) << constantSpeed;
        EXPECT_LT(glm::length(velocityBefore(eased, 4.0, h)), 0.05) << constantSpeed;
        EXPECT_GT(glm::length(velocityAfter(eased, 2.0, h)), 1.0) << constantSpeed;
        EXPECT_NEAR(glm::length(at(eased, 0.0).position - keys.front().position), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(at(eased, 4.0).position - keys.back().position), 0.0f, 1e-5f);
        // Speed stays continuous through the ramps (no kink in the time warp).
        for (const double t : {1.0, 3.0})
            EXPECT_LT(glm::length(velocityBefore(eased, t, h) - velocityAfter(eased, t, h)), 0.02);
    }
}

TEST(CameraPath, LoopClosesSmoothly) {
    // Four keys on a circle of radius 2, one second apart: the loop adds a closing second.
    std::vector<CameraKey> keys;
    for (int i = 0; i < 4; ++i) {
        const float a = float(i) * kPi / 2.0f;
        keys.push_back(key(float(i), {2.0f * std::cos(a), 1.0f, 2.0f * std::sin(a)}, yawPitch(-90.0f * float(i)),
                           0.7f + 0.05f * float(i)));
    }
    for (const bool constantSpeed : {false, true}) {
        const CameraPath loop(keys, {true, constantSpeed, false});
        EXPECT_FLOAT_EQ(loop.duration(), 4.0f);
        const double end = loop.endTime();
        // Wrapping: one period later is the same pose; beyond the end it wraps, not clamps.
        EXPECT_NEAR(glm::length(at(loop, 0.3).position - at(loop, 4.3).position), 0.0f, 1e-4f);
        EXPECT_NEAR(glm::length(at(loop, -0.5).position - at(loop, 3.5).position), 0.0f, 1e-4f);
        // Across the seam: position, velocity, rotation and fov continuous.
        const double h = 1e-3;
        const glm::dvec3 before = velocityBefore(loop, end - 1e-9, h);
        const glm::dvec3 after = velocityAfter(loop, end, h);
        EXPECT_GT(glm::length(after), 1.0);
        EXPECT_LT(glm::length(before - after), 0.02 * glm::length(after)) << "constantSpeed " << constantSpeed;
        EXPECT_LT(glm::length(at(loop, end - 1e-4).position - at(loop, end).position), 1e-3f);
        EXPECT_LT(angleBetween(at(loop, end - 1e-4).rotation, at(loop, end).rotation), 1e-3f);
        EXPECT_NEAR(at(loop, end - 1e-4).yfov, at(loop, end).yfov, 1e-3f);
        // The circle stays a circle-ish: no overshoot far outside radius 2.
        for (int i = 0; i < 80; ++i) {
            const glm::vec3 p = at(loop, i * 0.05).position;
            EXPECT_NEAR(std::hypot(p.x, p.z), 2.0f, 0.25f) << "t = " << i * 0.05;
        }
    }
}

TEST(CameraPath, LoopWhoseLastKeyRepeatsTheFirstClosesThere) {
    const std::vector<CameraKey> keys = {key(0.0f, {0, 0, 0}), key(1.0f, {1, 0, 0}), key(2.0f, {1, 0, 1}),
                                         key(5.0f, {0, 0, 0})};
    const CameraPath loop(keys, {true, false, false});
    EXPECT_FLOAT_EQ(loop.endTime(), 5.0f);
    EXPECT_NEAR(glm::length(at(loop, 5.0).position), 0.0f, 1e-5f);
    // The repeat is a seam, not a stop: the camera keeps moving through it.
    EXPECT_GT(glm::length(velocityAfter(loop, 0.0, 1e-3)), 0.1);
    EXPECT_LT(glm::length(velocityBefore(loop, 5.0 - 1e-9, 1e-3) - velocityAfter(loop, 0.0, 1e-3)), 0.01);
}

TEST(CameraPath, FrameTimes) {
    const CameraPath path({key(1.0f, {0, 0, 0}), key(4.0f, {1, 0, 0})});
    const std::vector<double> times = path.frameTimes(30.0);
    ASSERT_EQ(times.size(), 91u);  // 3 s at 30 fps, both ends included
    EXPECT_DOUBLE_EQ(times.front(), 1.0);
    EXPECT_NEAR(times.back(), 4.0, 1e-9);
    EXPECT_EQ(path.frameTimes(2.5).size(), 8u);                // 0, 0.4, ... 2.8 s
    const CameraPath loop(path.keys(), {true, false, false});  // 6 s: the closing segment takes 3 s
    EXPECT_EQ(loop.frameTimes(10.0).size(), 60u);              // the seam frame is the first frame again
    EXPECT_THROW(path.frameTimes(0.0), std::invalid_argument);
    EXPECT_THROW(path.frameTimes(std::nan("")), std::invalid_argument);
    EXPECT_THROW(path.frameTimes(1e9), std::invalid_argument);
}

TEST(CameraPath, ViewLooksDownTheKeyedDirection) {
    const CameraPath path({key(0.0f, {0.0f, 1.0f, 3.4f}, yawPitch(0.0f), 0.69f)});
    Aabb box;
    box.extend(glm::vec3(-1.0f, 0.0f, -1.0f));
    box.extend(glm::vec3(1.0f, 2.0f, 1.0f));
    const CameraView view = path.view(0.0, 1.5f, box).value();
    EXPECT_NEAR(glm::length(view.position - glm::vec3(0.0f, 1.0f, 3.4f)), 0.0f, 1e-6f);
    EXPECT_NEAR(view.forward().z, -1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(view.yfov, 0.69f);
    // The box's bounding sphere (centre 3.4 m ahead) fits between near and far.
    EXPECT_GT(view.zfar, 3.4f + box.radius());
    EXPECT_LT(view.znear, 3.4f - box.radius());
    EXPECT_GT(view.znear, 0.0f);
    const CameraView fixed = path.view(0.0, 1.0f, 0.1f, 50.0f).value();
    EXPECT_FLOAT_EQ(fixed.znear, 0.1f);
    EXPECT_FLOAT_EQ(fixed.zfar, 50.0f);
}

TEST(CameraPath, BadKeysAreRejectedWithTheirProblem) {
    const auto good = [] { return wigglyKeys(); };
    std::vector<CameraKey> keys = good();
    keys[3].time = 2.0f;
    keys[2].time = 2.5f;
    keys[3].time = 1.5f;
    EXPECT_EQ(errorOf(keys), "key 3: time 1.5 is not after key 2's time 2.5");
    keys = good();
    keys[1].time = 0.0f;
    EXPECT_EQ(errorOf(keys), "key 1: time 0 is not after key 0's time 0");
    keys = good();
    keys[2].position.y = std::nanf("");
    EXPECT_EQ(errorOf(keys), "key 2: position has a value that is not a finite number");
    keys = good();
    keys[0].time = INFINITY;
    EXPECT_EQ(errorOf(keys), "key 0: time is not a finite number");
    keys = good();
    keys[4].rotation = glm::quat(0.5f, 0.0f, 0.0f, 0.0f);
    EXPECT_EQ(errorOf(keys), "key 4: rotation [0, 0, 0, 0.5] is not a unit quaternion (length 0.5)");
    keys = good();
    keys[1].rotation.x = std::nanf("");
    EXPECT_EQ(errorOf(keys), "key 1: rotation has a value that is not a finite number");
    keys = good();
    keys[1].yfov = 0.0f;
    EXPECT_EQ(errorOf(keys), "key 1: yfov 0 is not between 0 and pi radians");
    keys = good();
    keys[1].yfov = 3.5f;
    EXPECT_EQ(errorOf(keys), "key 1: yfov 3.5 is not between 0 and pi radians");
    // Slightly unnormalized (as printed with few digits) is accepted and normalized.
    keys = good();
    keys[1].rotation = glm::quat(1.0005f, 0.0f, 0.0f, 0.0f);
    EXPECT_EQ(errorOf(keys), "");
    EXPECT_FLOAT_EQ(glm::length(CameraPath(keys).keys()[1].rotation), 1.0f);
}

TEST(CameraPath, EditsKeepTimeOrderAndFailWithoutChangingThePath) {
    CameraPath path({key(0.0f, {0, 0, 0}), key(2.0f, {2, 0, 0})});
    EXPECT_EQ(path.insertKey(key(1.0f, {1, 1, 0})), 1u);
    ASSERT_EQ(path.keys().size(), 3u);
    EXPECT_NEAR(glm::length(at(path, 1.0).position - glm::vec3(1, 1, 0)), 0.0f, 1e-6f);
    EXPECT_THROW(path.insertKey(key(2.0f, {5, 0, 0})), CameraPathError);
    EXPECT_THROW(path.setKey(0, key(3.0f, {0, 0, 0})), CameraPathError);  // would come after key 1
    EXPECT_THROW(path.removeKey(7), std::out_of_range);
    EXPECT_EQ(path.keys().size(), 3u);
    EXPECT_EQ(path.keys()[0].time, 0.0f);
    path.setKey(1, key(1.5f, {1, 0, 0}));
    EXPECT_EQ(path.keys()[1].time, 1.5f);
    path.removeKey(1);
    EXPECT_EQ(path.keys().size(), 2u);
    EXPECT_NEAR(glm::length(at(path, 1.0).position - glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace lit
