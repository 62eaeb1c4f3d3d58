// lit-render — renders a glTF scene headless (EGL, no window or X server) to PNG/HDR, or
// benchmarks it, or flies a camera path (frames to PNGs, or per-frame timings).
// Exit status: 0 success, 1 runtime failure, 2 bad command line, 130 a --reference render
// interrupted by Ctrl+C (after writing the image so far).

#include "Options.h"

#include "Log.h"
#include "Renderer.h"
#include "RenderSettings.h"
#include "animation/CameraPath.h"
#include "animation/CameraPathIO.h"
#include "context/HeadlessContext.h"
#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "image/ImageIO.h"
#include "scene/CameraView.h"
#include "passes/MipmapPass.h"
#include "scene/GltfLoader.h"
#include "scene/SceneBuilder.h"
#include "scene/Scene.h"
#include "scene/Sky.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"

#include <epoxy/gl.h>
#include <tbb/info.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <unistd.h>
#include <exception>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using lit::cli::Options;
using lit::cli::UsageError;
using Clock = std::chrono::steady_clock;

// A failure already phrased for the user ("cannot load X: ..."); main prints it and exits 1.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string readTextFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RunError("cannot read settings " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeTextFileAtomic(const fs::path& path, const std::string& text) {
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out.flush()) throw RunError("cannot write " + path.string());
    }
    fs::rename(tmp, path);
}

struct Summary {
    double min = 0, median = 0, mean = 0, max = 0;
};

Summary summarize(std::vector<double> values) {
    Summary s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.min = values.front();
    s.max = values.back();
    const std::size_t n = values.size();
    s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(n);
    return s;
}

nlohmann::ordered_json toJson(const Summary& s) {
    return {{"min", s.min}, {"median", s.median}, {"mean", s.mean}, {"max", s.max}};
}

// Per-pass samples over the benchmark, in the profiler's first-use order. A pass that did not
// run in a frame (voxelization once the volume is clean) contributes no sample for it.
struct PassSamples {
    std::string name;
    std::vector<double> gpuMs, cpuMs;
};

struct BenchResult {
    std::vector<PassSamples> passes;
    std::vector<double> frameMs;     // wall time per frame: issuing plus waiting for the GPU
    std::vector<double> cpuFrameMs;  // time spent issuing the frame on the CPU
    std::vector<double> cullMs;      // CPU time of BVH refit + frustum culling per frame
    lit::MipmapTimings mipmaps;      // compute chain vs glGenerateTextureMipmap (GI only)
};

void printBench(const BenchResult& bench, const lit::RenderSettings& settings, const lit::FrameStats& lastFrame) {
    const auto row = [](const std::string& name, const Summary& s, std::size_t frames) {
        std::printf("%-28s %10.3f %10.3f %10.3f %10.3f %8zu\n", name.c_str(), s.min, s.median, s.mean, s.max, frames);
    };
    std::printf("%-28s %10s %10s %10s %10s %8s\n", "pass (GPU ms)", "min", "median", "mean", "max", "frames");
    for (const PassSamples& pass : bench.passes) row(pass.name, summarize(pass.gpuMs), pass.gpuMs.size());
    const Summary frame = summarize(bench.frameMs);
    row("frame (wall ms)", frame, bench.frameMs.size());
    row("frame (CPU issue ms)", summarize(bench.cpuFrameMs), bench.cpuFrameMs.size());
    std::printf("%dx%d, GI %s: lowest FPS %.2f, highest FPS %.2f, mean frame %.3f ms (%.2f FPS)\n", settings.width,
                settings.height, settings.gi ? "on" : "off", frame.max > 0 ? 1000.0 / frame.max : 0.0,
                frame.min > 0 ? 1000.0 / frame.min : 0.0, frame.mean, frame.mean > 0 ? 1000.0 / frame.mean : 0.0);
    // Draws of the last frame's culled views (the camera; shadow views only when they were redrawn).
    std::printf("draws: %d of %d submitted (culling %s), culling %.3f ms CPU (mean), %zu triangles\n",
                lastFrame.drawsSubmitted, lastFrame.drawsTotal, settings.frustumCulling ? "on" : "off",
                summarize(bench.cullMs).mean, lastFrame.triangles);
    if (bench.mipmaps.computeMinMs > 0.0)
        std::printf("radiance mipmaps (%s): compute %.3f ms, glGenerateTextureMipmap %.3f ms (min of runs): "
                    "compute is %.2fx as fast\n",
                    bench.mipmaps.rgba8 ? "RGBA8" : "RGBA16F", bench.mipmaps.computeMinMs, bench.mipmaps.generateMinMs,
                    bench.mipmaps.speedup());
}

