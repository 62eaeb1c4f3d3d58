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
