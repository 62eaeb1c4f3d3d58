#include "PathRun.h"

#include <epoxy/gl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "Bench.h"
#include "FlickerMeter.h"
#include "Renderer.h"
#include "animation/CameraPathIO.h"
#include "animation/NodeAnimation.h"
#include "image/ImageIO.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit::cli {

namespace fs = std::filesystem;

namespace {

// Progress of a long render on stderr: "frame 12/90, 3.1 s elapsed, 20.2 s remaining". Silent for
// the first second (short renders print nothing); then rewritten in place on a terminal (at most
// 10 times a second), or one line a second when stderr is a file or pipe.
class Progress {
public:
    explicit Progress(std::size_t total)
        : total_(total), start_(Clock::now()), terminal_(isatty(fileno(stderr)) != 0) {}

    void update(std::size_t done) {
        const double elapsed = secondsSince(start_);
        if (elapsed < 1.0) return;
        if (elapsed - lastPrint_ < (terminal_ ? 0.1 : 1.0) && done < total_) return;
        lastPrint_ = elapsed;
        printed_ = true;
        const double remaining =
            done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(total_ - done) : 0.0;
        char line[128];
        std::snprintf(line, sizeof line, "frame %zu/%zu, %.1f s elapsed, %.1f s remaining", done, total_, elapsed,
                      remaining);
        if (terminal_)
            std::fprintf(stderr, "\r%-60s", line);
        else
            std::fprintf(stderr, "%s\n", line);
        std::fflush(stderr);
    }
    // Ends the in-place line so later output starts on a line of its own.
    void finish() {
        if (printed_ && terminal_) std::fputc('\n', stderr);
    }

private:
    std::size_t total_;
    Clock::time_point start_;
    bool terminal_;
    bool printed_ = false;
    double lastPrint_ = 0.0;  // seconds since start_
};

}  // namespace

CameraPath loadPath(const Options& options) {
    const std::string& what = *options.path;
    try {
        lit::CameraPath path;
        if (options.pathIsFile()) {
            // A path file is a few kB; refuse what is not one before reading it whole.
            std::error_code ec;
            const fs::file_status status = fs::status(what, ec);
            if (fs::exists(status) && !fs::is_regular_file(status))
                throw UsageError("cannot use the camera path: " + what + " is not a regular file");
            if (fs::exists(status) && fs::file_size(what, ec) > (16u << 20))
                throw UsageError("cannot use the camera path: " + what + " is larger than 16 MiB, not a path file");
            path = lit::loadCameraPathJson(what);
        } else {
            const std::vector<std::string> names = lit::cameraAnimationNames(options.scene);
            if (std::find(names.begin(), names.end(), what) == names.end()) {
                std::string message = "no camera animation '" + what + "' in " + options.scene.string() + "; ";
                if (names.empty())
                    message += "the scene has none";
                else
                    message += "its camera animations are:";
                for (std::size_t i = 0; i < names.size(); ++i) message += (i ? ", '" : " '") + names[i] + "'";
                throw UsageError(message + " (a path file's name ends in .json)");
            }
            path = lit::loadCameraPathFromGltf(options.scene, what);
        }
        if (path.empty()) throw UsageError("the camera path " + what + " has no keys");
        return path;
    } catch (const lit::CameraPathError& e) {
        throw UsageError(std::string("cannot use the camera path: ") + e.what());
    }
}

std::vector<double> pathFrameTimes(const Options& options, const CameraPath& path, const Scene& scene) {
    std::vector<double> times;
    try {
        times = path.frameTimes(options.pathFps());
    } catch (const std::invalid_argument& e) {
        throw RunError(std::string("cannot render the camera path: ") + e.what());
    }
    // The node animations may run on after the path's last key: the frames go on with them.
    const double animationEnd = summarizeNodeAnimations(scene).endTime;
    const double frameStep = 1.0 / options.pathFps();
    while (!times.empty() && times.back() + frameStep <= animationEnd + 1e-6 &&
           times.size() <= static_cast<std::size_t>(kMaxFrames))
        times.push_back(times.back() + frameStep);
    if (times.size() > static_cast<std::size_t>(kMaxFrames))
        throw RunError("the camera path is " + std::to_string(path.duration()) + " s long: " +
                       std::to_string(times.size()) + " frames at this --fps, more than " + std::to_string(kMaxFrames));
    return times;
}