nlohmann::ordered_json benchJson(const BenchResult& bench, const Options& options, const lit::RenderSettings& settings,
                                 const std::string& device, const lit::FrameStats& stats) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const PassSamples& pass : bench.passes)
        passes.push_back({{"name", pass.name},
                          {"framesRan", pass.gpuMs.size()},
                          {"gpuMs", toJson(summarize(pass.gpuMs))},
                          {"cpuMs", toJson(summarize(pass.cpuMs))}});
    const Summary frame = summarize(bench.frameMs);
    return {{"scene", options.scene.string()},
            {"device", device},
            {"width", settings.width},
            {"height", settings.height},
            {"view", std::string(lit::toString(settings.view))},
            {"gi", settings.gi},
            {"voxelResolution", settings.voxelResolution},
            {"frames", bench.frameMs.size()},
            {"frameMs", toJson(frame)},
            {"cpuFrameMs", toJson(summarize(bench.cpuFrameMs))},
            {"fps", frame.mean > 0 ? 1000.0 / frame.mean : 0.0},
            {"lowestFps", frame.max > 0 ? 1000.0 / frame.max : 0.0},
            {"highestFps", frame.min > 0 ? 1000.0 / frame.min : 0.0},
            {"mipmaps",
             {{"computeMinMs", bench.mipmaps.computeMinMs},
              {"computeMedianMs", bench.mipmaps.computeMedianMs},
              {"generateMinMs", bench.mipmaps.generateMinMs},
              {"generateMedianMs", bench.mipmaps.generateMedianMs},
              {"speedup", bench.mipmaps.speedup()}}},
            {"triangles", stats.triangles},
            {"drawCalls", stats.drawCalls},
            {"frustumCulling", settings.frustumCulling},
            {"drawsSubmitted", stats.drawsSubmitted},
            {"drawsTotal", stats.drawsTotal},
            {"cullMs", toJson(summarize(bench.cullMs))},
            {"passes", passes}};
}

// Waits for the frame just issued and records its timings. Waiting for this frame's queries
// serialises CPU and GPU: the wall time per frame is then the true cost of a frame, and the pass
// timings belong to this very frame.
void recordBenchFrame(BenchResult& bench, std::map<std::string, std::size_t>& passIndex, lit::Renderer& renderer,
                      Clock::time_point frameStart) {
    renderer.profiler().flush();
    bench.frameMs.push_back(secondsSince(frameStart) * 1000.0);
    bench.cpuFrameMs.push_back(renderer.profiler().lastCpuFrameMs());
    bench.cullMs.push_back(renderer.stats().cullMs);
    for (const lit::PassTiming& timing : renderer.profiler().timings()) {
        auto [it, inserted] = passIndex.try_emplace(timing.name, bench.passes.size());
        if (inserted) bench.passes.push_back({timing.name, {}, {}});
        if (!timing.ran) continue;
        bench.passes[it->second].gpuMs.push_back(timing.gpuMs);
        bench.passes[it->second].cpuMs.push_back(timing.cpuMs);
    }
}

