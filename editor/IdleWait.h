#pragma once
// When the editor's frame loop may sleep until the window system has news
// (glfwWaitEventsTimeout) instead of starting the next frame at once: after a few frames in which
// nothing happened (no input, no 3D render, no work in flight), so that an idle editor costs next
// to nothing. Dear ImGui shows some effects of input a frame or two late (a window that sizes
// itself to its contents, one that appears after a hidden frame), hence the quiet frames first.
// Window-free: tests/editor/test_idle_wait.cpp.

#include <algorithm>

namespace lit::editor {

class IdleWait {
public:
    // Frames in which nothing happened before the loop sleeps.
    static constexpr int kQuietFrames = 3;
    // The longest sleep, s: how late a check the loop makes every frame may come (changed shader
    // files every 0.5 s, the autosave), and the blink of a text cursor.
    static constexpr double kMaxSeconds = 0.5;

    // Once a frame, at its end. `busy`: input, a 3D render or work in flight this frame;
    // `wakeWithin`: s until something is due that no event announces (the end of the interactive
    // scale's grace period, a progress display). Returns how long the next frame may wait for
    // events before it starts, s; 0: poll and go on.
    double next(bool busy, double wakeWithin = kMaxSeconds) {
        quietFrames_ = busy ? 0 : std::min(quietFrames_ + 1, kQuietFrames);
        if (quietFrames_ < kQuietFrames) return 0.0;
        return std::clamp(wakeWithin, 0.0, kMaxSeconds);
    }

private:
    int quietFrames_ = 0;
};

}  // namespace lit::editor
