// IdleWait: the editor's frame loop sleeps only after a few frames in which nothing happened.
#include <gtest/gtest.h>

#include "IdleWait.h"

namespace lit::editor {
namespace {

TEST(IdleWait, SleepsAfterQuietFramesOnly) {
    IdleWait wait;
    EXPECT_EQ(wait.next(true), 0.0);
    // Dear ImGui shows some effects of input a frame late: a few more frames first.
    for (int frame = 1; frame < IdleWait::kQuietFrames; ++frame) EXPECT_EQ(wait.next(false), 0.0) << frame;
    EXPECT_EQ(wait.next(false), IdleWait::kMaxSeconds);
    EXPECT_EQ(wait.next(false), IdleWait::kMaxSeconds);
    // Input (or a render) wakes it up: frame after frame again.
    EXPECT_EQ(wait.next(true), 0.0);
    EXPECT_EQ(wait.next(false), 0.0);
}

TEST(IdleWait, WakesUpForWhatIsDue) {
    IdleWait wait;
    for (int frame = 0; frame < IdleWait::kQuietFrames; ++frame) wait.next(false);
    // The end of the interactive scale's grace period, a refresh of the reference image.
    EXPECT_DOUBLE_EQ(wait.next(false, 0.12), 0.12);
    EXPECT_EQ(wait.next(false, 7.0), IdleWait::kMaxSeconds);
    EXPECT_EQ(wait.next(false, -1.0), 0.0);
}

}  // namespace
}  // namespace lit::editor
