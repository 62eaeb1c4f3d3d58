#pragma once
// --path: a camera path flown through the scene, every frame written (--frames-out DIR) or timed
// (--bench-path, with the frame rates and a flicker figure).

#include "RunContext.h"
#include "animation/CameraPath.h"

namespace lit {
struct Scene;
}

namespace lit::cli {

// The camera path --path names: a .json file, or a camera animation in the scene file. Runs
// before any GL work so a bad path is reported at once (UsageError).
CameraPath loadPath(const Options& options);

// Renders every frame of `path` along it at --fps, with the scene's node animations posed at each
// frame's time (one clock; frames go on past the path's last key, the camera resting there,
// until the node animations' last key); returns the exit status.
int runPath(const RunContext& run, const CameraPath& path, Scene& scene, const GlRun& gl);

}  // namespace lit::cli
