// lit-render — renders a glTF scene headless (EGL, no window or X server) to PNG/HDR, or
// benchmarks it, or flies a camera path (frames to PNGs, or per-frame timings).
// Exit status: 0 success, 1 runtime failure (GL errors, a failed write), 2 bad input: the command
// line, a scene, settings or path file that cannot be used, an output folder that cannot be
// written, or a size this GL or this machine's memory cannot render; 130 a --reference render
// interrupted by Ctrl+C (after writing the image so far).

#include <epoxy/gl.h>
#include <tbb/info.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "LoadProgressLines.h"
#include "Log.h"
#include "Options.h"
#include "RenderSettings.h"
#include "Renderer.h"
#include "animation/CameraPath.h"
#include "animation/CameraPathIO.h"
#include "context/HeadlessContext.h"
#include "gi/MipmapBenchmark.h"
#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "image/ImageIO.h"
#include "reference/DifferenceImage.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"
#include "scene/SceneBuilder.h"
#include "scene/Sky.h"

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

// Settings files are small; anything larger than this is not one (a wrong path, a video).
constexpr std::uintmax_t kMaxSettingsBytes = 1 << 20;

std::string readTextFile(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw UsageError("cannot read settings " + path.string() + ": no such file");
    if (!fs::is_regular_file(status)) throw UsageError("cannot read settings " + path.string() + ": not a regular file");
    if (fs::file_size(path, ec) > kMaxSettingsBytes)
        throw UsageError("cannot read settings " + path.string() + ": larger than 1 MiB, not a settings file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UsageError("cannot read settings " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A settings file's values against what lit-render can render: keys it does not know and
// values it clamps are warnings; sizes it cannot render are errors (UsageError, exit 2).
void checkSettingsFile(const fs::path& path, const std::string& text, lit::RenderSettings& settings, lit::Log& log) {
    const nlohmann::json given = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const nlohmann::json known = nlohmann::json::parse(lit::toJson(lit::RenderSettings{}));
    const std::string name = path.filename().string();
    // An older flat key is read (with its deprecation message); anything else unknown is a typo.
    std::vector<std::string> deprecated;
    lit::renderSettingsFromJson(text, {}, &deprecated);
    for (const std::string& message : deprecated) log.warning(name + ": " + message);
    if (given.is_object())
        for (const auto& [key, value] : given.items()) {
            const bool old = std::any_of(deprecated.begin(), deprecated.end(), [&key](const std::string& message) {
                return message.find("'" + key + "'") != std::string::npos;
            });
            if (old) continue;
            if (!known.contains(key)) {
                log.warning(name + ": unknown setting '" + key + "' ignored");
            } else if (value.is_object()) {
                for (const auto& [field, fieldValue] : value.items())
                    if (!known[key].contains(field))
                        log.warning(name + ": unknown setting '" + key + "." + field + "' ignored");
            }
        }
    const auto requireRange = [&](const char* key, int value, int lo, int hi) {
        if (value < lo || value > hi)
            throw UsageError("settings " + path.string() + ": " + key + " is " + std::to_string(value) + ", expected " +
                             std::to_string(lo) + ".." + std::to_string(hi));
    };
    requireRange("output.width", settings.output.width, 1, lit::cli::kMaxImageSide);
    requireRange("output.height", settings.output.height, 1, lit::cli::kMaxImageSide);
    requireRange("gi.voxelResolution", settings.gi.voxelResolution, 64, 512);
    if ((settings.gi.voxelResolution & (settings.gi.voxelResolution - 1)) != 0)
        throw UsageError("settings " + path.string() + ": gi.voxelResolution is " +
                         std::to_string(settings.gi.voxelResolution) +
                         ", expected a power of two (64, 128, 256 or 512)");
    requireRange("shadows.mapSize", settings.shadows.mapSize, 16, lit::cli::kMaxImageSide);
    const auto clampWarn = [&](const char* key, auto& value, auto lo, auto hi) {
        using T = std::decay_t<decltype(value)>;
        const T clamped = std::clamp(value, static_cast<T>(lo), static_cast<T>(hi));
        if (!(clamped == value)) {  // also catches NaN, which compares unequal
            std::ostringstream line;
            line << name << ": " << key << " " << value << " is outside " << lo << ".." << hi << "; using " << clamped;
            log.warning(line.str());
            value = clamped;
        }
    };
    clampWarn("indirect.specularSamples", settings.indirect.specularSamples, 1, 8);
    clampWarn("debug.voxelSliceAxis", settings.debug.voxelSliceAxis, 0, 2);
    clampWarn("debug.voxelSlice", settings.debug.voxelSlice, 0.0f, 1.0f);
    clampWarn("output.exposureEv", settings.output.exposureEv, -10.0f, 20.0f);
    clampWarn("gi.coneStepScale", settings.gi.coneStepScale, 0.05f, 4.0f);
    clampWarn("gi.maxTraceDistance", settings.gi.maxTraceDistance, 0.0f, 2.0f);
}

// The memory a render at this size needs, estimated before any of it is allocated: 64 bytes per
// pixel (G-buffer, lighting and output targets plus the read-back copies; a 16384² render
// measured 17.5 GB, issue #14) and 21 bytes per voxel (RGBA16F radiance with its mip chain plus
// the RGBA8 albedo, normal and emission volumes).
std::uint64_t estimatedRenderBytes(const lit::RenderSettings& settings) {
    const auto pixels =
        static_cast<std::uint64_t>(settings.output.width) * static_cast<std::uint64_t>(settings.output.height);
    const auto side = static_cast<std::uint64_t>(settings.gi.voxelResolution);
    return pixels * 64 + (settings.gi.enabled ? side * side * side * 21 : 0);
}

// Bytes the GL can still give: system memory for a software rasterizer (llvmpipe renders into
// RAM), free video memory where the driver says (NVX_gpu_memory_info); 0 = unknown.
std::uint64_t availableRenderBytes() {
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos) {
        std::ifstream meminfo("/proc/meminfo");
        std::string key;
        std::uint64_t kib = 0;
        std::string unit;
        while (meminfo >> key >> kib >> unit)
            if (key == "MemAvailable:") return kib * 1024;
        return 0;
    }
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kib = 0;
        glGetIntegerv(0x9049, &kib);  // GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
        return static_cast<std::uint64_t>(std::max(kib, 0)) * 1024;
    }
    return 0;
}