// Progress of a long render on stderr: "frame 12/90, 3.1 s elapsed, 20.2 s remaining". Silent for
// the first second (short renders print nothing); then rewritten in place on a terminal (at most
// 10 times a second), or one line a second when stderr is a file or pipe.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), start_(Clock::now()), terminal_(isatty(fileno(stderr)) != 0) {}

    void update(std::size_t done) {
        const double elapsed = secondsSince(start_);
        if (elapsed < 1.0) return;
        if (elapsed - lastPrint_ < (terminal_ ? 0.1 : 1.0) && done < total_) return;
        lastPrint_ = elapsed;
        printed_ = true;
        const double remaining = done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(total_ - done) : 0.0;
        char line[128];
        std::snprintf(line, sizeof line, "frame %zu/%zu, %.1f s elapsed, %.1f s remaining", done, total_, elapsed, remaining);
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

// Load progress on stderr, for long loads only: silent for the first second, then one line per
// stage ("loading: images 12/69, 4.2 s") when the stage changes or a second has passed, and the
// GPU upload as its own stage. Uses the loader's progress callback (GltfLoadOptions::progress),
// which the editor's progress window reads as well.
class LoadProgressPrinter {
public:
    void operator()(const lit::LoadProgress& p) {
        const double elapsed = secondsSince(start_);
        const bool newStage = p.stage != stage_;
        stage_ = p.stage;
        if (elapsed < 1.0 || (!newStage && elapsed - lastPrint_ < 1.0 && p.done < p.total)) return;
        lastPrint_ = elapsed;
        std::fprintf(stderr, "loading: %s %d/%d, %.1f s\n", p.stage.c_str(), p.done, p.total, elapsed);
        std::fflush(stderr);
    }
    void stage(const char* name) { (*this)(lit::LoadProgress{name, 0, 1}); }
    void done(const char* name) { (*this)(lit::LoadProgress{name, 1, 1}); }

private:
    Clock::time_point start_ = Clock::now();
    std::string stage_;
    double lastPrint_ = -1.0;
};

// The camera path --path names: a .json file, or a camera animation in the scene file. Runs
// before any GL work so a bad path is reported at once.
lit::CameraPath loadPath(const Options& options) {
    const std::string& what = *options.path;
    try {
        lit::CameraPath path;
        if (options.pathIsFile()) {
            path = lit::loadCameraPathJson(what);
        } else {
            const std::vector<std::string> names = lit::cameraAnimationNames(options.scene);
            if (std::find(names.begin(), names.end(), what) == names.end()) {
                std::string message = "no camera animation '" + what + "' in " + options.scene.string() + "; ";
                if (names.empty()) message += "the scene has none";
                else message += "its camera animations are:";
                for (std::size_t i = 0; i < names.size(); ++i) message += (i ? ", '" : " '") + names[i] + "'";
                throw UsageError(message + " (a path file's name ends in .json)");
            }
            path = lit::loadCameraPathFromGltf(options.scene, what);
        }
        if (path.empty()) throw RunError("the camera path " + what + " has no keys");
        return path;
    } catch (const lit::CameraPathError& e) {
        throw RunError(std::string("cannot use the camera path: ") + e.what());
    }
}

// --path: renders every frame of the path (to PNGs with --frames-out) and times them (--bench-path).
int runPath(const Options& options, const lit::CameraPath& path, const lit::Scene& scene, lit::Renderer& renderer,
            const lit::RenderSettings& settings, const lit::HeadlessContext& context) {
    std::vector<double> times;
    try {
        times = path.frameTimes(options.pathFps());
    } catch (const std::invalid_argument& e) {
        throw RunError(std::string("cannot render the camera path: ") + e.what());
    }
    if (times.size() > static_cast<std::size_t>(lit::cli::kMaxFrames))
        throw RunError("the camera path is " + std::to_string(path.duration()) + " s long: " + std::to_string(times.size()) +
                       " frames at this --fps, more than " + std::to_string(lit::cli::kMaxFrames));
    if (!options.framesOut.empty()) {
        std::error_code ec;
        fs::create_directories(options.framesOut, ec);
        if (ec || !fs::is_directory(options.framesOut))
            throw RunError("cannot create the folder " + options.framesOut.string() + ": " + ec.message());
    }

    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const lit::Aabb bounds = scene.worldBounds();
    const auto viewAt = [&](double t) { return *path.view(t, aspect, bounds); };

    const Clock::time_point renderStart = Clock::now();
    if (options.benchPath) {
        // One untimed warm-up frame: voxelization, shader and driver warm-up happen once per
        // scene, not per frame of a fly-through.
        renderer.render(scene, viewAt(times.front()), settings);
        renderer.profiler().flush();
        glFinish();
    }
    BenchResult bench;
    std::map<std::string, std::size_t> passIndex;
    Progress progress(times.size());
    std::vector<std::uint8_t> rgba;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const lit::CameraView view = viewAt(times[i]);
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, view, settings);
        if (options.benchPath) recordBenchFrame(bench, passIndex, renderer, frameStart);
        if (!options.framesOut.empty()) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%05zu.png", i);
            rgba = renderer.readOutputRgba8();
            lit::writePng(options.framesOut / name, settings.width, settings.height, rgba);
        }
        progress.update(i + 1);
    }
    glFinish();
    progress.finish();

    const double seconds = secondsSince(renderStart);
    if (options.benchPath) {
        std::printf("camera path %s: %zu frames at %g fps over %.3f s\n", options.path->c_str(), times.size(),
                    options.pathFps(), static_cast<double>(path.duration()));
        printBench(bench, settings, renderer.stats());
        if (!options.benchJson.empty()) {
            nlohmann::ordered_json json = benchJson(bench, options, settings, context.description(), renderer.stats());
            json["path"] = *options.path;
            json["pathFps"] = options.pathFps();
            json["pathSeconds"] = path.duration();
            writeTextFileAtomic(options.benchJson, json.dump(2) + "\n");
            std::printf("wrote %s\n", options.benchJson.string().c_str());
        }
    }
    if (!options.framesOut.empty())
        std::printf("wrote %zu frames to %s (%dx%d, %g fps, %.2f s)\n", times.size(), options.framesOut.string().c_str(),
                    settings.width, settings.height, options.pathFps(), seconds);
    return 0;
}

