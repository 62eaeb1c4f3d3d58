#include <gtest/gtest.h>

#include "FrameTimer.h"

namespace {

using lit::editor::FrameTimer;

TEST(EditorFrameTimer, AveragesRecentFrames) {
    FrameTimer timer;
    EXPECT_EQ(timer.averageMs(), 0.0);
    EXPECT_EQ(timer.fps(), 0.0);
    timer.add(0.010);
    timer.add(0.030);
    EXPECT_NEAR(timer.averageMs(), 20.0, 1e-9);
    EXPECT_NEAR(timer.fps(), 50.0, 1e-9);
    EXPECT_NEAR(timer.lastMs(), 30.0, 1e-9);
}

TEST(EditorFrameTimer, ForgetsFramesOutsideTheWindow) {
    FrameTimer timer;
    timer.add(1.0);  // a stall, e.g. loading a scene
    for (std::size_t i = 0; i < FrameTimer::kWindow; ++i) timer.add(0.016);
    EXPECT_NEAR(timer.averageMs(), 16.0, 1e-9);
}

}  // namespace

namespace {

using lit::editor::FrameTimer;

TEST(EditorFrameTimer, HistoryCoversTheLastFewSecondsOldestFirst) {
    FrameTimer timer;
    EXPECT_TRUE(timer.historyMs().empty());
    timer.add(0.5);  // will fall out: more than kHistorySeconds of frames follow
    for (int i = 0; i < 400; ++i) timer.add(0.016);
    timer.add(0.040);
    const std::vector<float> history = timer.historyMs();
    ASSERT_FALSE(history.empty());
    EXPECT_NEAR(history.back(), 40.0f, 1e-4f);  // newest last
    double total = 0.0;
    for (float ms : history) total += ms;
    EXPECT_LE(total, FrameTimer::kHistorySeconds * 1000.0 + 1e-6);
    EXPECT_GT(total, FrameTimer::kHistorySeconds * 1000.0 - 20.0);  // filled to within one frame
    for (float ms : history) EXPECT_LT(ms, 100.0f);                 // the old 500 ms stall is gone
}

TEST(EditorFrameTimer, HistoryKeepsOneFrameLongerThanTheWindow) {
    FrameTimer timer;
    timer.add(12.0);  // a 12 s frame (a huge scene on a software renderer)
    ASSERT_EQ(timer.historyMs().size(), 1u);
    EXPECT_NEAR(timer.historyMs()[0], 12000.0f, 1e-2f);
}

}  // namespace