// Sizes checked against this GL's limits and memory before anything is rendered (exit 2).
void checkRenderLimits(const lit::RenderSettings& settings) {
    GLint maxTexture = 0, maxRenderbuffer = 0, maxWidth = 0, maxHeight = 0, max3d = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxHeight);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    const int maxSide = std::min({maxTexture, maxRenderbuffer, maxWidth, maxHeight});
    if (settings.output.width > maxSide || settings.output.height > maxSide)
        throw UsageError("the size " + std::to_string(settings.output.width) + "x" +
                         std::to_string(settings.output.height) + " is larger than this GL can render (" +
                         std::to_string(maxSide) + " per side)");
    // The voxel irradiance volumes are N × N × 2N (InjectPass).
    if (settings.gi.enabled && 2 * settings.gi.voxelResolution > max3d)
        throw UsageError(std::to_string(settings.gi.voxelResolution) +
                         "^3 voxels are more than this GL's 3D textures hold (" + std::to_string(max3d) +
                         " per side, 2N needed)");
    const std::uint64_t needed = estimatedRenderBytes(settings);
    std::uint64_t available = availableRenderBytes();
    // $LIT_MAX_RENDER_MB caps it further (a shared machine, a CI runner).
    if (const char* cap = std::getenv("LIT_MAX_RENDER_MB"); cap && *cap) {
        const std::uint64_t capBytes = std::strtoull(cap, nullptr, 10) * 1'000'000ull;
        if (capBytes > 0 && (available == 0 || capBytes < available)) available = capBytes;
    }
    if (available > 0 && needed > available)
        throw UsageError("a " + std::to_string(settings.output.width) + "x" + std::to_string(settings.output.height) +
                         " render with " + std::to_string(settings.gi.voxelResolution) + "^3 voxels needs about " +
                         std::to_string(needed / 1'000'000) + " MB, more than the " +
                         std::to_string(available / 1'000'000) + " MB available; use a smaller --size or --voxels");
}

