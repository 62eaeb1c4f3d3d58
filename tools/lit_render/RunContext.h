#pragma once
// What lit-render's runs share (StillRun, PathRun, ReferenceRun): the command line and the settings
// it resolved to, the renderer of a rasterized run, the runtime failure and the clock.

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

#include "Options.h"
#include "RenderSettings.h"

namespace lit {
class Log;
class Renderer;
struct HdrImage;
}  // namespace lit

namespace lit::cli {

// A failure already phrased for the user ("cannot write X: ..."); lit-render prints it and exits 1.
// A command line, scene or file that cannot be used is a UsageError instead (exit 2).
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// What every run reads, all resolved before the scene loads so a bad file fails at once.
struct RunContext {
    const Options& options;
    const RenderSettings& settings;  // --settings, then --set, then the other flags
    // --compare's reference image, read and checked against the render's size up front; null
    // without --compare.
    const HdrImage* compareTruth = nullptr;
    Log& log;
};

// What a rasterized run (a still or a camera path) has besides: the renderer with the scene
// uploaded, and the check that keeps a render with GL errors from writing anything.
struct GlRun {
    Renderer& renderer;
    std::string device;  // the GL context's description, for the benchmark JSON
    // Waits for the GL and throws RunError when a GL error was logged since the start.
    std::function<void()> requireNoGlErrors;
};

}  // namespace lit::cli
