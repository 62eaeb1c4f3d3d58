#pragma once
// --bench and --bench-path: the timings of every frame (wall, CPU issue, per pass on the GPU and
// CPU), summarised as a table on stdout and as JSON (tools/perf-table.sh reads the JSON).

#include <cstddef>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "RunContext.h"
#include "gi/MipmapBenchmark.h"

namespace lit {
class Renderer;
struct FrameStats;
}  // namespace lit

namespace lit::cli {

// Per-pass samples over the benchmark. A pass that did not run in a frame (voxelization once the
// volume is clean) contributes no sample for it.
struct PassSamples {
    std::string name;
    std::vector<double> gpuMs, cpuMs;
};

struct BenchResult {
    std::vector<PassSamples> passes;               // in the profiler's first-use order
    std::map<std::string, std::size_t> passIndex;  // name → index in passes
    std::vector<double> frameMs;                   // wall time per frame: issuing plus waiting for the GPU
    std::vector<double> cpuFrameMs;                // time spent issuing the frame on the CPU
    std::vector<double> cullMs;                    // CPU time of BVH refit + frustum culling per frame
    // Per frame, the GPU ms of each pass that ran in it (what made a slow frame slow).
    std::vector<std::vector<std::pair<std::string, double>>> framePasses;
    MipmapTimings mipmaps;                         // compute chain vs glGenerateTextureMipmap (GI only)
};

// Waits for the frame just issued and records its timings. Waiting for this frame's queries
// serialises CPU and GPU: the wall time per frame is then the true cost of a frame, and the pass
// timings belong to this very frame.
void recordBenchFrame(BenchResult& bench, Renderer& renderer, Clock::time_point frameStart);

// The table: min, median, mean and max per pass and per frame, the frame rates, the last frame's
// draws, and the mipmap comparison when it was measured.
void printBench(const BenchResult& bench, const RenderSettings& settings, const FrameStats& lastFrame);

// The same figures as JSON, with the scene, device and settings that produced them.
nlohmann::ordered_json benchJson(const BenchResult& bench, const Options& options, const RenderSettings& settings,
                                 const std::string& device, const FrameStats& stats);

// Writes `json` to `path` through a temporary file (a reader never sees half a file) and says so.
void writeBenchJson(const std::filesystem::path& path, const nlohmann::ordered_json& json);

}  // namespace lit::cli