// An output folder is checked (created, and a file created and removed in it) before the render,
// so a run that cannot write its result fails at once, not after the work (exit 2).
void checkWritableFolder(const fs::path& file, const char* what) {
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw UsageError(std::string(what) + " " + file.string() + " is a folder, not a file");
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder, ec))
        throw UsageError(std::string("cannot create the folder ") + folder.string() + " for " + what + " " + file.string() +
                         (ec ? " (" + ec.message() + ")" : std::string(" (a file is in the way)")));
    const fs::path probe = folder / (".lit-render-probe-" + std::to_string(::getpid()));
    {
        std::ofstream out(probe, std::ios::binary);
        if (!out) throw UsageError(std::string("cannot write ") + what + " " + file.string() + ": the folder " + folder.string() + " is not writable");
    }
    fs::remove(probe, ec);
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
    std::printf("%dx%d, GI %s: lowest FPS %.2f, highest FPS %.2f, mean frame %.3f ms (%.2f FPS)\n",
                settings.output.width, settings.output.height, settings.gi.enabled ? "on" : "off",
                frame.max > 0 ? 1000.0 / frame.max : 0.0, frame.min > 0 ? 1000.0 / frame.min : 0.0, frame.mean,
                frame.mean > 0 ? 1000.0 / frame.mean : 0.0);
    // Draws of the last frame's culled views (the camera; shadow views only when they were redrawn).
    std::printf("draws: %d of %d submitted (culling %s), culling %.3f ms CPU (mean), %zu triangles\n",
                lastFrame.drawsSubmitted, lastFrame.drawsTotal, settings.output.frustumCulling ? "on" : "off",
                summarize(bench.cullMs).mean, lastFrame.triangles);
    if (bench.mipmaps.computeMinMs > 0.0)
        std::printf("radiance mipmaps (%s): compute %.3f ms, glGenerateTextureMipmap %.3f ms (min of runs): "
                    "compute is %.2fx as fast\n",
                    bench.mipmaps.rgba8 ? "RGBA8" : "RGBA16F", bench.mipmaps.computeMinMs, bench.mipmaps.generateMinMs,
                    bench.mipmaps.speedup());
    const lit::MipmapTimings& m = bench.mipmaps;
    if (m.occupiedMinMs > 0.0) {
        // Interleaved rounds: the whole grid, then the occupied parents, back to back.
        for (std::size_t i = 0; i < m.occupiedRunsMs.size() && i < m.computeRunsMs.size(); ++i)
            std::printf("mipmap round %zu%s: whole grid %.3f ms | occupied parents %.3f ms | %.2fx\n", i + 1,
                        m.anisotropic ? " (with directional chains)" : "", m.computeRunsMs[i], m.occupiedRunsMs[i],
                        m.occupiedRunsMs[i] > 0.0 ? m.computeRunsMs[i] / m.occupiedRunsMs[i] : 0.0);
        std::printf("radiance mipmaps over occupied parents: %.3f ms, whole grid %.3f ms (min of runs): %.2fx as fast\n",
                    m.occupiedMinMs, m.computeMinMs, m.occupiedSpeedup());
    }
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
            {"width", settings.output.width},
            {"height", settings.output.height},
            {"view", std::string(lit::toString(settings.debug.view))},
            {"gi", settings.gi.enabled},
            {"voxelResolution", settings.gi.voxelResolution},
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
              {"speedup", bench.mipmaps.speedup()},
              {"occupiedMinMs", bench.mipmaps.occupiedMinMs},
              {"occupiedMedianMs", bench.mipmaps.occupiedMedianMs},
              {"occupiedSpeedup", bench.mipmaps.occupiedSpeedup()},
              {"anisotropic", bench.mipmaps.anisotropic}}},
            {"triangles", stats.triangles},
            {"drawCalls", stats.drawCalls},
            {"frustumCulling", settings.output.frustumCulling},
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

// Load progress on stderr, for long loads only (LoadProgressLines.h says when a line is printed),
// with the GPU upload as its own stage. Uses the loader's progress callback
// (GltfLoadOptions::progress), which the editor's progress window reads as well.
class LoadProgressPrinter {
public:
    void operator()(const lit::LoadProgress& p) {
        if (const auto line = lines_(p, secondsSince(start_))) {
            std::fprintf(stderr, "%s\n", line->c_str());
            std::fflush(stderr);
        }
    }
    void stage(const char* name) { (*this)(lit::LoadProgress{name, 0, 1}); }
    void done(const char* name) { (*this)(lit::LoadProgress{name, 1, 1}); }

private:
    Clock::time_point start_ = Clock::now();
    lit::cli::LoadProgressLines lines_;
};

