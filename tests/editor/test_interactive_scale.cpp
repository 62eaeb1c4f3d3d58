// InteractiveScale: the editor's render scale while the camera moves (docs/PERFORMANCE.md, "Editor").
#include <gtest/gtest.h>

#include "InteractiveScale.h"

namespace lit::editor {
namespace {

constexpr float kFps = 10.0f;  // RenderSettings::interactiveFpsTarget's default

// Feeds frames one after the other, each rendered; the clock advances by each frame's time.
class Frames {
public:
    float next(float full, bool interacting, float targetFps, double lastFrameSeconds) {
        now_ += lastFrameSeconds;
        return scale_.next({.full = full,
                            .interacting = interacting,
                            .targetFps = targetFps,
                            .now = now_,
                            .lastRenderSeconds = lastFrameSeconds,
                            .previousRendered = true});
    }
    // A frame that showed the last image again (redraw on demand) after `seconds`.
    float reused(float full, bool interacting, double seconds, double lastRenderSeconds) {
        now_ += seconds;
        return scale_.next({.full = full,
                            .interacting = interacting,
                            .targetFps = kFps,
                            .now = now_,
                            .lastRenderSeconds = lastRenderSeconds,
                            .previousRendered = false});
    }
    float current() const { return scale_.current(); }
    const InteractiveScale& scale() const { return scale_; }
    double now() const { return now_; }

private:
    InteractiveScale scale_;
    double now_ = 100.0;  // s
};

TEST(InteractiveScale, StillFramesRenderAtTheFullScale) {
    Frames s;
    EXPECT_FLOAT_EQ(s.next(1.0f, false, kFps, 2.0), 1.0f);
    EXPECT_FLOAT_EQ(s.next(0.5f, false, kFps, 2.0), 0.5f);
    // Off (target 0): full scale even while moving.
    EXPECT_FLOAT_EQ(s.next(1.0f, true, 0.0f, 2.0), 1.0f);
}

TEST(InteractiveScale, FirstMotionJumpsToTheScaleTheStillFramePredicts) {
    Frames s;
    s.next(1.0f, false, kFps, 2.0);
    // A 2 s still frame at scale 1: 0.1 s needs √(0.1/2) = 0.22 of the side, quantized to 0.2.
    // (The first version could only halve per frame: 0.5, then 0.25, ...)
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 2.0), 0.2f);
}

TEST(InteractiveScale, NextMotionStartsWhereTheLastOneEnded) {
    Frames s;
    s.next(1.0f, true, kFps, 2.0);           // 0.2
    s.next(1.0f, true, kFps, 0.3);           // too slow: √(0.1/0.3) = 0.58 → 0.2·0.58 = 0.115 → 0.1
    EXPECT_FLOAT_EQ(s.current(), 0.1f);
    s.next(1.0f, false, kFps, 0.1);  // stop: the grace period holds the scale
    s.next(1.0f, false, kFps, 2.5);  // ... for 0.3 s: then full scale
    // Moving again after a slow still frame: the last motion's scale, not one derived from the
    // still frame's time.
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 2.5), 0.1f);
}

TEST(InteractiveScale, FrameTimesNearTheTargetKeepTheScale) {
    Frames s;
    s.next(1.0f, true, kFps, 2.0);  // 0.2
    // Frames scattered 60–140 ms around 100 ms are noise on a loaded machine: no new scale
    // (each new scale reallocates the renderer's targets).
    for (double t : {0.08, 0.125, 0.11, 0.09, 0.14, 0.079, 0.06, 0.127, 0.1, 0.12})
        EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, t), 0.2f) << t;
}

TEST(InteractiveScale, FollowsTheMeanFrameTimeAtAScale) {
    Frames s;
    s.next(1.0f, true, kFps, 2.0);  // 0.2
    // Steadily too slow (180 ms): the first frame at a scale is not counted, three are.
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.18), 0.2f);
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.18), 0.2f);
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.18), 0.2f);
    // √(0.1/0.18) · 0.2 = 0.149 → 0.15.
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.18), 0.15f);
    // Steadily too fast (40 ms): up again, at most ×1.25 per change (0.1875 → 0.2).
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.04), 0.15f);
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.04), 0.2f);
}

