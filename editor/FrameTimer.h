#pragma once
// Frame time averaged over the last few frames, for the stats overlay (a single frame's time
// jumps around too much to read).

#include <array>
#include <cstddef>

namespace lit::editor {

class FrameTimer {
public:
    static constexpr std::size_t kWindow = 30;  // frames averaged

    void add(double frameSeconds) {
        samples_[next_] = frameSeconds;
        next_ = (next_ + 1) % kWindow;
        if (count_ < kWindow) ++count_;
        last_ = frameSeconds;
    }

    double lastMs() const { return last_ * 1000.0; }
    double averageMs() const {
        if (count_ == 0) return 0.0;
        double sum = 0.0;
        for (std::size_t i = 0; i < count_; ++i) sum += samples_[i];
        return sum / static_cast<double>(count_) * 1000.0;
    }
    double fps() const {
        const double ms = averageMs();
        return ms > 0.0 ? 1000.0 / ms : 0.0;
    }

private:
    std::array<double, kWindow> samples_{};
    std::size_t next_ = 0;
    std::size_t count_ = 0;
    double last_ = 0.0;  // seconds
};

}  // namespace lit::editor