// The camera path --path names: a .json file, or a camera animation in the scene file. Runs
// before any GL work so a bad path is reported at once.
lit::CameraPath loadPath(const Options& options) {
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
                if (names.empty()) message += "the scene has none";
                else message += "its camera animations are:";
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

// Temporal stability along a camera path (--bench-path): the mean absolute luminance change from
// one frame to the next of pixels whose surface did not move, relative to the frame's mean
// luminance. Each pixel's world point (from its depth) is projected into the previous frame; it
// counts when the previous frame saw the same point there (within 1 % of its distance, at all
// four bilinear taps, so silhouettes are left out), and is compared with the previous frame's
// luminance interpolated at that spot.
class FlickerMeter {
public:
    void add(const lit::CameraView& camera, int width, int height, std::vector<float> rgb, std::vector<float> depth) {
        Frame current{camera.projection * camera.view, camera.position, std::move(depth), {}};
        current.luminance.resize(current.depth.size());
        for (std::size_t i = 0; i < current.luminance.size(); ++i)
            current.luminance[i] = 0.2126f * rgb[3 * i] + 0.7152f * rgb[3 * i + 1] + 0.0722f * rgb[3 * i + 2];
        if (previous_) measure(*previous_, current, width, height);
        previous_ = std::move(current);
    }
    // Mean over the frame pairs measured, and the largest pair; 0 before two frames.
    double mean() const { return pairs_.empty() ? 0.0 : std::accumulate(pairs_.begin(), pairs_.end(), 0.0) / pairs_.size(); }
    double max() const { return pairs_.empty() ? 0.0 : *std::max_element(pairs_.begin(), pairs_.end()); }
    std::size_t pairs() const { return pairs_.size(); }

private:
    struct Frame {
        glm::mat4 viewProjection;
        glm::vec3 position;
        std::vector<float> depth, luminance;
    };
    static glm::vec3 world(const Frame& f, const glm::mat4& inverse, int width, int height, int x, int y) {
        const float d = f.depth[static_cast<std::size_t>(y) * width + x];
        const glm::vec4 w = inverse * glm::vec4((x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f,
                                                d * 2.0f - 1.0f, 1.0f);
        return glm::vec3(w) / w.w;
    }
    void measure(const Frame& prev, const Frame& cur, int width, int height) {
        const glm::mat4 curInverse = glm::inverse(cur.viewProjection), prevInverse = glm::inverse(prev.viewProjection);
        double change = 0.0, total = 0.0;
        std::size_t counted = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                if (cur.depth[i] >= 1.0f) continue;
                const glm::vec3 p = world(cur, curInverse, width, height, x, y);
                const glm::vec4 clip = prev.viewProjection * glm::vec4(p, 1.0f);
                if (clip.w <= 0.0f) continue;
                const float px = (clip.x / clip.w * 0.5f + 0.5f) * width - 0.5f;
                const float py = (clip.y / clip.w * 0.5f + 0.5f) * height - 0.5f;
                const int x0 = static_cast<int>(std::floor(px)), y0 = static_cast<int>(std::floor(py));
                if (x0 < 0 || y0 < 0 || x0 + 1 >= width || y0 + 1 >= height) continue;
                const float tolerance = 0.01f * glm::length(p - prev.position);
                bool same = true;
                float value = 0.0f;
                for (int t = 0; t < 4 && same; ++t) {
                    const int tx = x0 + (t & 1), ty = y0 + (t >> 1);
                    if (prev.depth[static_cast<std::size_t>(ty) * width + tx] >= 1.0f) { same = false; break; }
                    same = glm::length(world(prev, prevInverse, width, height, tx, ty) - p) <=
                           tolerance + 2.0f * glm::length(p - prev.position) / height;  // + a pixel's footprint
                    const float wx = (t & 1) ? px - x0 : 1.0f - (px - x0), wy = (t >> 1) ? py - y0 : 1.0f - (py - y0);
                    value += wx * wy * prev.luminance[static_cast<std::size_t>(ty) * width + tx];
                }
                if (!same) continue;
                change += std::abs(static_cast<double>(cur.luminance[i]) - value);
                ++counted;
            }
        for (float l : cur.luminance) total += l;
        const double mean = total / static_cast<double>(cur.luminance.size());
        if (counted > 0 && mean > 0.0) pairs_.push_back(change / static_cast<double>(counted) / mean);
    }
    std::optional<Frame> previous_;
    std::vector<double> pairs_;
};

// --path: renders every frame of the path (to PNGs with --frames-out) and times them (--bench-path).
int runPath(const Options& options, const lit::CameraPath& path, const lit::Scene& scene, lit::Renderer& renderer,
            const lit::RenderSettings& settings, const lit::HeadlessContext& context,
            const std::function<void()>& requireNoGlErrors) {
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

    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    const lit::Aabb bounds = scene.worldBounds();
    const auto viewAt = [&](double t) { return *path.view(t, aspect, bounds); };

    const Clock::time_point renderStart = Clock::now();
    if (options.benchPath) {
        // One untimed warm-up frame: voxelization, shader and driver warm-up happen once per
        // scene, not per frame of a fly-through.
        renderer.render(scene, viewAt(times.front()), settings, lit::cli::giBudgetFor(options));
        renderer.profiler().flush();
        glFinish();
    }
    BenchResult bench;
    std::map<std::string, std::size_t> passIndex;
    FlickerMeter flicker;
    Progress progress(times.size());
    std::vector<std::uint8_t> rgba;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const lit::CameraView view = viewAt(times[i]);
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, view, settings, lit::cli::giBudgetFor(options));
        if (options.benchPath) {
            recordBenchFrame(bench, passIndex, renderer, frameStart);  // timed before the read-backs below
            flicker.add(view, settings.output.width, settings.output.height, renderer.readHdrRgb(),
                        renderer.readDepth());
        }
        if (!options.framesOut.empty()) {
            requireNoGlErrors();  // before each frame is written: no wrong frame on disk
            char name[32];
            std::snprintf(name, sizeof name, "frame_%05zu.png", i);
            rgba = renderer.readOutputRgba8();
            lit::writePng(options.framesOut / name, settings.output.width, settings.output.height, rgba);
        }
        progress.update(i + 1);
    }
    glFinish();
    progress.finish();
    requireNoGlErrors();

    const double seconds = secondsSince(renderStart);
    if (options.benchPath) {
        std::printf("camera path %s: %zu frames at %g fps over %.3f s\n", options.path->c_str(), times.size(),
                    options.pathFps(), static_cast<double>(path.duration()));
        printBench(bench, settings, renderer.stats());
        std::printf("flicker: %.3f %% mean (%.3f %% worst of %zu frame pairs): mean |change| of pixels whose surface did "
                    "not move, relative to the mean luminance\n",
                    100.0 * flicker.mean(), 100.0 * flicker.max(), flicker.pairs());
        if (!options.benchJson.empty()) {
            nlohmann::ordered_json json = benchJson(bench, options, settings, context.description(), renderer.stats());
            json["flickerPercent"] = 100.0 * flicker.mean();
            json["flickerWorstPercent"] = 100.0 * flicker.max();
            json["path"] = *options.path;
            json["pathFps"] = options.pathFps();
            json["pathSeconds"] = path.duration();
            writeTextFileAtomic(options.benchJson, json.dump(2) + "\n");
            std::printf("wrote %s\n", options.benchJson.string().c_str());
        }
    }
    if (!options.framesOut.empty())
        std::printf("wrote %zu frames to %s (%dx%d, %g fps, %.2f s)\n", times.size(),
                    options.framesOut.string().c_str(), settings.output.width, settings.output.height,
                    options.pathFps(), seconds);
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