TEST(InteractiveScale, OneFarTooSlowFrameLowersTheScaleAtOnce) {
    Frames s;
    s.next(1.0f, true, kFps, 0.5);  // first motion after a 0.5 s still frame: √0.2 = 0.45
    EXPECT_FLOAT_EQ(s.current(), 0.45f);
    // 1 s: √(0.1/1) = 0.32, at most ÷2 per change: 0.225 → 0.2 (0.225/0.05 = 4.4999...).
    const float next = s.next(1.0f, true, kFps, 1.0);
    EXPECT_TRUE(next == 0.2f || next == 0.25f) << next;
    EXPECT_LT(next, 0.45f);
}

TEST(InteractiveScale, NeverAboveTheChosenScaleNorBelowTheMinimum) {
    Frames s;
    s.next(0.3f, true, kFps, 0.001);
    for (int i = 0; i < 10; ++i) EXPECT_LE(s.next(0.3f, true, kFps, 0.001), 0.3f);
    for (int i = 0; i < 10; ++i) EXPECT_GE(s.next(0.3f, true, kFps, 100.0), InteractiveScale::kMinScale);
    EXPECT_FLOAT_EQ(s.current(), InteractiveScale::kMinScale);
}

TEST(InteractiveScale, HoldsTheScaleForAGracePeriodAfterTheMotionStops) {
    Frames s;
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 2.0), 0.2f);
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.1), 0.2f);
    // A mouse-look that pauses: the frames shortly after keep the scale (they show the last image
    // again: nothing changed), so the motion does not stutter through one full-size frame.
    EXPECT_FLOAT_EQ(s.next(1.0f, false, kFps, 0.1), 0.2f);
    EXPECT_TRUE(s.scale().holding(s.now()));
    EXPECT_NEAR(s.scale().graceLeft(s.now()), InteractiveScale::kGraceSeconds, 1e-9);
    EXPECT_FLOAT_EQ(s.reused(1.0f, false, 0.02, 0.1), 0.2f);
    EXPECT_FLOAT_EQ(s.reused(1.0f, false, 0.2, 0.1), 0.2f);
    EXPECT_NEAR(s.scale().graceLeft(s.now()), InteractiveScale::kGraceSeconds - 0.22, 1e-9);
    // The motion resumes within the grace period: at the scale it had.
    EXPECT_FLOAT_EQ(s.next(1.0f, true, kFps, 0.02), 0.2f);
    // It stops for good: full scale once the grace period has passed, and no longer held.
    EXPECT_FLOAT_EQ(s.next(1.0f, false, kFps, 0.1), 0.2f);
    EXPECT_FLOAT_EQ(s.reused(1.0f, false, InteractiveScale::kGraceSeconds - 0.01, 0.1), 0.2f);
    EXPECT_FLOAT_EQ(s.reused(1.0f, false, 0.02, 0.1), 1.0f);
    EXPECT_FALSE(s.scale().holding(s.now()));
    EXPECT_EQ(s.scale().graceLeft(s.now()), 0.0);
    // Off (target 0): no grace.
    Frames off;
    off.next(1.0f, true, kFps, 2.0);
    EXPECT_FLOAT_EQ(off.next(1.0f, false, 0.0f, 0.1), 1.0f);
}

TEST(InteractiveScale, FramesThatShowedTheLastImageAgainAreNotMeasured) {
    Frames s;
    s.next(1.0f, true, kFps, 2.0);  // 0.2
    // A value held without a change renders nothing: 5 ms frames say nothing about the cost of
    // a render at this scale, and would raise it.
    for (int i = 0; i < 10; ++i) EXPECT_FLOAT_EQ(s.reused(1.0f, true, 0.005, 0.1), 0.2f);
    // The first motion after a still view starts from the last rendered frame's time, not the
    // idle frames' (the still frame before was a 2 s render: √(0.1/2) = 0.22 → 0.2).
    Frames t;
    t.next(1.0f, false, kFps, 2.0);
    t.reused(1.0f, false, 0.005, 2.0);
    EXPECT_FLOAT_EQ(t.reused(1.0f, true, 0.005, 2.0), 0.2f);
}

}  // namespace
}  // namespace lit::editor