// Set by SIGINT while a reference render runs: the render stops after the tiles in flight and
// writes the image so far. A lock-free atomic is async-signal-safe; a signal handler has no other
// way to reach the render than through static storage.
std::atomic<bool>& interruptRequested() {
    static std::atomic<bool> requested{false};
    return requested;
}
extern "C" void onInterrupt(int) { interruptRequested().store(true); }

// --reference: path-trace the still on the CPU and write the same images as the rasterizer.
int runReference(const Options& options, const lit::Scene& scene, int cameraIndex, const lit::RenderSettings& settings,
                 lit::Log& log) {
    const Clock::time_point buildStart = Clock::now();
    // A scene without lights is lit by the rasterizer's default sun (scene/Sky.h); give the
    // reference the same sun as a light of its own copy of the scene.
    lit::Scene withSun = scene;
    if (lit::hasDefaultSun(scene, settings)) {
        lit::Light sun;
        sun.name = "default sun";
        sun.type = lit::LightType::Directional;
        sun.intensity = settings.defaultSunIrradiance;
        lit::addLightNode(withSun, sun, glm::vec3(0.0f), lit::defaultSunDirection(settings));
        withSun.updateWorldTransforms();
    }
    const lit::reference::ReferenceScene referenceScene(withSun, log);
    const double buildSeconds = secondsSince(buildStart);
    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const lit::CameraView camera = lit::sceneCameraView(scene, cameraIndex, aspect);

    lit::reference::ReferenceSettings reference;
    // Without --bounces the reference follows --gi: one bounce like the VCT, or direct light only.
    reference.bounces = options.bounces.value_or(settings.gi ? 1 : 0);
    reference.seed = options.seed.value_or(0);
    // Rays that leave the scene see the same sky as the rasterizer's background and cones.
    std::string skyError;
    reference.environment = lit::makeSkyFunction(scene, settings, &skyError);
    if (!skyError.empty()) log.error(skyError + "; using the gradient sky");
    lit::reference::PathTracer tracer(referenceScene, camera, settings.width, settings.height, reference);

    interruptRequested().store(false);
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    struct sigaction previous {};
    sigaction(SIGINT, &action, &previous);

    const int spp = options.referenceSpp();
    const bool terminal = isatty(fileno(stderr)) != 0;
    const Clock::time_point renderStart = Clock::now();
    double lastPrint = -1.0;
    bool interrupted = false;
    bool printed = false;
    while (tracer.samplesDone() < spp) {
        if (!tracer.addSamples(1, &interruptRequested())) {
            interrupted = true;
            break;
        }
        const double elapsed = secondsSince(renderStart);
        const int done = tracer.samplesDone();
        if (elapsed - lastPrint >= (terminal ? 0.2 : 1.0) || done == spp) {
            lastPrint = elapsed;
            printed = true;
            const double raysPerSecond = elapsed > 0.0 ? static_cast<double>(tracer.raysTraced()) / elapsed : 0.0;
            const double remaining = elapsed / done * (spp - done);
            char line[160];
            std::snprintf(line, sizeof line, "reference: %d/%d spp, %.2f Mrays/s, %.1f s elapsed, ETA %.1f s", done, spp,
                          raysPerSecond * 1e-6, elapsed, remaining);
            if (terminal)
                std::fprintf(stderr, "\r%-72s", line);
            else
                std::fprintf(stderr, "%s\n", line);
            std::fflush(stderr);
        }
    }
    sigaction(SIGINT, &previous, nullptr);
    if (printed && terminal) std::fputc('\n', stderr);
    const double seconds = secondsSince(renderStart);

    const std::string bounces = reference.bounces == lit::reference::kAllBounces ? "all" : std::to_string(reference.bounces);
    std::printf("reference: %dx%d, %u spp (min per pixel), bounces %s, seed %llu: %.1f M rays in %.2f s = %.2f Mrays/s "
                "on %d threads (scene build %.2f s, %zu triangles)\n",
                settings.width, settings.height, tracer.image().minSamples(), bounces.c_str(),
                static_cast<unsigned long long>(reference.seed), static_cast<double>(tracer.raysTraced()) * 1e-6, seconds,
                seconds > 0.0 ? static_cast<double>(tracer.raysTraced()) / seconds * 1e-6 : 0.0,
                tbb::info::default_concurrency(), buildSeconds, referenceScene.triangleCount());

    const std::vector<float> rgb = tracer.image().viewRgb(settings.view, settings);
    std::string written;
    if (!options.out.empty()) {
        lit::writePng(options.out, settings.width, settings.height, lit::reference::toneMapToRgba8(rgb, settings.exposureScale()));
        written = options.out.string();
    }
    if (!options.hdr.empty()) {
        lit::writeHdr(options.hdr, settings.width, settings.height, rgb);
        written += (written.empty() ? "" : " and ") + options.hdr.string();
    }
    if (!written.empty()) std::printf("wrote %s\n", written.c_str());
    if (interrupted) {
        std::fprintf(stderr, "lit-render: interrupted after %d of %d samples per pixel; the image so far was written\n",
                     tracer.samplesDone(), spp);
        return 130;  // the shell's status for a SIGINT
    }
    return 0;
}