// --compare REF.hdr [--difference FILE.png]: the image's figures against a reference image of the
// same size (typically `--reference --hdr`), and the editor's Difference view as a PNG.
// `truth` was read, and its size checked against the render's, before rendering (run()).
void compareWithReference(const Options& options, const lit::HdrImage& truth, const std::vector<float>& rgb) {
    const lit::reference::ImageComparison figures = lit::reference::compareImages(rgb, truth.rgb);
    std::printf("compare with %s: mean luminance %.5g against %.5g (ratio %.3f), RMSE %.1f %% of the reference's mean\n",
                options.compare.string().c_str(), figures.testMean, figures.referenceMean, figures.meanRatio(),
                100.0 * figures.relativeRmse);
    if (options.difference.empty()) return;
    const float maxError = options.maxError.value_or(lit::cli::kDefaultMaxError);
    // The ramp is display colour: encoded as sRGB, as the editor's blit does.
    lit::writePng(options.difference, truth.width, truth.height,
                  lit::reference::displayColoursToRgba8(lit::reference::relativeErrorColours(rgb, truth.rgb, maxError)));
    std::printf("wrote %s (relative error, ramp ends at ±%.0f %%)\n", options.difference.string().c_str(), 100.0 * maxError);
}

// --reference: path-trace the still on the CPU and write the same images as the rasterizer.
int runReference(const Options& options, const lit::Scene& scene, int cameraIndex, const lit::RenderSettings& settings,
                 const lit::HdrImage* compareTruth, lit::Log& log) {
    const Clock::time_point buildStart = Clock::now();
    // A scene without lights is lit by the rasterizer's default sun (scene/Sky.h); give the
    // reference the same sun as a light of its own copy of the scene.
    lit::Scene withSun = scene;
    lit::addDefaultSun(withSun, settings);
    const lit::reference::ReferenceScene referenceScene(withSun, log);
    const double buildSeconds = secondsSince(buildStart);
    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    const lit::CameraView camera = lit::sceneCameraView(scene, cameraIndex, aspect);

    lit::reference::ReferenceSettings reference;
    // Without --bounces the reference follows --gi and the settings' bounces: the same light paths
    // as the VCT, or direct light only.
    reference.bounces = options.bounces.value_or(settings.gi.enabled ? settings.gi.bounces : 0);
    reference.seed = options.seed.value_or(0);
    // Rays that leave the scene see the same sky as the rasterizer's background and cones.
    std::string skyError;
    reference.environment = lit::makeSkyFunction(scene, settings, &skyError);
    if (!skyError.empty()) log.error(skyError + "; using the gradient sky");
    lit::reference::PathTracer tracer(referenceScene, camera, settings.output.width, settings.output.height, reference);

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
    std::printf(
        "reference: %dx%d, %u spp (min per pixel), bounces %s, seed %llu: %.1f M rays in %.2f s = %.2f Mrays/s "
        "on %d threads (scene build %.2f s, %zu triangles)\n",
        settings.output.width, settings.output.height, tracer.image().minSamples(), bounces.c_str(),
        static_cast<unsigned long long>(reference.seed), static_cast<double>(tracer.raysTraced()) * 1e-6, seconds,
        seconds > 0.0 ? static_cast<double>(tracer.raysTraced()) / seconds * 1e-6 : 0.0,
        tbb::info::default_concurrency(), buildSeconds, referenceScene.triangleCount());

    const std::vector<float> rgb = tracer.image().viewRgb(settings.debug.view, settings);
    std::string written;
    if (!options.out.empty()) {
        lit::writePng(options.out, settings.output.width, settings.output.height,
                      lit::reference::toneMapToRgba8(rgb, settings.output.exposureScale()));
        written = options.out.string();
    }
    if (!options.hdr.empty()) {
        lit::writeHdr(options.hdr, settings.output.width, settings.output.height, rgb);
        written += (written.empty() ? "" : " and ") + options.hdr.string();
    }
    if (!written.empty()) std::printf("wrote %s\n", written.c_str());
    if (compareTruth) compareWithReference(options, *compareTruth, rgb);
    if (interrupted) {
        std::fprintf(stderr, "lit-render: interrupted after %d of %d samples per pixel; the image so far was written\n",
                     tracer.samplesDone(), spp);
        return 130;  // the shell's status for a SIGINT
    }
    return 0;
}