void makeFramesFolder(const fs::path& folder) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder))
        throw RunError("cannot create the folder " + folder.string() + ": " + ec.message());
}

fs::path frameFile(const fs::path& folder, std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.png", index);
    return folder / name;
}

int runPath(const RunContext& run, const CameraPath& path, Scene& scene, const GlRun& gl) {
    const Options& options = run.options;
    const RenderSettings& settings = run.settings;
    Renderer& renderer = gl.renderer;
    const std::vector<double> times = pathFrameTimes(options, path, scene);
    if (!options.framesOut.empty()) makeFramesFolder(options.framesOut);

    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    // Each frame poses the nodes at its time first: the view's near and far planes fit the
    // bounds as posed.
    const auto viewAt = [&](double t) {
        applyNodeAnimations(scene, t);
        return *path.view(t, aspect, scene.worldBounds());
    };

    const Clock::time_point renderStart = Clock::now();
    if (options.benchPath) {
        // One untimed warm-up frame: voxelization, shader and driver warm-up happen once per
        // scene, not per frame of a fly-through. It finishes the GI work whole, so that a spread
        // budget times the flight from converged light (as a user who waited for the scene), not
        // the scene's first update.
        renderer.render(scene, viewAt(times.front()), settings, GiBudget::converge());
        renderer.profiler().flush();
        glFinish();
    }
    BenchResult bench;
    FlickerMeter flicker;
    Progress progress(times.size());
    std::vector<std::uint8_t> rgba;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const lit::CameraView view = viewAt(times[i]);
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, view, settings, giBudgetFor(options));
        if (options.benchPath) {
            recordBenchFrame(bench, renderer, frameStart);  // timed before the read-backs below
            flicker.add(view, settings.output.width, settings.output.height, renderer.readHdrRgb(),
                        renderer.readDepth());
        }
        if (!options.framesOut.empty()) {
            gl.requireNoGlErrors();  // before each frame is written: no wrong frame on disk
            rgba = renderer.readOutputRgba8();
            lit::writePng(frameFile(options.framesOut, i), settings.output.width, settings.output.height, rgba);
        }
        progress.update(i + 1);
    }
    glFinish();
    progress.finish();
    gl.requireNoGlErrors();

    const double seconds = secondsSince(renderStart);
    if (options.benchPath) {
        std::printf("camera path %s: %zu frames at %g fps over %.3f s\n", options.path->c_str(), times.size(),
                    options.pathFps(), static_cast<double>(path.duration()));
        printBench(bench, settings, renderer.stats());
        std::printf(
            "flicker: %.3f %% mean (%.3f %% worst of %zu frame pairs): mean |change| of pixels whose surface did "
            "not move, relative to the mean luminance\n",
            100.0 * flicker.mean(), 100.0 * flicker.max(), flicker.pairs());
        if (!options.benchJson.empty()) {
            nlohmann::ordered_json json = benchJson(bench, options, settings, gl.device, renderer.stats());
            json["flickerPercent"] = 100.0 * flicker.mean();
            json["flickerWorstPercent"] = 100.0 * flicker.max();
            json["path"] = *options.path;
            json["pathFps"] = options.pathFps();
            json["pathSeconds"] = path.duration();
            writeBenchJson(options.benchJson, json);
        }
    }
    if (!options.framesOut.empty())
        std::printf("wrote %zu frames to %s (%dx%d, %g fps, %.2f s)\n", times.size(),
                    options.framesOut.string().c_str(), settings.output.width, settings.output.height,
                    options.pathFps(), seconds);
    return 0;
}

}  // namespace lit::cli
