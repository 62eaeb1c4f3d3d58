// lit-render — renders a glTF scene headless (EGL, no window or X server) to PNG/HDR, or
// benchmarks it. Exit status: 0 success, 1 runtime failure, 2 bad command line.

#include "Options.h"

#include "Log.h"
#include "Renderer.h"
#include "RenderSettings.h"
#include "context/HeadlessContext.h"
#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "image/ImageIO.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
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
};

void printBench(const BenchResult& bench, const lit::RenderSettings& settings) {
    const auto row = [](const std::string& name, const Summary& s, std::size_t frames) {
        std::printf("%-28s %10.3f %10.3f %10.3f %10.3f %8zu\n", name.c_str(), s.min, s.median, s.mean, s.max, frames);
    };
    std::printf("%-28s %10s %10s %10s %10s %8s\n", "pass (GPU ms)", "min", "median", "mean", "max", "frames");
    for (const PassSamples& pass : bench.passes) row(pass.name, summarize(pass.gpuMs), pass.gpuMs.size());
    const Summary frame = summarize(bench.frameMs);
    row("frame (wall ms)", frame, bench.frameMs.size());
    row("frame (CPU issue ms)", summarize(bench.cpuFrameMs), bench.cpuFrameMs.size());
    std::printf("%dx%d: mean frame %.3f ms, %.2f FPS\n", settings.width, settings.height, frame.mean,
                frame.mean > 0 ? 1000.0 / frame.mean : 0.0);
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
            {"triangles", stats.triangles},
            {"drawCalls", stats.drawCalls},
            {"passes", passes}};
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
    try {
        scene = lit::loadGltf(options.scene, log);
    } catch (const std::exception& e) {
        // The loader's messages usually start with the path already; say it once.
        std::string reason = e.what();
        const std::string prefix = options.scene.string() + ": ";
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw RunError("cannot load " + options.scene.string() + ": " + reason);
    }
    const int cameraIndex = lit::cli::resolveCamera(options, scene);

    lit::HeadlessContext context;
    lit::gl::requireCapabilities();
    lit::gl::installDebugOutput(log);
    lit::Renderer renderer(lit::defaultShaderRoot(), log);
    renderer.setScene(scene);

    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const lit::CameraView camera = lit::sceneCameraView(scene, cameraIndex, aspect);

    const Clock::time_point renderStart = Clock::now();
    BenchResult bench;
    std::map<std::string, std::size_t> passIndex;
    for (int frame = 0; frame < options.frameCount(); ++frame) {
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, camera, settings);
        if (options.benchFrames == 0) continue;
        // Waiting for this frame's queries serialises CPU and GPU: the wall time per frame is
        // then the true cost of a frame, and the pass timings belong to this very frame.
        renderer.profiler().flush();
        bench.frameMs.push_back(secondsSince(frameStart) * 1000.0);
        bench.cpuFrameMs.push_back(renderer.profiler().lastCpuFrameMs());
        for (const lit::PassTiming& timing : renderer.profiler().timings()) {
            auto [it, inserted] = passIndex.try_emplace(timing.name, bench.passes.size());
            if (inserted) bench.passes.push_back({timing.name, {}, {}});
            if (!timing.ran) continue;
            bench.passes[it->second].gpuMs.push_back(timing.gpuMs);
            bench.passes[it->second].cpuMs.push_back(timing.cpuMs);
        }
    }
    glFinish();

    if (options.benchFrames > 0) {
        printBench(bench, settings);
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