// --bench-gi-updates: a light edit (re-inject + mipmaps; the voxels stay) against a full
// re-voxelization (voxelize + inject + mipmaps), interleaved, GPU times from the profiler; both
// with the bounce passes and the cached GI mode's voxel irradiance pass and filter that follow
// every edit (the whole list in the edit's frame unless --gi-update-per-frame; else only
// that frame's share). Both also re-render the shadow maps (the light or geometry changed); that
// is printed separately.
void benchGiUpdates(int rounds, lit::Scene& scene, const lit::CameraView& camera, lit::Renderer& renderer,
                    const lit::RenderSettings& settings, const lit::GiBudget& budget) {
    const auto passMs = [&](const char* name) {
        for (const lit::PassTiming& t : renderer.profiler().timings())
            if (t.name == name && t.ran) return t.gpuMs;
        return 0.0;
    };
    std::printf(
        "GI updates at %d³, %u occupied voxels (%.2f %% of the grid), %d rounds:\n", settings.gi.voxelResolution,
        renderer.stats().occupiedVoxels,
        100.0 * renderer.stats().occupiedVoxels / std::pow(static_cast<double>(settings.gi.voxelResolution), 3.0),
        rounds);
    // The cached GI mode's irradiance pass and filter (and any bounces) follow every edit: they
    // belong to its cost (0 in the modes without them).
    const auto cachedMs = [&] { return passMs("bounces") + passMs("voxel irradiance") + passMs("voxel irradiance filter"); };
    // An update spread over frames (--gi-update-per-frame, as the editor runs it) goes on
    // after the timed frame: the next edit is timed once it is done, as a user's next edit usually
    // comes after the last one's light settled (and only then is the voxel rays' hit cache
    // recorded, which the light edits of the editor replay). Returns the frames it took and their
    // GI passes' GPU ms (the time to the final light is those frames).
    struct Settle {
        int frames = 0;
        double giMs = 0.0;
    };
    const auto settle = [&] {
        constexpr int kMaxFrames = 20000;
        Settle done;
        while (renderer.stats().giUpdateDone < 1.0f && done.frames < kMaxFrames) {
            renderer.render(scene, camera, settings, budget);
            renderer.profiler().flush();
            ++done.frames;
            done.giMs += cachedMs();
        }
        return done;
    };
    settle();
    std::vector<double> ratios;
    for (int round = 1; round <= rounds; ++round) {
        // A: light edit. The first light's intensity changes by a part in 10⁴ and back next round.
        if (!scene.lights.empty()) scene.lights[0].intensity *= (round % 2) ? 1.0001f : 1.0f / 1.0001f;
        ++scene.lightRevision;
        renderer.render(scene, camera, settings, budget);
        renderer.profiler().flush();
        const double editInject = passMs("inject"), editMipmap = passMs("mipmap"), editCached = cachedMs();
        const double edit = editInject + editMipmap + editCached, editShadow = passMs("shadow");
        const Settle editRest = settle();
        // B: geometry edit without moving anything: the volume is voxelized again.
        ++scene.geometryRevision;
        renderer.render(scene, camera, settings, budget);
        renderer.profiler().flush();
        const double lists = passMs("mip lists"), revoxelizeCached = cachedMs();
        const double revoxelize =
                         passMs("voxelize") + lists + passMs("inject") + passMs("mipmap") + revoxelizeCached,
                     fullShadow = passMs("shadow");
        const Settle revoxelizeRest = settle();
        ratios.push_back(edit / revoxelize);
        std::printf("gi-update round %d: light edit %.1f ms (inject %.1f + mipmap %.1f + bounces/voxel irradiance %.1f) | "
                    "re-voxelize %.1f ms (voxelize + mip lists %.1f + inject + mipmap + bounces/voxel irradiance %.1f) | "
                    "ratio %.3f | shadow maps %.1f / %.1f ms\n",
                    round, edit, editInject, editMipmap, editCached, revoxelize, lists, revoxelizeCached,
                    edit / revoxelize, editShadow, fullShadow);
        if (editRest.frames > 0 || revoxelizeRest.frames > 0)
            std::printf("gi-update round %d, spread over frames: the light edit's update took %d more frames (GI passes "
                        "%.1f ms), the re-voxelization's %d (%.1f ms)\n",
                        round, editRest.frames, editRest.giMs, revoxelizeRest.frames, revoxelizeRest.giMs);
    }
    std::sort(ratios.begin(), ratios.end());
    std::printf("gi-update median ratio (light edit / re-voxelize): %.3f\n", ratios[ratios.size() / 2]);
}

