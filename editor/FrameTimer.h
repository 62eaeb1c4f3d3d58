#pragma once
// Frame times for the performance overlay: an average over the last few frames (a single
// frame's time jumps around too much to read) and a history of the last few seconds for the
// frame-time graph.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace lit::editor {

class FrameTimer {
public:
    static constexpr std::size_t kWindow = 30;         // frames averaged
    static constexpr std::size_t kHistory = 600;       // frames kept for the graph at most
    static constexpr double kHistorySeconds = 5.0;     // ... and no more than this much time

    void add(double frameSeconds) {
        samples_[next_] = frameSeconds;
        next_ = (next_ + 1) % kWindow;
        if (count_ < kWindow) ++count_;
        last_ = frameSeconds;

        history_[historyNext_] = frameSeconds;
        historyNext_ = (historyNext_ + 1) % kHistory;
        if (historyCount_ < kHistory) ++historyCount_;
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

    // Frame times in milliseconds, oldest first, covering the last kHistorySeconds (at least the
    // latest frame, so a slow renderer still shows something).
    std::vector<float> historyMs() const {
        std::vector<float> out;
        double seconds = 0.0;
        for (std::size_t i = 0; i < historyCount_; ++i) {
            const double sample = history_[(historyNext_ + kHistory - 1 - i) % kHistory];
            if (i > 0 && seconds + sample > kHistorySeconds) break;
            seconds += sample;
            out.push_back(static_cast<float>(sample * 1000.0));
        }
        std::reverse(out.begin(), out.end());
        return out;
    }

private:
    std::array<double, kWindow> samples_{};
    std::size_t next_ = 0;
    std::size_t count_ = 0;
    double last_ = 0.0;  // seconds
    std::array<double, kHistory> history_{};
    std::size_t historyNext_ = 0;
    std::size_t historyCount_ = 0;
};

}  // namespace lit::editor
