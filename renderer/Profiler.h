#pragma once
// Per-pass GPU and CPU timings without stalling the pipeline.
//
// Each pass is bracketed by a Scope (RAII) that pushes a KHR_debug group with the pass name,
// issues GL_TIME_ELAPSED queries and measures CPU time. Query results are read back
// kFramesInFlight frames later, when they are ready, so reading never waits on the GPU.
// Passes that did not run in a frame (e.g. voxelization when nothing changed) report 0 for it.

#include "gl/Handle.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace lit {

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;  // GPU time of the pass in the latest frame whose queries are ready
    double cpuMs = 0.0;  // CPU time spent issuing the pass
    bool ran = false;    // whether the pass ran in that frame
    std::uint64_t frame = 0;  // Profiler frame number the timing comes from
};

class Profiler {
public:
    static constexpr int kFramesInFlight = 4;

    class Scope {
    public:
        Scope(Profiler& profiler, const char* name);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        Profiler& profiler_;
        int slot_;
        std::chrono::steady_clock::time_point start_;
    };

    Profiler();

    // Frame boundaries: beginFrame collects finished queries from earlier frames.
    void beginFrame();
    void endFrame();

    // Latest completed timings, in first-use pass order.
    const std::vector<PassTiming>& timings() const { return latest_; }
    // The timings of the last kFramesInFlight completed frames, oldest first (a beginFrame may
    // complete several at once; timings() holds only the newest of them).
    const std::deque<std::vector<PassTiming>>& recentFrames() const { return recent_; }
    double gpuMs(const std::string& pass) const;  // in the latest completed frame; 0 when it did not run or is unknown
    // The timing of the most recent completed frame in which `pass` ran (passes that run only
    // when something changed, like voxelization, keep their last cost here); nullptr if never.
    const PassTiming* lastRun(const std::string& pass) const;
    // Number of the frame currently being recorded (frames are numbered from 1 by beginFrame).
    std::uint64_t currentFrame() const { return frameNumber_; }
    double totalGpuMs() const;
    double lastCpuFrameMs() const { return lastCpuFrameMs_; }
    std::uint64_t completedFrames() const { return completedFrames_; }

    // Blocks until every issued query is available and collects them (for benchmarks and tests
    // that need the timings of the frame they just rendered).
    void flush();
    // Collects the frames whose queries are ready, oldest first, without waiting or starting a
    // frame: a front end that shows its last image again instead of rendering (the editor when
    // nothing changed) calls it so that the last rendered frame's timings still arrive.
    void poll();

private:
    struct Sample {
        int passIndex;
        gl::QueryHandle begin, end;  // GL_TIMESTAMP pairs: nested scopes stay correct
        double cpuMs;
    };
    struct Frame {
        std::vector<Sample> samples;
        bool pending = false;
        std::uint64_t number = 0;
    };

    int passIndex(const char* name);
    bool collect(Frame& frame, bool wait);

    std::vector<std::string> passNames_;
    std::array<Frame, kFramesInFlight> frames_;
    int current_ = 0;
    std::vector<PassTiming> latest_;
    std::deque<std::vector<PassTiming>> recent_;
    std::vector<PassTiming> lastRun_;
    std::uint64_t frameNumber_ = 0;
    std::uint64_t completedFrames_ = 0;
    std::chrono::steady_clock::time_point frameStart_;
    double lastCpuFrameMs_ = 0.0;
    std::vector<gl::QueryHandle> pool_;
};

}  // namespace lit
