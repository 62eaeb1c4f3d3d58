#include "Bench.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>

#include "Renderer.h"

namespace lit::cli {

namespace {

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

void writeTextFileAtomic(const std::filesystem::path& path, const std::string& text) {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    const std::filesystem::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out.flush()) throw RunError("cannot write " + path.string());
    }
    std::filesystem::rename(tmp, path);
}

}  // namespace

void recordBenchFrame(BenchResult& bench, Renderer& renderer, Clock::time_point frameStart) {
    renderer.profiler().flush();
    bench.frameMs.push_back(secondsSince(frameStart) * 1000.0);
    bench.cpuFrameMs.push_back(renderer.profiler().lastCpuFrameMs());
    bench.cullMs.push_back(renderer.stats().cullMs);
    bench.framePasses.emplace_back();
    for (const lit::PassTiming& timing : renderer.profiler().timings()) {
        auto [it, inserted] = bench.passIndex.try_emplace(timing.name, bench.passes.size());
        if (inserted) bench.passes.push_back({timing.name, {}, {}});
        if (!timing.ran) continue;
        bench.passes[it->second].gpuMs.push_back(timing.gpuMs);
        bench.passes[it->second].cpuMs.push_back(timing.cpuMs);
        bench.framePasses.back().emplace_back(timing.name, timing.gpuMs);
    }
}

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
    if (settings.gi.enabled) {
        // The GI's GPU memory, per volume: the scene's, then each near level's.
        constexpr double kMiB = 1024.0 * 1024.0;
        std::size_t nearBytes = 0;
        for (const lit::FrameStats::NearLevelMemory& level : lastFrame.nearLevels) nearBytes += level.bytes;
        std::printf("GI memory: %.1f MiB: scene volume %.1f MiB", static_cast<double>(lastFrame.voxelBytes) / kMiB,
                    static_cast<double>(lastFrame.voxelBytes - nearBytes) / kMiB);
        for (const lit::FrameStats::NearLevelMemory& level : lastFrame.nearLevels)
            std::printf(", %g m near level %.1f MiB", static_cast<double>(level.side),
                        static_cast<double>(level.bytes) / kMiB);
        std::printf("\n");
    }
    const lit::MipmapTimings& m = bench.mipmaps;
    // Like for like: one isotropic chain against glGenerateTextureMipmap's one chain over the
    // whole grid; the directional chains (anisotropic voxels) on a line of their own.
    if (m.computeMinMs > 0.0)
        std::printf("radiance mipmaps (%s, isotropic chain, whole grid): compute %.3f ms, glGenerateTextureMipmap "
                    "%.3f ms (min of runs): compute is %.2fx as fast\n",
                    m.rgba8 ? "RGBA8" : "RGBA16F", m.computeMinMs, m.generateMinMs, m.speedup());
    if (m.occupiedMinMs > 0.0) {
        // Interleaved rounds: the whole grid, then the occupied parents, back to back.
        for (std::size_t i = 0; i < m.occupiedRunsMs.size() && i < m.computeRunsMs.size(); ++i)
            std::printf("mipmap round %zu: whole grid %.3f ms | occupied parents %.3f ms | %.2fx\n", i + 1,
                        m.computeRunsMs[i], m.occupiedRunsMs[i],
                        m.occupiedRunsMs[i] > 0.0 ? m.computeRunsMs[i] / m.occupiedRunsMs[i] : 0.0);
        std::printf(
            "radiance mipmaps over occupied parents: %.3f ms, whole grid %.3f ms (min of runs): %.2fx as fast\n",
            m.occupiedMinMs, m.computeMinMs, m.occupiedSpeedup());
    }
    if (m.anisotropic && m.directionalMinMs > 0.0)
        std::printf("directional mipmaps (six chains, anisotropic voxels): whole grid %.3f ms, occupied parents "
                    "%.3f ms (min of runs)\n",
                    m.directionalMinMs, m.directionalOccupiedMinMs);
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
    nlohmann::ordered_json frames = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < bench.frameMs.size(); ++i) {
        nlohmann::ordered_json gpu = nlohmann::ordered_json::object();
        if (i < bench.framePasses.size())
            for (const auto& [name, ms] : bench.framePasses[i]) gpu[name] = ms;
        frames.push_back({{"ms", bench.frameMs[i]}, {"gpuMs", gpu}});
    }
    // The GI's GPU memory: the scene's volume, then each near level's.
    nlohmann::ordered_json nearLevels = nlohmann::ordered_json::array();
    std::size_t nearBytes = 0;
    for (const lit::FrameStats::NearLevelMemory& level : stats.nearLevels) {
        nearLevels.push_back({{"side", level.side}, {"bytes", level.bytes}});
        nearBytes += level.bytes;
    }
    const nlohmann::ordered_json giMemory = {{"totalBytes", stats.voxelBytes},
                                             {"sceneVolumeBytes", stats.voxelBytes - nearBytes},
                                             {"nearLevels", nearLevels}};
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
              {"anisotropic", bench.mipmaps.anisotropic},
              {"directionalMinMs", bench.mipmaps.directionalMinMs},
              {"directionalOccupiedMinMs", bench.mipmaps.directionalOccupiedMinMs}}},
            {"giMemory", giMemory},
            {"perFrame", frames},
            {"triangles", stats.triangles},
            {"drawCalls", stats.drawCalls},
            {"frustumCulling", settings.output.frustumCulling},
            {"drawsSubmitted", stats.drawsSubmitted},
            {"drawsTotal", stats.drawsTotal},
            {"cullMs", toJson(summarize(bench.cullMs))},
            {"passes", passes}};
}

void writeBenchJson(const std::filesystem::path& path, const nlohmann::ordered_json& json) {
    writeTextFileAtomic(path, json.dump(2) + "\n");
    std::printf("wrote %s\n", path.string().c_str());
}

}  // namespace lit::cli