int run(const Options& options) {
    lit::Log log;

    // Everything that needs no GL comes first, so a bad file or camera is reported at once.
    lit::RenderSettings settings;
    if (!options.settings.empty()) {
        const std::string text = readTextFile(options.settings);
        try {
            settings = lit::renderSettingsFromJson(text);
        } catch (const std::exception& e) {
            throw UsageError("cannot use settings " + options.settings.string() + ": " + e.what());
        }
        checkSettingsFile(options.settings, text, settings, log);
    }
    settings = lit::cli::applyOptions(options, settings);
    // The reference is read now, before a render that may take minutes, so a wrong name or size
    // fails at once.
    std::optional<lit::HdrImage> compareTruth;
    if (!options.compare.empty()) {
        try {
            compareTruth = lit::readHdr(options.compare);
        } catch (const std::exception& e) {
            throw UsageError(std::string("--compare: ") + e.what());
        }
        const lit::HdrImage& truth = *compareTruth;
        if (truth.width != settings.output.width || truth.height != settings.output.height)
            throw UsageError(options.compare.string() + " is " + std::to_string(truth.width) + "x" +
                             std::to_string(truth.height) + ", the image will be " +
                             std::to_string(settings.output.width) + "x" + std::to_string(settings.output.height) +
                             ": render both at one --size");
    }
    for (const fs::path* file : {&options.out, &options.hdr, &options.benchJson, &options.difference})
        if (!file->empty()) checkWritableFolder(*file, "the output");
    if (!options.framesOut.empty()) checkWritableFolder(options.framesOut / "frame_00000.png", "the frames");

    lit::Scene scene;
    LoadProgressPrinter loadProgress;
    try {
        lit::GltfLoadOptions loadOptions;
        loadOptions.limits.allowExternalUris = options.allowExternalUris;
        loadOptions.progress = [&](const lit::LoadProgress& p) { loadProgress(p); };
        scene = lit::loadGltf(options.scene, log, loadOptions);  // logs the summary line (meshes, triangles, MB, ms)
    } catch (const std::exception& e) {
        // The loader's messages usually start with the path already; say it once.
        std::string reason = e.what();
        const std::string prefix = options.scene.string() + ": ";
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw UsageError("cannot load " + options.scene.string() + ": " + reason);
    }
    lit::addDefaultCamera(scene, log);
    const int cameraIndex = lit::cli::resolveCamera(options, scene);
    if (options.reference) return runReference(options, scene, cameraIndex, settings, compareTruth ? &*compareTruth : nullptr, log);
    const std::optional<lit::CameraPath> path = options.path ? std::optional(loadPath(options)) : std::nullopt;

    lit::HeadlessContext context;
    lit::gl::requireCapabilities();
    checkRenderLimits(settings);
    // GL errors (debug output of high severity) are counted: a render that had any exits 1 and
    // writes nothing, instead of a wrong image with exit 0.
    std::size_t glErrors = 0;
    log.setSink([&glErrors](const lit::LogMessage& m) {
        if (m.level == lit::LogLevel::Error && m.text.starts_with("GL ")) ++glErrors;
        if (m.level == lit::LogLevel::Info)
            std::fprintf(stderr, "lit: %s\n", m.text.c_str());
        else
            std::fprintf(stderr, "lit: %s: %s\n", lit::toString(m.level), m.text.c_str());
    });
    lit::gl::installDebugOutput(log);
    const auto requireNoGlErrors = [&glErrors] {
        glFinish();
        if (glErrors > 0)
            throw RunError(std::to_string(glErrors) + " GL error" + (glErrors == 1 ? "" : "s") +
                           " during the render (see above); nothing was written");
    };
    const fs::path shaderRoot = lit::defaultShaderRoot();
    log.info("shaders from " + shaderRoot.string());  // installed, $LIT_SHADER_DIR or source tree
    lit::Renderer renderer(shaderRoot, log);
    loadProgress.stage("upload");
    renderer.setScene(scene);
    loadProgress.done("upload");
    if (path) return runPath(options, *path, scene, renderer, settings, context, requireNoGlErrors);

    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    const lit::CameraView camera = lit::sceneCameraView(scene, cameraIndex, aspect);

    const Clock::time_point renderStart = Clock::now();
    BenchResult bench;
    std::map<std::string, std::size_t> passIndex;
    // With temporal accumulation a still renders until the history is full, so it shows the
    // converged image (docs/GI.md); --frames or --bench choose the count themselves.
    const int frames = settings.indirect.temporalAccumulation && !options.frames && options.benchFrames == 0
                           ? std::max(settings.indirect.temporalMaxFrames, 1)
                           : options.frameCount();
    for (int frame = 0; frame < frames; ++frame) {
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, camera, settings, lit::cli::giBudgetFor(options));
        if (options.benchFrames > 0) recordBenchFrame(bench, passIndex, renderer, frameStart);
    }
    lit::gl::injectGlErrorIfRequested();  // LIT_TEST_GL_ERROR=1: the test of the check below
    glFinish();
    if (settings.output.autoExposure)
        std::printf("auto exposure: %+.2f EV\n", static_cast<double>(renderer.exposureEv(settings)));
    if (options.benchFrames > 0 && settings.gi.enabled) bench.mipmaps = renderer.benchmarkMipmaps(7);
    if (options.giUpdateRounds > 0 && settings.gi.enabled)
        benchGiUpdates(options.giUpdateRounds, scene, camera, renderer, settings, lit::cli::giBudgetFor(options));

    if (options.benchFrames > 0) {
        printBench(bench, settings, renderer.stats());
        if (!options.benchJson.empty()) {
            writeTextFileAtomic(options.benchJson,
                                benchJson(bench, options, settings, context.description(), renderer.stats()).dump(2) + "\n");
            std::printf("wrote %s\n", options.benchJson.string().c_str());
        }
    }

    requireNoGlErrors();
    std::string written;
    if (!options.out.empty()) {
        const std::vector<std::uint8_t> rgba = renderer.readOutputRgba8();
        lit::writePng(options.out, settings.output.width, settings.output.height, rgba);
        written = options.out.string();
    }
    if (!options.hdr.empty() || compareTruth) {
        const std::vector<float> rgb = renderer.readHdrRgb();
        if (!options.hdr.empty()) {
            lit::writeHdr(options.hdr, settings.output.width, settings.output.height, rgb);
            written += (written.empty() ? "" : " and ") + options.hdr.string();
        }
        if (compareTruth) compareWithReference(options, *compareTruth, rgb);
    }
    if (!written.empty())
        std::printf("wrote %s (%d\u00d7%d, %.2f s)\n", written.c_str(), settings.output.width, settings.output.height,
                    secondsSince(renderStart));
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