int run(const Options& options) {
    lit::Log log;

    // Everything that needs no GL comes first, so a bad file or camera is reported at once.
    lit::RenderSettings settings;
    if (!options.settings.empty()) {
        try {
            settings = lit::renderSettingsFromJson(readTextFile(options.settings));
        } catch (const RunError&) {
            throw;
        } catch (const std::exception& e) {
            throw RunError("cannot use settings " + options.settings.string() + ": " + e.what());
        }
    }
    settings = lit::cli::applyOptions(options, settings);

    lit::Scene scene;
    LoadProgressPrinter loadProgress;
    try {
        lit::GltfLoadOptions loadOptions;
        loadOptions.progress = [&](const lit::LoadProgress& p) { loadProgress(p); };
        scene = lit::loadGltf(options.scene, log, loadOptions);  // logs the summary line (meshes, triangles, MB, ms)
    } catch (const std::exception& e) {
        // The loader's messages usually start with the path already; say it once.
        std::string reason = e.what();
        const std::string prefix = options.scene.string() + ": ";
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw RunError("cannot load " + options.scene.string() + ": " + reason);
    }
    lit::addDefaultCamera(scene, log);
    const int cameraIndex = lit::cli::resolveCamera(options, scene);
    if (options.reference) return runReference(options, scene, cameraIndex, settings, log);
    const std::optional<lit::CameraPath> path = options.path ? std::optional(loadPath(options)) : std::nullopt;

    lit::HeadlessContext context;
    lit::gl::requireCapabilities();
    lit::gl::installDebugOutput(log);
    lit::Renderer renderer(lit::defaultShaderRoot(), log);
    loadProgress.stage("upload");
    renderer.setScene(scene);
    loadProgress.done("upload");
    if (path) return runPath(options, *path, scene, renderer, settings, context);

    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const lit::CameraView camera = lit::sceneCameraView(scene, cameraIndex, aspect);

    const Clock::time_point renderStart = Clock::now();
    BenchResult bench;
    std::map<std::string, std::size_t> passIndex;
    for (int frame = 0; frame < options.frameCount(); ++frame) {
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, camera, settings);
        if (options.benchFrames > 0) recordBenchFrame(bench, passIndex, renderer, frameStart);
    }
    glFinish();
    if (settings.autoExposure) std::printf("auto exposure: %+.2f EV\n", static_cast<double>(renderer.exposureEv(settings)));
    if (options.benchFrames > 0 && settings.gi) bench.mipmaps = renderer.benchmarkMipmaps(7);

    if (options.benchFrames > 0) {
        printBench(bench, settings, renderer.stats());
        if (!options.benchJson.empty()) {
            writeTextFileAtomic(options.benchJson,
                                benchJson(bench, options, settings, context.description(), renderer.stats()).dump(2) + "\n");
            std::printf("wrote %s\n", options.benchJson.string().c_str());
        }
    }

    std::string written;
    if (!options.out.empty()) {
        const std::vector<std::uint8_t> rgba = renderer.readOutputRgba8();
        lit::writePng(options.out, settings.width, settings.height, rgba);
        written = options.out.string();
    }
    if (!options.hdr.empty()) {
        const std::vector<float> rgb = renderer.readHdrRgb();
        lit::writeHdr(options.hdr, settings.width, settings.height, rgb);
        written += (written.empty() ? "" : " and ") + options.hdr.string();
    }
    if (!written.empty())
        std::printf("wrote %s (%d\u00d7%d, %.2f s)\n", written.c_str(), settings.width, settings.height, secondsSince(renderStart));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = lit::cli::parseOptions(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "lit-render: %s\n%s", e.what(), lit::cli::shortUsage().c_str());
        return 2;
    }
    if (options.help) {
        std::fputs(lit::cli::usageText().c_str(), stdout);
        return 0;
    }
    try {
        return run(options);
    } catch (const UsageError& e) {  // a camera the scene does not have
        std::fprintf(stderr, "lit-render: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {  // RunError, GlError, EGL and file failures
        std::fprintf(stderr, "lit-render: %s\n", e.what());
        return 1;
    }
}
