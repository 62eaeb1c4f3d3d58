#pragma once
// --path: a camera path flown through the scene, every frame written (--frames-out DIR) or timed
// (--bench-path, with the frame rates and a flicker figure).

#include "RunContext.h"
#include "animation/CameraPath.h"

#include <cstddef>
#include <filesystem>
#include <vector>

namespace lit {
struct Scene;
}

namespace lit::cli {

// The camera path --path names: a .json file, or a camera animation in the scene file. Runs
// before any GL work so a bad path is reported at once (UsageError).
CameraPath loadPath(const Options& options);

// The times of the frames of `path` at --fps: along the path, then on past its last key (the
// camera resting there) until the scene's node animations' last key. Throws RunError beyond
// kMaxFrames frames.
std::vector<double> pathFrameTimes(const Options& options, const CameraPath& path, const Scene& scene);
// Creates --frames-out's folder (RunError when it cannot), and names frame `index` in it.
void makeFramesFolder(const std::filesystem::path& folder);
std::filesystem::path frameFile(const std::filesystem::path& folder, std::size_t index);

// Renders every frame of `path` along it at --fps (pathFrameTimes), with the scene's node
// animations posed at each frame's time (one clock); returns the exit status.
int runPath(const RunContext& run, const CameraPath& path, Scene& scene, const GlRun& gl);

}  // namespace lit::cli
